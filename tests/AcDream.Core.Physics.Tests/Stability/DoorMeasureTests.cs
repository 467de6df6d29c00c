using AcDream.Core.Physics.Bench;
using AcDream.Core.Physics.Bench.Accuracy;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Tests.Stability;

/// <summary>The measures themselves.</summary>
public class DoorMeasureTests
{
    [Fact]
    public void SlabPenetration_IsTheDeepestSphereOverlap()
    {
        Assert.Equal(0f, DoorScene.SlabPenetration(new Vector3(100, DoorScene.FrontStop, 0)), 1e-4f);
        Assert.Equal(0.1f, DoorScene.SlabPenetration(new Vector3(100, DoorScene.FrontStop + 0.1f, 0)), 1e-4f);
        Assert.Equal(-0.5f, DoorScene.SlabPenetration(new Vector3(100, DoorScene.FrontStop - 0.5f, 0)), 1e-4f);
        // Centre inside the slab: deeper than a radius.
        Assert.True(DoorScene.SlabPenetration(new Vector3(100, DoorScene.SlabMidY, 0)) > DoorScene.PlayerRadius);
    }

    [Fact]
    public void Crossed_OnlyThroughTheSlab()
    {
        float y0 = DoorScene.FrontStop, y1 = DoorScene.DoorOrigin.Y + 1f;
        Assert.True(AccuracyRunner.Crossed(new Vector3(100.3f, y0, 0), new Vector3(100.3f, y1, 0)));
        Assert.False(AccuracyRunner.Crossed(new Vector3(101.2f, y0, 0), new Vector3(101.2f, y1, 0)));
        Assert.False(AccuracyRunner.Crossed(new Vector3(100.3f, y0, 0), new Vector3(100.3f, y0 + 0.2f, 0)));
    }

    [Fact]
    public void IsStuck_NeedsTangentialMotionAboveTheSlideThresholdPerSubStep()
    {
        var before = new Vector3(100, DoorScene.FrontStop, 0);
        var moved = new ReferenceMoveResult(before + new Vector3(0.05f, 0, 0), 1, -Vector3.UnitY, -Vector3.UnitY, 0f);
        var step = new Vector3(0.05f, 0.05f, 0);
        Assert.True(AccuracyRunner.IsStuck(before, before, step, moved, 1));
        Assert.False(AccuracyRunner.IsStuck(before, before, step, moved, 4), "0.05 / 4 is below √EPSILON");
        Assert.False(AccuracyRunner.IsStuck(before, before + new Vector3(0.01f, 0, 0), step, moved, 1));
        var stayed = new ReferenceMoveResult(before, 1, -Vector3.UnitY, -Vector3.UnitY, 0f);
        Assert.False(AccuracyRunner.IsStuck(before, before, step, stayed, 1), "the reference could not move either");
    }
}
