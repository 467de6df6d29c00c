using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// The seed's Holtburg cottage door, synthetic: a 1 m × 0.26 m × 2.2 m slab (BSP part), a foot cylinder
/// and a base sphere, state 0x10008 (HasPhysicsBsp | ReportCollisions), on a flat floor; a retail player
/// (two spheres r 0.48 at z 0.475 and 1.35, step-up 0.6, step-down 0.04) walks into it.
/// </summary>
public class DoorApparatusTests
{
    private const float Eps = PhysicsConstants.Epsilon;
    private static readonly float FrontStop = TestScenes.DoorOrigin.Y + TestScenes.SlabFront - TestScenes.PlayerRadius;
    private static readonly float BackStop = TestScenes.DoorOrigin.Y + TestScenes.SlabBack + TestScenes.PlayerRadius;

    [Theory]
    [InlineData(0x10008u)]
    [InlineData(0x10009u)]
    public void DeadCentre_FrontApproach_BlocksBeforeTheFace(uint state)
    {
        var world = TestScenes.Door((PhysicsState)state);
        var player = TestScenes.Player(world, 100, 98);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        // Retail stops at the last sub-step before contact: the gap is less than one frame's motion.
        Assert.InRange(player.Origin.Y, FrontStop - 0.1f, FrontStop + Eps * 5);
        Assert.InRange(player.Origin.X, 100 - 1e-3f, 100 + 1e-3f);
        Assert.True(player.State.OnWalkable, "the player stays grounded");
    }

    [Fact]
    public void DeadCentre_BackApproach_BlocksAfterTheBackFace()
    {
        var world = TestScenes.Door();
        var player = TestScenes.Player(world, 100, 102);
        player.Walk(new Vector3(0, -0.1f, 0), 40);
        // Retail stops at the last sub-step before contact: the gap is less than one frame's motion.
        Assert.InRange(player.Origin.Y, BackStop - Eps * 5, BackStop + 0.1f);
    }

    [Fact]
    public void HalfMetreOffCentre_FrontApproach_Blocks()
    {
        var world = TestScenes.Door();
        var player = TestScenes.Player(world, 100.5f, 98);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y <= FrontStop + Eps * 5, $"y = {player.Origin.Y}");
    }

    [Fact]
    public void OneLargeJumpThroughTheSlab_StillBlocks()
    {
        var world = TestScenes.Door();
        var player = TestScenes.Player(world, 100, 98);
        player.Step(new Vector3(0, 4f, 0));
        Assert.True(player.Origin.Y <= FrontStop + Eps * 5, $"y = {player.Origin.Y}: the mover tunnelled");
        Assert.True(player.Origin.Y > 98.5f, "sub-stepping should carry the mover up to the slab");
    }

    [Theory]
    [InlineData(1f)]   // NE
    [InlineData(-1f)]  // NW-ward along the face (the SE case mirrored for a front approach)
    public void DiagonalApproach_SlidesAlongTheFace_NeverStuck_NeverUsesTheCylinder(float sign)
    {
        var world = TestScenes.Door();
        var player = TestScenes.Player(world, 100 - sign * 0.4f, 99.0f).WithLog();
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
        Assert.All(player.Frames, f => Assert.True(TestScenes.SlabPenetration(f.After) <= Eps, $"penetrates the slab at {f.After}"));
        Assert.True(MathF.Abs(player.Origin.X - 100) > TestScenes.SlabHalfWidth + TestScenes.PlayerRadius, "the slide carries the mover past the slab's edge");
    }

    /// <summary>
    /// Headings every 5° over the half-plane facing the door, at several lateral offsets. Retail quirk
    /// (CSphere::slide_sphere; ACE Sphere.SlideSphere): a slide whose tangential displacement per sub-step
    /// has a squared length below EPSILON is refused as Collided, so a walk nearly square to the face
    /// (here 5° at 0.1 m per frame: 0.0087 m along the face) stalls every other frame. Every heading whose
    /// tangential part exceeds √EPSILON must never stall, and nothing may penetrate the slab.
    /// </summary>
    [Fact]
    public void HeadingSweep_NeverStuckWhenTheTangentialPartExceedsTheRetailSlideThreshold()
    {
        var world = TestScenes.Door();
        float threshold = MathF.Sqrt(PhysicsConstants.Epsilon);
        int stuckAboveThreshold = 0, stuckBelowThreshold = 0, runs = 0;
        foreach (float lateral in new[] { -0.45f, -0.2f, 0f, 0.2f, 0.45f })
            for (int heading = -85; heading <= 85; heading += 5)
            {
                if (heading == 0) continue; // dead-centre has no tangential part
                float rad = heading * MathF.PI / 180f;
                var step = new Vector3(MathF.Sin(rad), MathF.Cos(rad), 0) * 0.1f;
                var player = TestScenes.Player(world, 100 + lateral, 99.3f);
                player.Walk(step, 12);
                runs++;
                foreach (var f in player.Frames)
                {
                    Assert.True(TestScenes.SlabPenetration(f.After) <= Eps, $"heading {heading}, lateral {lateral}: penetrates at {f.After}");
                    if (Vector3.DistanceSquared(f.Before, f.After) >= 1e-10f)
                        continue;
                    if (MathF.Abs(step.X) > threshold) stuckAboveThreshold++;
                    else stuckBelowThreshold++;
                }
            }
        Assert.Equal(5 * 34, runs);
        Assert.Equal(0, stuckAboveThreshold);
        Assert.True(stuckBelowThreshold > 0, "the retail slide threshold should stall the 5° walks (quirk pinned)");
    }

    /// <summary>
    /// With HasPhysicsBsp cleared the door is collided through its foot cylinder (the second rung), never
    /// its BSP. The synthetic foot cylinder is 0.2 m tall, under the 0.6 m step-up, so the player steps up
    /// onto it (retail CCylSphere::step_sphere_up) and — the slab being untested — walks on through:
    /// exactly why the retail dispatch must not fall through to the cylinder for a door.
    /// </summary>
    [Fact]
    public void BitCleared_DoorCollidesThroughItsCylinder_AndTheLowCylinderIsSteppedOnto()
    {
        var world = TestScenes.Door((PhysicsState)0x00008, registerShapesOnly: true);
        var player = TestScenes.Player(world, 100, 98).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Cylinder);
        Assert.DoesNotContain(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Bsp);
        Assert.Contains(player.Frames, f => MathF.Abs(f.After.Z - (0.2f + 0.005f)) < 0.01f);
        Assert.True(player.Origin.Y > TestScenes.DoorOrigin.Y + TestScenes.SlabBack, "nothing tests the slab, so the player passes it");
    }

    [Fact]
    public void Transition_AllocatesNothing_InSteadyState()
    {
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var mover = TestScenes.SeedPlayer();
        var state = MoverState.OnFloor(TestGeometry.At(100.3f, 99.3f, 0), 0f);
        var target = state.Position;
        target.Frame.Origin += new Vector3(0.07f, 0.07f, 0);
        long allocated = Allocations.PerRound(
            () => { for (int i = 0; i < 50; i++) engine.Resolve(mover, state, target); },
            () => { for (int i = 0; i < 200; i++) engine.Resolve(mover, state, target); });
        Assert.Equal(0, allocated);
    }

    /// <summary>
    /// A grounded mover blocked by the slab falls back on its last known contact plane, and retail then
    /// zeroes its velocity (OBJECTINFO::kill_velocity in validate_transition); free frames do not.
    /// </summary>
    [Fact]
    public void BlockedFrames_AskForTheVelocityToBeKilled_FreeFramesDoNot()
    {
        var world = TestScenes.Door();
        var player = TestScenes.Player(world, 100, 98);
        player.Walk(new Vector3(0, 0.1f, 0), 20);
        Assert.False(player.Frames[0].Result.VelocityKilled);
        Assert.Contains(player.Frames, f => f.Result.VelocityKilled && f.After == f.Before);
        Assert.All(player.Frames.Where(f => f.Result.VelocityKilled), f => Assert.True(f.Result.CollisionNormalValid));
    }
}
