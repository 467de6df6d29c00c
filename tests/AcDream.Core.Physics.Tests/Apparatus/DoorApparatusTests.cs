using AcDream.Core.Physics;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// The seed's Holtburg cottage door, synthetic: a 1 m × 0.26 m × 2.2 m slab (BSP part), a foot cylinder
/// and a base sphere, state 0x10008 (HasPhysicsBsp | ReportCollisions), on a flat floor; a retail player
/// (two spheres r 0.48 at z 0.475 and 1.35, step-up 0.6, step-down 0.04) walks into it.
/// </summary>
public class DoorApparatusTests
{
    private const float Eps = PhysicsConstants.Epsilon;
    private static readonly float FrontStop = Scenes.DoorOrigin.Y + Scenes.SlabFront - Scenes.PlayerRadius;
    private static readonly float BackStop = Scenes.DoorOrigin.Y + Scenes.SlabBack + Scenes.PlayerRadius;

    [Theory]
    [InlineData(0x10008u)]
    [InlineData(0x10009u)]
    public void DeadCentre_FrontApproach_BlocksBeforeTheFace(uint state)
    {
        var world = Scenes.Door((PhysicsState)state);
        var player = Scenes.Player(world, 100, 98);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.InRange(player.Origin.Y, FrontStop - 0.05f, FrontStop + Eps * 5);
        Assert.InRange(player.Origin.X, 100 - 1e-3f, 100 + 1e-3f);
        Assert.True(player.State.OnWalkable, "the player stays grounded");
    }

    [Fact]
    public void DeadCentre_BackApproach_BlocksAfterTheBackFace()
    {
        var world = Scenes.Door();
        var player = Scenes.Player(world, 100, 102);
        player.Walk(new Vector3(0, -0.1f, 0), 40);
        Assert.InRange(player.Origin.Y, BackStop - Eps * 5, BackStop + 0.05f);
    }

    [Fact]
    public void HalfMetreOffCentre_FrontApproach_Blocks()
    {
        var world = Scenes.Door();
        var player = Scenes.Player(world, 100.5f, 98);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y <= FrontStop + Eps * 5, $"y = {player.Origin.Y}");
    }

    [Fact]
    public void OneLargeJumpThroughTheSlab_StillBlocks()
    {
        var world = Scenes.Door();
        var player = Scenes.Player(world, 100, 98);
        player.Step(new Vector3(0, 4f, 0));
        Assert.True(player.Origin.Y <= FrontStop + Eps * 5, $"y = {player.Origin.Y}: the mover tunnelled");
        Assert.True(player.Origin.Y > 98.5f, "sub-stepping should carry the mover up to the slab");
    }

    [Theory]
    [InlineData(1f)]   // NE
    [InlineData(-1f)]  // NW-ward along the face (the SE case mirrored for a front approach)
    public void DiagonalApproach_SlidesAlongTheFace_NeverStuck_NeverUsesTheCylinder(float sign)
    {
        var world = Scenes.Door();
        var player = Scenes.Player(world, 100 - sign * 0.4f, 99.0f).WithLog();
        var step = new Vector3(sign * 0.0707f, 0.0707f, 0);
        player.Walk(step, 30);
        foreach (var frame in player.Frames)
        {
            float tangential = (frame.After - frame.Before).X * sign;
            Assert.True(tangential > 1e-4f, $"stuck: frame moved {frame.After - frame.Before} for request {frame.Requested}");
        }
        Assert.DoesNotContain(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind != ShadowShapeKind.Bsp);
        Assert.DoesNotContain(player.Log!.Events, e => e.Kind == TransitionEventKind.ObjectNormal && e.ShapeKind == ShadowShapeKind.Cylinder);
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeSkipped && e.Reason == SkipReason.BspOnlyDispatch);
        Assert.All(player.Frames, f => Assert.True(f.After.Y <= FrontStop + Eps * 5 || MathF.Abs(f.After.X - 100) > Scenes.SlabHalfWidth + Scenes.PlayerRadius - 0.01f));
    }

    [Fact]
    public void HeadingSweep_HalfPlaneFacingTheDoor_NeverStuckWhileMotionHasATangentialPart()
    {
        var world = Scenes.Door();
        int stuck = 0, runs = 0;
        foreach (float lateral in new[] { -0.45f, -0.2f, 0f, 0.2f, 0.45f })
            for (int heading = -85; heading <= 85; heading += 5)
            {
                if (heading == 0) continue; // dead-centre has no tangential part
                float rad = heading * MathF.PI / 180f;
                var step = new Vector3(MathF.Sin(rad), MathF.Cos(rad), 0) * 0.1f;
                var player = Scenes.Player(world, 100 + lateral, 99.3f);
                player.Walk(step, 12);
                runs++;
                foreach (var f in player.Frames)
                    if (Vector3.DistanceSquared(f.Before, f.After) < 1e-10f)
                        stuck++;
            }
        Assert.Equal(0, stuck);
        Assert.Equal(5 * 34, runs);
    }

    [Fact]
    public void BitCleared_DoorCollidesThroughItsCylinder()
    {
        var world = Scenes.Door((PhysicsState)0x00008, registerShapesOnly: true);
        var player = Scenes.Player(world, 100, 98).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Cylinder);
        Assert.DoesNotContain(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Bsp);
        // The foot cylinder (r 0.5 at door-local y 0.12) stops the player before the slab would.
        float cylStop = Scenes.DoorOrigin.Y + 0.12f - 0.5f - Scenes.PlayerRadius;
        Assert.InRange(player.Origin.Y, cylStop - 0.05f, cylStop + 0.01f);
    }

    [Fact]
    public void Transition_AllocatesNothing_InSteadyState()
    {
        var world = Scenes.Door();
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(100.3f, 99.3f, 0), 0f);
        var target = state.Position;
        target.Frame.Origin += new Vector3(0.07f, 0.07f, 0);
        for (int i = 0; i < 50; i++)
            engine.Resolve(mover, state, target);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 200; i++)
            engine.Resolve(mover, state, target);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0, allocated);
    }
}
