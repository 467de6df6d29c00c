using AcDream.Core.Physics.Managers;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>
/// Where retail joins MoveTo and sticking: MoveToManager::BeginNextNode's arrival with the Sticky flag calls
/// PositionManager::StickTo; every end of a running stick (StickTo over it, HandleUpdateTarget with another status,
/// UseTime's timeout, HandleExitWorld through unstick_from_object) calls CPhysicsObj::cancel_moveto, which ends a
/// move in progress with ActionCancelled (0x36); and PerformMovement unsticks before each new move.
/// </summary>
public class StickyMoveToTests
{
    private const uint Target = 0x50000002;

    // A move 30 m north: it runs for seconds, far longer than any test below.
    private static ManagerRig Moving()
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Motion.MoveToPosition(ManagerRig.At(60f, 90f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        rig.Frame();
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        return rig;
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void AnArrivalWithTheStickyFlag_SticksToTheObject_ForOneSecondFromThere(bool sticky)
    {
        // Cylinders 0.48 and 0.48 with centres 0.9 m apart overlap (0.9 - 0.96 < 0.6 m to the object): the move
        // arrives without walking, and with Sticky the object sticks to the target at the clock of its arrival.
        var rig = new ManagerRig(60f, 60f);
        rig.Motion.SetCylinder(0.48f, 1.835f);
        var flags = MoveToFlags.RetailDefault | (sticky ? MoveToFlags.Sticky : MoveToFlags.None);
        rig.Motion.MoveToObject(Target, 0.48f, 1.835f, MoveToParameters.Default with { Flags = flags }, rig.Mover, rig.State, rig.Body);
        rig.Motion.UpdateMoveToTarget(Target, ManagerRig.At(60f, 60.9f), rig.Mover, rig.State, rig.Body);
        for (int i = 0; i < 60 && rig.Motion.MoveToStatus != MoveToStatus.Ended; i++)
            rig.Frame();
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        if (sticky)
        {
            Assert.Equal(Target, rig.Manager.StickyTargetId);
            Assert.True(rig.Manager.StickyTimeout > rig.Manager.Clock && rig.Manager.StickyTimeout <= rig.Manager.Clock + 1.0);
        }
        else
        {
            Assert.Equal(0u, rig.Manager.StickyTargetId);
        }
    }

    [Fact]
    public void TheSticksTimeout_CancelsTheMoveInProgress()
    {
        // StickTo at the clock after one quantum q = (float)(1/30) = 0.0333333351: timeout q + 1.0. The clock after n
        // more quanta is (n + 1) q, past the timeout once n q > 1: 29 q = 0.967, 30 q = 1.0000000522. So the stick
        // ends in the 30th quantum after StickTo, and the move with it, not before.
        var rig = Moving();
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        for (int frame = 1; frame <= 29; frame++)
        {
            rig.Frame();
            Assert.True(rig.Motion.MoveToStatus == MoveToStatus.Moving, $"frame {frame}: {rig.Motion.MoveToStatus} {rig.Motion.MoveToResult} clock {rig.Manager.Clock:R} timeout {rig.Manager.StickyTimeout:R} stick {rig.Manager.StickyTargetId}");
        }
        rig.Frame();
        Assert.Equal(0u, rig.Manager.StickyTargetId);
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.ActionCancelled, rig.Motion.MoveToResult);
        Assert.Equal(0u, rig.Motion.MoveToCommand);
    }

    [Fact]
    public void LosingTheStuckTarget_CancelsTheMoveAtOnce_AnotherObjectsLossDoesNot()
    {
        var rig = Moving();
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Manager.LoseTarget(Target + 5, TargetStatus.ExitWorld);
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        rig.Manager.LoseTarget(Target, TargetStatus.ExitWorld);
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.ActionCancelled, rig.Motion.MoveToResult);
    }

    [Fact]
    public void UnStick_CancelsTheMove_OnlyWhenAStickWasRunning()
    {
        var rig = Moving();
        rig.Manager.UnStick(); // no stick: HandleExitWorld does nothing
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Manager.UnStick();
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.ActionCancelled, rig.Motion.MoveToResult);
    }

    [Fact]
    public void StickingAgain_EndsTheRunningStick_AndCancelsTheMove()
    {
        var rig = Moving();
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover); // the first stick: nothing was running
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        rig.Manager.StickTo(Target + 5, 0.48f, 1.835f, rig.Mover);
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(Target + 5, rig.Manager.StickyTargetId);
    }

    [Fact]
    public void ANewMove_UnsticksTheObject()
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Motion.MoveToPosition(ManagerRig.At(60f, 90f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.Equal(0u, rig.Manager.StickyTargetId);
        rig.Frame();
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
    }
}
