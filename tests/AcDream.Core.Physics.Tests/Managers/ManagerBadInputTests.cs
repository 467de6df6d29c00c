using AcDream.Core.Physics.Managers;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>Bad input to the position managers: a clear error naming the field, nothing changed, or a documented retail outcome.</summary>
public class ManagerBadInputTests
{
    [Theory]
    [InlineData(float.NaN, 90f, "position")]
    [InlineData(100f, float.PositiveInfinity, "position")]
    [InlineData(1e30f, 90f, "position")]
    public void ABadPosition_IsRefusedByName_AndTheQueueIsUnchanged(float x, float y, string field)
    {
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 90f);
        var before = rig.State;
        var ex = Assert.Throws<ArgumentException>(() => rig.Manager.InterpolateTo(new Position(0xA9B40025, new Vector3(x, y, 0f)), false, rig.Mover, ref rig.State));
        Assert.Contains(field, ex.Message);
        Assert.Equal(1, rig.Manager.QueuedPositions);
        Assert.Equal(before.Position.Frame.Origin, rig.State.Position.Frame.Origin);
    }

    [Fact]
    public void ACellOutsideTheWorld_IsRefusedByName()
    {
        var rig = new ManagerRig(100f, 84f);
        var ex = Assert.Throws<ArgumentException>(() => rig.Manager.InterpolateTo(new Position(0xFFFF0001, new Vector3(1f, 1f, 0f)), false, rig.Mover, ref rig.State));
        Assert.Contains("position.cell", ex.Message);
        Assert.Throws<ArgumentException>(() => rig.Manager.UpdateTarget(0x50000002, new Position(0, Vector3.Zero)));
    }

    [Fact]
    public void APositionInAnUnloadedLandblock_CannotBeBlippedTo_AndIsRetriedEachQuantum()
    {
        // Retail: 0xA9B6 is 400 m away (beyond the blip distance): the node is marked failed, SetPositionSimple fails
        // (no cell) and the queue stays, UseTime tries again each quantum while adjust_offset moves towards the node
        // through the transition. No crash, no NaN.
        var rig = new ManagerRig(100f, 84f);
        rig.Manager.InterpolateTo(new Position(0xA9B60013, new Vector3(60f, 60f, 0f)), false, rig.Mover, ref rig.State);
        rig.Frames(5);
        Assert.Equal(ManagerRig.Block, rig.State.Position.CellId >> 16);
        Assert.True(float.IsFinite(rig.Origin.X) && float.IsFinite(rig.Origin.Y) && float.IsFinite(rig.Origin.Z));
        Assert.True(rig.Origin.Y > 84f);
        Assert.True(rig.Manager.IsInterpolating);
        Assert.Equal(4, rig.Manager.FailedNodes);
    }

    [Fact]
    public void StickingToNothingOrToItself_IsRefusedByName()
    {
        var rig = new ManagerRig(60f, 60f);
        Assert.Contains("targetId", Assert.Throws<ArgumentException>(() => rig.Manager.StickTo(0, 0.5f, 1f, rig.Mover)).Message);
        Assert.Contains("itself", Assert.Throws<ArgumentException>(() => rig.Manager.StickTo(rig.Mover.ObjectId, 0.5f, 1f, rig.Mover)).Message);
        Assert.Contains("targetRadius", Assert.Throws<ArgumentException>(() => rig.Manager.StickTo(2, float.NaN, 1f, rig.Mover)).Message);
        Assert.Contains("targetHeight", Assert.Throws<ArgumentException>(() => rig.Manager.StickTo(2, 0.5f, -1f, rig.Mover)).Message);
        Assert.Equal(0u, rig.Manager.StickyTargetId);
    }

    [Fact]
    public void LosingATargetWithStatusOk_IsRefused() =>
        Assert.Contains("status", Assert.Throws<ArgumentException>(() => new ManagerRig(60f, 60f).Manager.LoseTarget(2, TargetStatus.Ok)).Message);

    [Fact]
    public void TargetCallsWithoutAStick_DoNothing()
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.UpdateTarget(0x50000002, ManagerRig.At(61f, 61f));
        rig.Manager.LoseTarget(0x50000002, TargetStatus.ExitWorld);
        rig.Manager.UnStick();
        rig.Frame();
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
    }

    [Fact]
    public void ALeashWithMaxNotAboveStart_IsRefusedByName()
    {
        var rig = new ManagerRig(60f, 60f);
        Assert.Contains("maxDistance", Assert.Throws<ArgumentException>(() => rig.Manager.ConstrainTo(rig.State.Position, 2f, 2f, rig.State)).Message);
        Assert.Contains("startDistance", Assert.Throws<ArgumentException>(() => rig.Manager.ConstrainTo(rig.State.Position, float.NaN, 2f, rig.State)).Message);
        Assert.False(rig.Manager.IsConstrained);
    }
}
