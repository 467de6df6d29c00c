using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// A table whose sidestep and turn cycles may replace a moving substate (bitfield 0) sends re_modify and
/// GetObjectSequence round and round: the sidestep, pushed back as a modifier by the turn, is made the substate
/// again by its re-giving, which pushes the turn back, and so on. Retail would recurse until its stack
/// overflowed; the library bounds the nesting (not retail, docs/open-questions.md).
/// </summary>
public class ReModifyLoopTests
{
    [Fact]
    public void SideStepThenTurn_OnCyclesWithoutBitfield2_ReturnsInsteadOfOverflowingTheStack()
    {
        const uint style = MotionCommand.NonCombat;
        var anim = new Animation(0x03000001, 2, []);
        MotionData Cycle(Vector3 velocity, Vector3 omega) => new(0,
            (velocity != Vector3.Zero ? MotionDataFlags.HasVelocity : 0) | (omega != Vector3.Zero ? MotionDataFlags.HasOmega : 0),
            [new AnimData(anim.Id, 0, -1, 30f)], velocity, omega);
        var cycles = new Dictionary<uint, MotionData>
        {
            [MotionTable.CycleKey(style, MotionCommand.Ready)] = Cycle(Vector3.Zero, Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.SideStepRight)] = Cycle(new Vector3(1.25f, 0, 0), Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.TurnRight)] = Cycle(Vector3.Zero, new Vector3(0, 0, -1.5f)),
        };
        var table = new MotionTable(0x09000002, style, new Dictionary<uint, uint> { [style] = MotionCommand.Ready }, cycles,
            new Dictionary<uint, MotionData>(), new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>(), [anim]);
        var rig = new MotionRig();
        var motion = new ObjectMotion(table);
        motion.Place(rig.Mover, rig.State, ref rig.Body);

        Assert.Equal(MotionError.None, motion.DoMotion(MotionCommand.SideStepRight, new MotionParameters(), rig.Mover, ref rig.State, ref rig.Body));
        motion.DoMotion(MotionCommand.TurnRight, new MotionParameters(), rig.Mover, ref rig.State, ref rig.Body);

        // It came back, with one of the two as the substate and a bounded modifier list; the body still steps.
        Assert.True(motion.Substate is MotionCommand.SideStepRight or MotionCommand.TurnRight, $"substate 0x{motion.Substate:X8}");
        Assert.InRange(motion.ModifierCount, 0, 2);
        var step = rig.Engine.Step(rig.Mover, rig.State, rig.Body, motion, 1.0 / 30);
        Assert.True(float.IsFinite(step.Next.Position.Frame.Origin.X) && float.IsFinite(step.Next.Position.Frame.Origin.Y));
    }
}
