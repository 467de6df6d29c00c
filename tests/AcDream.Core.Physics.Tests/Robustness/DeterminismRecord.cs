using System.Globalization;
using System.Text;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// What the determinism data records, as text lines: every frame of the fuzz areas' cases as raw bits, and
/// one hash per mover of each built-in scene. Shared by <see cref="RecordedDeterminismTests"/> (which
/// compares the lines with the committed files) and the determinism program run on other architectures
/// (tests/AcDream.Core.Physics.Determinism, scripts/check-arm64.sh), so both produce the same lines.
/// </summary>
internal static class DeterminismRecord
{
    /// <summary>A fuzz area: the features its cases may use, and the run seed its case seeds derive from.</summary>
    internal sealed record Area(string Name, SceneFuzzer.Features Features, int Seed);

    public const int CasesPerArea = 30;

    internal static readonly Area[] Areas =
    [
        new("classic", SceneFuzzer.Features.None, 1101),
        new("steep-terrain", SceneFuzzer.Features.SteepTerrain, 1102),
        new("scaled-objects", SceneFuzzer.Features.ScaledObjects, 1103),
        new("ethereal-mover", SceneFuzzer.Features.EtherealMover, 1104),
        new("missile-mover", SceneFuzzer.Features.MissileMover, 1105),
        new("large-objects", SceneFuzzer.Features.LargeObjects, 1106),
        new("indoor-cell", SceneFuzzer.Features.IndoorCell, 1107),
    ];

    /// <summary>The names of the values of one frame, in record order (collided ids follow separately).</summary>
    internal static readonly string[] FieldNames =
    [
        "cell", "origin.x", "origin.y", "origin.z", "orientation.x", "orientation.y", "orientation.z", "orientation.w",
        "succeeded", "contact", "onWalkable", "contactPlane.normal.x", "contactPlane.normal.y", "contactPlane.normal.z",
        "contactPlane.d", "contactPlane.cell", "slidingNormal.valid", "slidingNormal.x", "slidingNormal.y", "slidingNormal.z",
        "collisionNormal.valid", "collisionNormal.x", "collisionNormal.y", "collisionNormal.z", "collidedWithEnvironment",
    ];

    /// <summary>Every output of one resolved frame, as raw bits (floats by their IEEE bits).</summary>
    internal static uint[] FrameValues(in MoveResult r)
    {
        var n = r.Next;
        static uint F(float f) => BitConverter.SingleToUInt32Bits(f);
        static uint B(bool b) => b ? 1u : 0u;
        return
        [
            n.Position.CellId, F(n.Position.Origin.X), F(n.Position.Origin.Y), F(n.Position.Origin.Z),
            F(n.Position.Frame.Orientation.X), F(n.Position.Frame.Orientation.Y), F(n.Position.Frame.Orientation.Z), F(n.Position.Frame.Orientation.W),
            B(r.Succeeded), B(n.Contact), B(n.OnWalkable), F(n.ContactPlane.Normal.X), F(n.ContactPlane.Normal.Y), F(n.ContactPlane.Normal.Z),
            F(n.ContactPlane.D), n.ContactPlaneCellId, B(n.SlidingNormalValid), F(n.SlidingNormal.X), F(n.SlidingNormal.Y), F(n.SlidingNormal.Z),
            B(r.CollisionNormalValid), F(r.CollisionNormal.X), F(r.CollisionNormal.Y), F(r.CollisionNormal.Z), B(r.CollidedWithEnvironment),
        ];
    }

    /// <summary>One frame as a line: key, frame index, the values in hex, the collided ids.</summary>
    internal static string FrameLine(string key, int frame, in MoveResult r)
    {
        var sb = new StringBuilder();
        sb.Append(key).Append('\t').Append(frame.ToString(CultureInfo.InvariantCulture)).Append('\t');
        sb.AppendJoin(' ', FrameValues(r).Select(v => v.ToString("X8", CultureInfo.InvariantCulture)));
        sb.Append('\t').AppendJoin(',', r.CollidedObjects.ToArray().Select(v => v.ToString("X8", CultureInfo.InvariantCulture)));
        return sb.ToString();
    }

    /// <summary>The frame lines of fuzz cases: <paramref name="cases"/> case seeds derived from <paramref name="runSeed"/>.</summary>
    internal static List<string> CaseLines(int runSeed, int cases, SceneFuzzer.Features features)
    {
        var lines = new List<string>();
        for (int i = 0; i < cases; i++)
        {
            var c = SceneFuzzer.Make(SceneFuzzer.CaseSeed(runSeed, i), features);
            var engine = new PhysicsEngine(c.World);
            var state = c.Start;
            for (int f = 0; f < c.Targets.Count; f++)
            {
                var r = engine.Resolve(c.Mover, state, SceneFuzzer.TargetFor(state, c.Targets[f]));
                lines.Add(FrameLine(c.Seed.ToString(CultureInfo.InvariantCulture), f, r));
                state = r.Next;
            }
        }
        return lines;
    }

    /// <summary>The lines of an area: every frame of its cases.</summary>
    internal static List<string> AreaLines(Area area) => CaseLines(area.Seed, CasesPerArea, area.Features);

    /// <summary>
    /// One line per case of an area: its seed and an FNV-1a hash of its description (terrain, objects, mover,
    /// start and offsets as printed), so that a case generated differently on another machine is told apart
    /// from a case resolved differently.
    /// </summary>
    internal static List<string> InputLines(int runSeed, int cases, SceneFuzzer.Features features)
    {
        var lines = new List<string>();
        for (int i = 0; i < cases; i++)
        {
            var c = SceneFuzzer.Make(SceneFuzzer.CaseSeed(runSeed, i), features);
            ulong h = 14695981039346656037UL;
            foreach (char ch in c.ToString())
            {
                h ^= ch;
                h *= 1099511628211UL;
            }
            lines.Add($"{c.Seed.ToString(CultureInfo.InvariantCulture)}\t0x{h:X16}");
        }
        return lines;
    }

    /// <summary>FNV-1a over every frame of one mover of a scene.</summary>
    internal static ulong MoverHash(Scene scene, int moverIndex)
    {
        var mover = scene.Movers[moverIndex];
        var engine = new PhysicsEngine(scene.World);
        ulong h = 14695981039346656037UL;
        void Add(uint x) { for (int i = 0; i < 4; i++) { h ^= (byte)(x >> (8 * i)); h *= 1099511628211UL; } }
        var state = mover.Start;
        var body = mover.StartBody;
        // A mover that sticks to an earlier one follows that mover's frames (the scene run so far).
        var earlier = moverIndex == 0 ? null : SceneRunner.Earlier(scene, SceneRunner.Run(scene).Movers, moverIndex);
        var motion = mover.Commands?.Start(mover.Description, state, ref body, earlier);
        var missile = mover.IsMissile ? new AcDream.Core.Physics.Missile(mover.Description, mover.Start.Position, mover.StartBody) : null;
        for (int f = 0; f < mover.FrameCount; f++)
        {
            MoveResult r;
            if (missile is not null)
            {
                // A missile (PhysicsEngine.Step(Missile, …)): its velocity, quanta and the hit of the step count too.
                var flown = engine.Step(missile, mover.Steps[f].Elapsed);
                foreach (float v in new[] { flown.Step.Body.Velocity.X, flown.Step.Body.Velocity.Y, flown.Step.Body.Velocity.Z })
                    Add(BitConverter.SingleToUInt32Bits(v));
                Add((uint)flown.Step.Quanta);
                Add((uint)flown.Hit.Kind);
                Add(flown.Hit.ObjectId);
                Add((uint)flown.Hit.Quantum);
                r = flown.Step.Move;
            }
            else if (mover.IsBody)
            {
                // A body mover (PhysicsEngine.Step): its velocity and quanta count too; a motion mover's commands
                // are given first and its interpreted state is hashed after the step (the orientation is in FrameValues).
                var step = mover.Steps[f];
                var stepped = motion is null
                    ? engine.Step(mover.Description, state, body, step.Elapsed, step.DesiredVelocity, step.JumpVelocity)
                    : SceneRunner.StepMotion(engine, mover.Description, step.Elapsed, ref state, ref body, motion, f);
                if (motion is not null)
                {
                    var i = motion.Motion.Interpreted;
                    foreach (uint v in new[] { i.Style, i.ForwardCommand, i.SideStepCommand, i.TurnCommand })
                        Add(v);
                    foreach (float v in new[] { i.ForwardSpeed, i.SideStepSpeed, i.TurnSpeed })
                        Add(BitConverter.SingleToUInt32Bits(v));
                }
                body = stepped.Body;
                Add(BitConverter.SingleToUInt32Bits(body.Velocity.X));
                Add(BitConverter.SingleToUInt32Bits(body.Velocity.Y));
                Add(BitConverter.SingleToUInt32Bits(body.Velocity.Z));
                Add((uint)stepped.Quanta);
                r = stepped.Move;
            }
            else
            {
                var target = state.Position;
                target.Frame.Origin += mover.Motion[f];
                r = engine.Resolve(mover.Description, state, target);
            }
            foreach (uint v in FrameValues(r)) Add(v);
            Add((uint)r.CollidedObjects.Length);
            foreach (uint id in r.CollidedObjects.Span) Add(id);
            state = r.Next;
        }
        return h;
    }

    /// <summary>The lines of a built-in scene: each mover's name and hash.</summary>
    internal static List<string> SceneLines(string name)
    {
        var scene = SceneLibrary.Load(name);
        var lines = new List<string>();
        for (int m = 0; m < scene.Movers.Count; m++)
            lines.Add($"{scene.Movers[m].Name}\t0x{MoverHash(scene, m):X16}");
        return lines;
    }
}
