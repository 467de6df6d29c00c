using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>The motion-layer body step's contract: no allocation once warm, the same inputs give the same bits, a creature steps as a player.</summary>
public class MotionStepContractTests
{
    // A run with a turn, a stop, a jump and its landing: every path of the step (links, modifiers, the sequence's
    // cycle ends, leaving and hitting the ground).
    private static void Script(MotionRig rig)
    {
        rig.Do(MotionCommand.Ready, HoldKey.Run);
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        rig.Frames(10);
        rig.Do(MotionCommand.TurnRight, HoldKey.Run);
        rig.Frames(10);
        rig.Stop(MotionCommand.TurnRight, HoldKey.Run);
        rig.Jump(0.5f);
        rig.Frames(40);
        rig.Stop(MotionCommand.WalkForward, HoldKey.Run);
        rig.Do(MotionCommand.WalkBackwards);
        rig.Frames(10);
        rig.Do(MotionCommand.SideStepLeft);
        rig.Frames(10);
        rig.Motion.StopCompletely(rig.Mover, ref rig.State, ref rig.Body);
        rig.Frames(5);
    }

    [Fact]
    public void TheMotionStep_AllocatesNothingOnceWarm()
    {
        var rig = new MotionRig();
        Assert.Equal(0, Allocations.PerRound(() => Script(rig), () => Script(rig)));
    }

    [Fact]
    public void TheSameCommands_GiveTheSameBits()
    {
        var a = new MotionRig();
        var b = new MotionRig();
        Script(a);
        Script(b);
        Assert.Equal(a.State.Position.Frame.Origin, b.State.Position.Frame.Origin);
        Assert.Equal(a.State.Position.Frame.Orientation, b.State.Position.Frame.Orientation);
        Assert.Equal(a.Body.Velocity, b.Body.Velocity);
    }

    [Fact]
    public void ACreature_WithoutSkills_StepsThroughTheSameCode()
    {
        // A server's creature: the same table and step, no skills (run rate 1: WalkForward with Run is RunForward × 1,
        // 4 m/s forward, one run-cycle frame (6 frames at 30/s) per quantum: 4/30 m).
        var rig = new MotionRig();
        var creature = new ObjectMotion(MotionTables.Humanoid());
        var state = rig.State;
        var body = AcDream.Core.Physics.BodyState.Creature();
        creature.Place(rig.Mover, state, ref body);
        creature.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), rig.Mover, ref state, ref body);
        Assert.Equal(MotionCommand.RunForward, creature.Interpreted.ForwardCommand);
        Assert.Equal(1f, creature.Interpreted.ForwardSpeed);
        for (int i = 0; i < 30; i++)
        {
            var r = rig.Engine.Step(rig.Mover, state, body, creature, 1.0 / 30);
            state = r.Next;
            body = r.Body;
        }
        Assert.Equal(64f, state.Position.Frame.Origin.Y, 2); // 30 frames × 4/30 m = 4 m
    }
}
