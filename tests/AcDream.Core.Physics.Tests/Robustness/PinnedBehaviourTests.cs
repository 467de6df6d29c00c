using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Tests.Managers;
using AcDream.Core.Physics.Tests.Motion;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Behaviours no test held before (each survived a small change of its line in an outside fault check): each is pinned
/// here by the behaviour's name, with values worked by hand from the retail rule in the comment.
/// </summary>
public class PinnedBehaviourTests
{
    [Fact]
    public void TheInterpreter_TakesSixPendingActions_AndRefusesTheSeventh()
    {
        // CMotionInterp::DoMotion: an action (0x10000000 bit) with six already pending is TooManyActions.
        var rig = new MotionRig();
        var action = MotionCommandMask.Action | 0x51u;
        rig.Motion.Manager.State.ActionCount = 6;
        Assert.Equal(MotionError.TooManyActions, rig.Motion.Interpreter.DoMotion(action, new MotionParameters(1f, HoldKey.None)));
        rig.Motion.Manager.State.ActionCount = 5;
        Assert.NotEqual(MotionError.TooManyActions, rig.Motion.Interpreter.DoMotion(action, new MotionParameters(1f, HoldKey.None)));
    }

    [Fact]
    public void ZeroSpeed_HasTheSignOfAPositiveSpeed_InTheTablesSameSign()
    {
        // same_sign (CMTable.c:66-84): zero counts as positive (ACE's Math.Sign gives zero a sign of its own).
        Assert.True(MotionTableManager.SameSign(0f, 1f));
        Assert.True(MotionTableManager.SameSign(0f, 0f));
        Assert.False(MotionTableManager.SameSign(0f, -1f));
        Assert.False(MotionTableManager.SameSign(-0.5f, 0f));
    }

    [Fact]
    public void ACycleWrappingWithinOneQuantum_GoesBackToTheFirstCyclicAnimation_NotTheFirstAnimation()
    {
        // [link, cycle 1, cycle 2], one frame each at 30 frames/s, the link playing: a 0.2 s quantum plays the link, then
        // the cycles round and round (six frames' time). Entering a node adds its first root frame: the link's moves
        // +1 m along x, the cycles' not at all. The link is never entered (it was playing already), so the offset is 0;
        // wrapping to the first animation instead would enter the link and add 1 m each time.
        var link = new Animation(0x03000001, 1, [new RootFrame(new Vector3(1f, 0f, 0f), Quaternion.Identity)]);
        var c1 = new Animation(0x03000002, 1, [new RootFrame(Vector3.Zero, Quaternion.Identity)]);
        var c2 = new Animation(0x03000003, 1, [new RootFrame(Vector3.Zero, Quaternion.Identity)]);
        var sequence = new Sequence();
        sequence.Restore([
            new Sequence.Node { Animation = link, Framerate = 30f, LowFrame = 0, HighFrame = 0 },
            new Sequence.Node { Animation = c1, Framerate = 30f, LowFrame = 0, HighFrame = 0 },
            new Sequence.Node { Animation = c2, Framerate = 30f, LowFrame = 0, HighFrame = 0 },
        ], firstCyclic: 1, current: 0, frameNumber: 0.0, Vector3.Zero, Vector3.Zero);
        var offset = new Frame(Vector3.Zero);
        sequence.Update(0.2f, ref offset);
        Assert.Equal(0f, offset.Origin.X);
        // The link, played, was dropped from the head (apricot): the two cycles are left.
        Assert.Equal(2, sequence.Count);
    }

    [Theory]
    // CylinderDistance: the vertical gap is measured from the top of the LOWER body (its own height), not the other's.
    // Radii 0.5 each, 10 m apart horizontally and 5 m vertically: reach sqrt(125) - 1 m; distance sqrt(gap² + reach²).
    [InlineData(0f, 2f, 5f, 1f, 3.0)] // lower body 1 is 2 m tall: gap 5 - 2 = 3
    [InlineData(5f, 1f, 0f, 2f, 3.0)] // the same bodies given the other way round
    [InlineData(0f, 1f, 5f, 2f, 4.0)] // lower body 1 is 1 m tall: gap 4
    public void CylinderDistance_OfBodiesOfUnequalHeights_TakesTheGapAboveTheLowerBody(float z1, float h1, float z2, float h2, double gap)
    {
        var p1 = TestGeometry.At(100f, 100f, z1);
        var p2 = TestGeometry.At(110f, 100f, z2);
        float d = Headings.CylinderDistance(0.5f, h1, p1, 0.5f, h2, p2);
        double reach = Math.Sqrt(125.0) - 1.0;
        Assert.Equal(Math.Sqrt(gap * gap + reach * reach), d, 4);
    }

    private static ObjectView View(float x, float y) => new(TestGeometry.At(x, y, 0f), contact: true, radius: 0.48f, maxSpeed: 1f, adjustedMaxSpeed: 1f, isPlayer: false);

    [Fact]
    public void ASticker_OverlappingItsTargetByMoreThanOneStep_StepsFurtherIn_AsRetail()
    {
        // StickyManager::adjust_offset (CStickyManager.c:388518): step = speed × quantum = (1 × 5) × 0.1 = 0.5 m, toward
        // the target; only a gap smaller than the step is taken whole (negative: backing away to 0.3 m). Radii 0.48 and
        // 0.5, target straight ahead (+y).
        var sticky = new StickyManager();
        sticky.StickTo(7, 0.5f, 0.0);
        // 0.5 m apart: gap 0.5 - 0.98 - 0.3 = -0.78, more than a step: retail steps 0.5 m further in.
        sticky.HandleUpdateTarget(7, TargetStatus.Ok, TestGeometry.At(100f, 100.5f, 0f));
        var offset = new Frame(Vector3.Zero);
        sticky.AdjustOffset(ref offset, 0.1f, View(100f, 100f));
        Assert.Equal(0.5f, offset.Origin.Y, 5);
        // 1.2 m apart: gap -0.08, within a step: it backs away 0.08 m.
        sticky.HandleUpdateTarget(7, TargetStatus.Ok, TestGeometry.At(100f, 101.2f, 0f));
        offset = new Frame(Vector3.Zero);
        sticky.AdjustOffset(ref offset, 0.1f, View(100f, 100f));
        Assert.Equal(-0.08f, offset.Origin.Y, 4);
        // An object whose max speed is below EPSILON catches up at DefaultSpeed 15 m/s: 1.5 m in 0.1 s of a 1.72 m gap
        // (3 m apart: 3 - 0.98 - 0.3).
        sticky.HandleUpdateTarget(7, TargetStatus.Ok, TestGeometry.At(100f, 103f, 0f));
        offset = new Frame(Vector3.Zero);
        sticky.AdjustOffset(ref offset, 0.1f, new ObjectView(TestGeometry.At(100f, 100f, 0f), true, 0.48f, 0f, 0f, false));
        Assert.Equal(1.5f, offset.Origin.Y, 4);
    }

    [Fact]
    public void InterpolatingWhileStuck_TheStickerSetsTheOffset_AndNoInterpolationNodeFails()
    {
        // PositionManager::adjust_offset runs the interpolation, then the sticky manager (whose offset replaces it), and
        // tells the interpolation it is sticking: its progress check then always passes (CInterpolationManager.c:389177).
        // A player stuck to a target 1.6 m north (the gap closes to 0.3 m: y 60.34) and asked to interpolate to a node
        // 10 m south: the node makes no progress, yet it neither fails nor blips, and the sticker holds the player.
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.StickTo(0x50000002, 0.48f, 1.835f, rig.Mover);
        rig.Manager.UpdateTarget(0x50000002, ManagerRig.At(60f, 61.6f));
        rig.InterpolateTo(60f, 50f);
        for (int frame = 1; frame <= 20; frame++)
        {
            rig.Frame();
            Assert.Equal(60.34f, rig.Origin.Y, 4);
            Assert.Equal(0, rig.Manager.FailedNodes);
            Assert.True(rig.Manager.IsInterpolating, $"frame {frame}: the node was dropped");
        }
    }

    private static readonly PhysicsSetup Ball = new() { Spheres = [new Sphere(Vector3.Zero, 0.4f)] };

    [Fact]
    public void UnloadingALandblock_DropsAnObjectStandingInItsLastLandCell()
    {
        // Land cell 0x40 is the north-east corner (x and y 168..192): the drop walks cells 1..64 inclusive.
        var world = new PhysicsWorld();
        world.LoadLandblock(Terrain.Flat(0xA9B4, 0f));
        world.Objects.Register(5, Ball, new Position(0xA9B40040, new Vector3(180f, 180f, 0.4f)));
        Assert.Equal([0xA9B40040u], world.Objects.CellsOf(5));
        world.UnloadLandblock(0xA9B4);
        Assert.False(world.Objects.Contains(5));
        Assert.Equal(0, world.Objects.Count);
    }

    [Fact]
    public void AFailedLoadObjects_RollsBackEveryObjectItRegistered()
    {
        // Four objects; the fourth's id is already in the target: the three registered before it are removed again.
        var source = TestGeometry.FlatWorld();
        for (uint id = 1; id <= 4; id++)
            source.Objects.Register(id, Ball, TestGeometry.At(100 + 2 * id, 100, 0.4f));
        var bytes = Snapshot.SaveObjects(source, _ => 1u);
        var target = TestGeometry.FlatWorld();
        target.Objects.Register(4, Ball, TestGeometry.At(50, 50, 0.4f));
        Assert.Throws<ArgumentException>(() => Snapshot.LoadObjects(bytes, target, _ => Ball));
        Assert.Equal(1, target.Objects.Count);
        for (uint id = 1; id <= 3; id++)
            Assert.False(target.Objects.Contains(id), $"object {id} stayed registered after the failed load");
        Assert.Equal(50f, target.Objects.PositionOf(4).Frame.Origin.X);
    }
}
