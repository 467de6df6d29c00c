using System.Globalization;
using System.IO;
using System.Text;
using AcDream.Core.Physics.Bench.Reporting;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// The motion job (<c>-- motion [--out DIR]</c>): the cost of a body step moved by the motion layer (the
/// interpreter's commands, the sequence's offset and the body step: <c>PhysicsEngine.Step</c> with an
/// <see cref="ObjectMotion"/>) next to a <see cref="PhysicsEngine.Resolve"/> of the same run on the same scene
/// (the built-in <c>run-turn</c>'s flat landblock), in one run, timed side by side by <see cref="RowTimer"/>;
/// bytes per call (0 once warm). Writes <c>motion.md</c> to the output directory (default <c>out/motion</c>).
/// </summary>
public static class MotionJob
{
    private const double Frame = 1.0 / 30.0;

    /// <summary>Runs the job; returns the exit code.</summary>
    public static int Run(string[] args)
    {
        string outDir = Path.Combine("out", "motion");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--out" && i + 1 < args.Length)
                outDir = args[++i];
            else
            {
                Console.Error.WriteLine($"motion: unknown option '{args[i]}'. Usage: motion [--out DIR]");
                return 2;
            }
        }
        Directory.CreateDirectory(outDir);
        Console.WriteLine($"motion job: {Reports.Machine()}");
        var scene = SceneLibrary.Load("run-turn");
        var engine = new PhysicsEngine(scene.World);
        var sceneMover = scene.Movers[0];
        var mover = sceneMover.Description;
        var start = sceneMover.Start;

        // A running player (Run 200: 4 m/s × 2.375 = 9.5 m/s): its motion layer holds RunForward.
        var body = BodyState.Creature();
        var runner = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(200, 200));
        runner.Place(mover, start, ref body);
        var runState = start;
        runner.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), mover, ref runState, ref body);
        var runBody = body;

        // The same frame's displacement as a Resolve: 9.5 m/s for 1/30 s along +Y.
        var target = start.Position;
        target.Frame.Origin += new Vector3(0f, 9.5f / 30f, 0f);
        // And as the desired-velocity step (not retail: the caller's velocity).
        var walker = BodyState.Creature();
        var run = new Vector3(0f, 9.5f, 0f);

        // A second motion layer that takes a command every frame (run on, stop, run on…): interpreter + sequence + step.
        var toggler = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(200, 200));
        var toggleBody = BodyState.Creature();
        toggler.Place(mover, start, ref toggleBody);
        var toggleState = start;
        bool running = false;
        var runKey = new MotionParameters(1f, HoldKey.Run);
        var stop = new MotionParameters();

        // Creatures with retail's MoveToManager (issue 22): one chasing a point 60 m ahead (run, aim check, progress check
        // every quantum; the default CountOnly, the client's rule, so that the unchanging state each call repeats never ends the move), one whose
        // manager is idle (its last move ended). Each call steps from the same state.
        var chaser = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(200, 200));
        chaser.SetCylinder(0.48f, 1.835f);
        var chaseBody = BodyState.Creature();
        chaser.Place(mover, start, ref chaseBody);
        var far = start.Position;
        far.Frame.Origin += new Vector3(0f, 60f, 0f);
        chaser.MoveToPosition(far, MoveToParameters.Default, mover, start, chaseBody);
        var chaseState = start;
        for (int i = 0; i < 15; i++) // through the turn node's check into the run
        {
            var r = engine.Step(mover, chaseState, chaseBody, chaser, Frame);
            chaseState = r.Next;
            chaseBody = r.Body;
        }
        var idle = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(200, 200));
        var idleBody = BodyState.Creature();
        idle.Place(mover, start, ref idleBody);
        idle.TurnToHeading(MoveToParameters.Default, mover, start, idleBody); // already facing 0: ends at once
        var stand = start;

        var rows = new (string Name, Action Call)[]
        {
            ("Resolve: one frame of the run (0.317 m)", () => engine.Resolve(mover, start, target)),
            ("Step with motion: the run (sequence + body step)", () => engine.Step(mover, runState, runBody, runner, Frame)),
            ("Step with motion: a command, then the step", () =>
            {
                var s = toggleState;
                var b = toggleBody;
                if (running = !running)
                    toggler.DoMotion(MotionCommand.WalkForward, runKey, mover, ref s, ref b);
                else
                    toggler.StopMotion(MotionCommand.WalkForward, stop, mover, ref s, ref b);
                engine.Step(mover, s, b, toggler, Frame);
            }),
            ("Step (desired velocity, not retail): the same run", () => engine.Step(mover, start, walker, Frame, run)),
            ("Step with motion: a creature with a MoveTo active (run, aim, progress check)", () => engine.Step(mover, chaseState, chaseBody, chaser, Frame)),
            ("Step with motion: a creature standing, its MoveTo idle", () => engine.Step(mover, stand, idleBody, idle, Frame)),
        };
        var measured = RowTimer.Measure(Array.ConvertAll(rows, r => r.Call), warmUp: 20_000, reps: 2000, rounds: 9);
        var md = new StringBuilder();
        md.Append("# Motion step cost\n\n").Append($"Machine: {Reports.Machine()}.\n\n");
        md.Append("| call | ns per call | B per call | × Resolve |\n|---|---:|---:|---:|\n");
        for (int r = 0; r < rows.Length; r++)
        {
            var (ns, bytes) = measured[r];
            Console.WriteLine($"{rows[r].Name,-55} {ns,8:0} ns  {bytes:0} B  {ns / measured[0].Ns,5:0.00} × Resolve");
            md.Append(CultureInfo.InvariantCulture, $"| {rows[r].Name} | {ns:0} | {bytes:0} | {ns / measured[0].Ns:0.00} |\n");
        }
        File.WriteAllText(Path.Combine(outDir, "motion.md"), md.ToString());
        Console.WriteLine($"written {Path.GetFullPath(Path.Combine(outDir, "motion.md"))}");
        return 0;
    }
}
