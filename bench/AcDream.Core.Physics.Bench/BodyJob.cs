using System.Globalization;
using System.IO;
using System.Text;
using AcDream.Core.Physics.Bench.Benchmarks;
using AcDream.Core.Physics.Bench.Reporting;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// The body job (<c>-- body [--out DIR]</c>): the cost of one <see cref="PhysicsEngine.Step"/> next to one
/// <see cref="PhysicsEngine.Resolve"/> of the same motion on the door scene, and of the step's other paths
/// (a fall, time only gathered, an arrow's flight), timed side by side by <see cref="RowTimer"/>; bytes per call.
/// Writes <c>body.md</c> to the output directory (default <c>out/body</c>).
/// </summary>
public static class BodyJob
{
    private const double Frame = 1.0 / 30.0;

    /// <summary>Runs the job; returns the exit code.</summary>
    public static int Run(string[] args)
    {
        string outDir = Path.Combine("out", "body");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--out" && i + 1 < args.Length)
                outDir = args[++i];
            else
            {
                Console.Error.WriteLine($"body: unknown option '{args[i]}'. Usage: body [--out DIR]");
                return 2;
            }
        }
        Directory.CreateDirectory(outDir);
        Console.WriteLine($"body job: {Reports.Machine()}");
        var scene = DoorScene.Create();
        var engine = new PhysicsEngine(scene.World);
        var player = DoorScene.Player;

        // The door transition: a grounded walk of 0.1 m into the slab's face, dead centre.
        var start = DoorWorkloads.TransitionStart;
        var target = start.Position;
        target.Frame.Origin = DoorWorkloads.TransitionTarget;
        // The same motion as a body: 3 m/s for 1/30 s.
        var walker = BodyState.Creature();
        var walk = new Vector3(0, 3f, 0);
        // A fall in the open, 3 m from the door: 2 m up, moving 3 m/s sideways and 2 m/s down.
        var air = MoverState.Airborne(DoorScene.At(new Vector3(97f, 97f, 2f)));
        var faller = BodyState.Object(new Vector3(3f, 0, -2f));
        // Arrows (r = 0.05) in the open at 1.5 m, 3 m from the door, flying away from it: one quantum of 1/30 s is
        // 1 m (20 sub-steps) at 30 m/s and 1.67 m (34 sub-steps) at 50 m/s. Put back at the launch before each step.
        var arrowStart = DoorScene.At(new Vector3(97f, 97f, 1.5f));
        var arrow30 = Missile.Launch(0x8000_0001, 0.05f, arrowStart, new Vector3(-30f, 0, 0));
        var arrow50 = Missile.Launch(0x8000_0002, 0.05f, arrowStart, new Vector3(-50f, 0, 0));
        var (state30, body30, state50, body50) = (arrow30.State, arrow30.Body, arrow50.State, arrow50.Body);

        var rows = new (string Name, Action Call)[]
        {
            ("Resolve: door transition (walk 0.1 m into the face)", () => engine.Resolve(player, start, target)),
            ("Step: the same walk as a body (3 m/s, 1/30 s)", () => engine.Step(player, start, walker, Frame, walk)),
            ("Step: falling in the open (one quantum)", () => engine.Step(player, air, faller, Frame, Vector3.Zero)),
            ("Step: 10 ms gathered (no quantum runs)", () => engine.Step(player, start, walker, 0.01, walk)),
            ("Step(Missile): arrow at 30 m/s in the open (one quantum)", () => { arrow30.State = state30; arrow30.Body = body30; engine.Step(arrow30, Frame); }),
            ("Step(Missile): arrow at 50 m/s in the open (one quantum)", () => { arrow50.State = state50; arrow50.Body = body50; engine.Step(arrow50, Frame); }),
        };
        var measured = RowTimer.Measure(Array.ConvertAll(rows, r => r.Call));
        var results = new (string Name, double Ns, double Bytes)[rows.Length];
        for (int r = 0; r < rows.Length; r++)
        {
            results[r] = (rows[r].Name, measured[r].Ns, measured[r].Bytes);
            Console.WriteLine($"{rows[r].Name,-55} {measured[r].Ns,8:0} ns  {measured[r].Bytes:0} B");
        }

        var md = new StringBuilder();
        md.Append("# Body step cost\n\n").Append($"Machine: {Reports.Machine()}.\n\n");
        md.Append("| call | ns per call | B per call | × Resolve |\n|---|---:|---:|---:|\n");
        foreach (var (name, ns, bytes) in results)
            md.Append(CultureInfo.InvariantCulture, $"| {name} | {ns:0} | {bytes:0} | {ns / results[0].Ns:0.00} |\n");
        File.WriteAllText(Path.Combine(outDir, "body.md"), md.ToString());
        Console.WriteLine($"written {Path.GetFullPath(Path.Combine(outDir, "body.md"))}");
        return 0;
    }
}
