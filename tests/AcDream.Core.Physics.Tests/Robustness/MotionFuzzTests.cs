using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Random (valid) motion tables driven by random command sequences through the motion step, with random bad
/// inputs mixed in (NaN and infinite speeds and extents, unknown commands, hold keys out of range): no crash, no
/// NaN, no allocation once warm; bad input gets an <see cref="ArgumentException"/> naming the field and changes
/// nothing the caller owns (the mover state, the body, the object's interpreted state). Seeded, a few seconds.
/// </summary>
public class MotionFuzzTests
{
    private const int Seed = 20261202, Cases = 150, Frames = 60;
    private const uint Style = MotionCommand.NonCombat;

    private static readonly uint[] Substates = [MotionCommand.WalkForward, MotionCommand.RunForward, MotionCommand.Falling];
    private static readonly uint[] Modifiers = [MotionCommand.SideStepRight, MotionCommand.TurnRight];
    private static readonly uint[] Commanded =
    [
        MotionCommand.Ready, MotionCommand.WalkForward, MotionCommand.WalkBackwards, MotionCommand.RunForward, MotionCommand.TurnRight,
        MotionCommand.TurnLeft, MotionCommand.SideStepRight, MotionCommand.SideStepLeft, MotionCommand.Falling,
    ];

    private enum Kind { Do, Stop, StopCompletely, HoldKey, Jump }

    /// <summary>A command of a case, given before the step of its frame.</summary>
    private readonly record struct Command(Kind Kind, uint Motion, float Speed, HoldKey Hold, float Extent, bool Stamina);

    /// <summary>A random table: Ready and a random choice of the other cycles, modifiers and links, random animations.</summary>
    internal static MotionTable RandomTable(Random rng)
    {
        var animations = new List<Animation>();
        AnimData Anim()
        {
            uint id = 0x03000100u + (uint)animations.Count;
            int frames = rng.Next(1, 10);
            var roots = new List<RootFrame>();
            if (rng.Next(2) == 0)
                for (int f = 0; f < frames; f++)
                {
                    var axis = Vector3.Normalize(new Vector3(rng.NextSingle() - 0.5f, rng.NextSingle() - 0.5f, rng.NextSingle() + 0.1f));
                    roots.Add(new RootFrame(new Vector3(rng.NextSingle() - 0.5f, rng.NextSingle() - 0.5f, 0f) * 0.05f,
                        Quaternion.CreateFromAxisAngle(axis, (rng.NextSingle() - 0.5f) * 0.05f)));
                }
            animations.Add(new Animation(id, frames, roots));
            int low = rng.Next(frames);
            int high = rng.Next(3) == 0 ? -1 : rng.Next(low, frames);
            float rate = (5f + rng.NextSingle() * 55f) * (rng.Next(6) == 0 ? -1f : 1f);
            return new AnimData(id, low, high, rate);
        }
        MotionData Data(bool needsAnim, byte? bitfield = null)
        {
            var anims = new List<AnimData>();
            for (int i = rng.Next(needsAnim ? 1 : 0, 3); i > 0; i--)
                anims.Add(Anim());
            var velocity = rng.Next(2) == 0 ? Vector3.Zero : new Vector3(rng.NextSingle() - 0.5f, rng.NextSingle(), 0f) * 5f;
            var omega = rng.Next(2) == 0 ? Vector3.Zero : new Vector3(0f, 0f, (rng.NextSingle() - 0.5f) * 4f);
            var flags = (velocity != Vector3.Zero ? MotionDataFlags.HasVelocity : 0) | (omega != Vector3.Zero ? MotionDataFlags.HasOmega : 0);
            return new MotionData(bitfield ?? (byte)rng.Next(3), flags, anims, velocity, omega);
        }
        var cycles = new Dictionary<uint, MotionData> { [MotionTable.CycleKey(Style, MotionCommand.Ready)] = Data(true) };
        foreach (uint m in Substates)
            if (rng.Next(3) != 0)
                cycles[MotionTable.CycleKey(Style, m)] = Data(true);
        // Turn and sidestep cycles with any bitfield: one that may be entered while moving (without 2) sends
        // re_modify and GetObjectSequence round and round, which the bounded nesting of MotionTableManager.ReModify
        // stops (it overflowed the stack before).
        foreach (uint m in Modifiers)
            if (rng.Next(3) != 0)
                cycles[MotionTable.CycleKey(Style, m)] = Data(true);
        var modifiers = new Dictionary<uint, MotionData>();
        foreach (uint m in Modifiers)
            if (rng.Next(2) == 0)
                modifiers[MotionTable.CycleKey(Style, m)] = Data(false);
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>();
        var present = Substates.Prepend(MotionCommand.Ready).Where(m => cycles.ContainsKey(MotionTable.CycleKey(Style, m))).ToArray();
        foreach (uint from in present)
        {
            var inner = new Dictionary<uint, MotionData>();
            foreach (uint to in present)
                if (to != from && rng.Next(2) == 0)
                    inner[to] = Data(true);
            if (inner.Count > 0)
                links[MotionTable.CycleKey(Style, from)] = inner;
        }
        return new MotionTable(0x09000100, Style, new Dictionary<uint, uint> { [Style] = MotionCommand.Ready }, cycles, modifiers, links, animations);
    }

    private static Command RandomCommand(Random rng)
    {
        var kind = (Kind)rng.Next(5);
        float speed = rng.Next(4) == 0 ? 1f : (rng.NextSingle() - 0.3f) * 4f;
        var hold = (HoldKey)rng.Next(3);
        return new Command(kind, Commanded[rng.Next(Commanded.Length)], speed, kind == Kind.HoldKey ? (HoldKey)rng.Next(1, 3) : hold,
            rng.NextSingle(), rng.Next(4) != 0);
    }

    /// <summary>A bad command and the field its error must name.</summary>
    private static (Command Command, string Field) RandomBad(Random rng)
    {
        float[] bad = [float.NaN, float.PositiveInfinity, float.NegativeInfinity, 1e9f];
        return rng.Next(5) switch
        {
            0 => (new Command(Kind.Do, MotionCommand.Ready, bad[rng.Next(bad.Length)], HoldKey.None, 0f, true), "parameters.Speed"),
            1 => (new Command(Kind.Stop, MotionCommand.Ready, bad[rng.Next(bad.Length)], HoldKey.Run, 0f, true), "parameters.Speed"),
            2 => (new Command(Kind.Jump, 0, 1f, HoldKey.Invalid, rng.Next(2) == 0 ? float.NaN : rng.Next(2) == 0 ? float.PositiveInfinity : -0.5f, true), "extent"),
            3 => (new Command(rng.Next(2) == 0 ? Kind.Do : Kind.Stop, 0x4500FFFFu - (uint)rng.Next(100), 1f, HoldKey.None, 0f, true), "motion"),
            _ => (new Command(Kind.Do, MotionCommand.Ready, 1f, (HoldKey)(3 + rng.Next(100)), 0f, true), "parameters.HoldKey"),
        };
    }

    private static MotionError Give(ObjectMotion motion, in Command c, MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        switch (c.Kind)
        {
            case Kind.Do: return motion.DoMotion(c.Motion, new MotionParameters(c.Speed, c.Hold), mover, ref state, ref body);
            case Kind.Stop: return motion.StopMotion(c.Motion, new MotionParameters(c.Speed, c.Hold), mover, ref state, ref body);
            case Kind.StopCompletely: return motion.StopCompletely(mover, ref state, ref body);
            case Kind.HoldKey: motion.SetHoldKey(c.Hold, mover, ref state, ref body); return MotionError.None;
            default:
                var charged = motion.ChargeJump(mover, state, body);
                return charged != MotionError.None ? charged : motion.Jump(c.Extent, c.Stamina, mover, ref state, ref body);
        }
    }

    /// <summary>A command the table may not know is a clear refusal too; anything else must be taken.</summary>
    private static bool KnownToTable(ObjectMotion motion, in Command c) =>
        c.Kind is not (Kind.Do or Kind.Stop) || c.Motion is MotionCommand.WalkBackwards or MotionCommand.TurnLeft or MotionCommand.SideStepLeft
        || motion.Table.Knows(c.Motion);

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    private static bool SameBits(in MoverState a, in MoverState b, in BodyState x, in BodyState y, in InterpretedMotionState i, in InterpretedMotionState j) =>
        a.Position.CellId == b.Position.CellId && a.Position.Frame.Origin.Equals(b.Position.Frame.Origin)
        && a.Position.Frame.Orientation.Equals(b.Position.Frame.Orientation) && a.Contact == b.Contact && a.OnWalkable == b.OnWalkable
        && x.Velocity.Equals(y.Velocity) && x.PendingTime.Equals(y.PendingTime) && i.Equals(j);

    [Fact]
    public void RandomCommandsThroughRandomTables_KeepTheInvariants_AndBadInputChangesNothing()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var mover = MoverDescription.Player(stepDownHeight: 0.04f);
        double[] elapsed = [1.0 / 30, 1.0 / 60, 0.2, 0.01, 0.05];
        int badSeen = 0, stepsTaken = 0;
        for (int n = 0; n < Cases; n++)
        {
            int seed = FuzzTests.CaseSeed(Seed, n);
            var rng = new Random(seed);
            var motion = new ObjectMotion(RandomTable(rng), rng.Next(3) == 0 ? null : new RetailSkills(rng.Next(0, 1000), rng.Next(0, 1000), rng.NextSingle() * 2.5f));
            var state = MoverState.OnFloor(TestGeometry.At(96f, 96f, 0f), 0f);
            var body = BodyState.Creature();
            motion.Place(mover, state, ref body);
            for (int f = 0; f < Frames; f++)
            {
                string at = $"case seed {seed}, frame {f}";
                if (rng.Next(3) == 0)
                {
                    var c = RandomCommand(rng);
                    if (KnownToTable(motion, c))
                        Give(motion, c, mover, ref state, ref body);
                    else
                    {
                        var ex = Assert.Throws<ArgumentException>(() => { var s = state; var b = body; Give(motion, c, mover, ref s, ref b); });
                        Assert.StartsWith("motion:", ex.Message);
                    }
                }
                if (rng.Next(8) == 0)
                {
                    var (c, field) = RandomBad(rng);
                    var (s0, b0, i0) = (state, body, motion.Interpreted);
                    var (s, b) = (state, body);
                    // A bad extent goes to Jump itself: Give charges first, which a loaded-down owner refuses.
                    var ex = Assert.Throws<ArgumentException>(() =>
                        c.Kind == Kind.Jump ? motion.Jump(c.Extent, c.Stamina, mover, ref s, ref b) : Give(motion, c, mover, ref s, ref b));
                    Assert.True(ex.Message.StartsWith(field + ":", StringComparison.Ordinal), $"{at}: {c} gave \"{ex.Message}\", expected it to name {field}");
                    Assert.True(SameBits(s0, s, b0, b, i0, motion.Interpreted), $"{at}: {c} was refused but changed the caller's state");
                    badSeen++;
                }
                var r = engine.Step(mover, state, body, motion, elapsed[rng.Next(elapsed.Length)]);
                (state, body) = (r.Next, r.Body);
                stepsTaken++;
                var i = motion.Interpreted;
                Assert.True(Finite(state.Position.Frame.Origin) && float.IsFinite(state.Position.Frame.Orientation.W) && Finite(body.Velocity)
                    && float.IsFinite(i.ForwardSpeed) && float.IsFinite(i.SideStepSpeed) && float.IsFinite(i.TurnSpeed),
                    $"{at}: NaN or infinity: {state.Position} v={body.Velocity} {i.ForwardSpeed}/{i.SideStepSpeed}/{i.TurnSpeed}");
            }
        }
        Assert.True(badSeen > 50, $"only {badSeen} bad inputs were tried");
        Assert.Equal(Cases * Frames, stepsTaken);
    }

    [Fact]
    public void RandomCommandsThroughRandomTables_AllocateNothingOnceWarm()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var mover = MoverDescription.Player(stepDownHeight: 0.04f);
        for (int n = 0; n < 10; n++)
        {
            var rng = new Random(FuzzTests.CaseSeed(Seed + 1, n));
            var motion = new ObjectMotion(RandomTable(rng), new RetailSkills(rng.Next(0, 1000), rng.Next(0, 1000)));
            var start = MoverState.OnFloor(TestGeometry.At(96f, 96f, 0f), 0f);
            var startBody = BodyState.Creature();
            motion.Place(mover, start, ref startBody);
            var commands = new Command?[Frames];
            for (int f = 0; f < Frames; f++)
                if (rng.Next(3) == 0 && RandomCommand(rng) is var c && KnownToTable(motion, c))
                    commands[f] = c;
            void Round()
            {
                var (state, body) = (start, startBody);
                motion.StopCompletely(mover, ref state, ref body);
                for (int f = 0; f < Frames; f++)
                {
                    if (commands[f] is { } c)
                        Give(motion, c, mover, ref state, ref body);
                    var r = engine.Step(mover, state, body, motion, 1.0 / 30);
                    (state, body) = (r.Next, r.Body);
                }
            }
            Assert.Equal(0, Allocations.PerRound(Round, Round));
        }
    }
}
