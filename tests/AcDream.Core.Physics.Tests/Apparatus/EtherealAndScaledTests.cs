using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>An ethereal mover against static and non-static objects; a player standing on and landing on a scaled BSP object.</summary>
public class EtherealAndScaledTests
{
    private const uint WallId = 0x7000_0040;

    private static MoverDescription Ghost() =>
        new(0x5000_000A, [new Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f, PhysicsState.Gravity | PhysicsState.Ethereal, ObjectInfoState.IsPlayer);

    /// <summary>A wall 4 m wide, 1 m thick (y 102..103), 2 m tall, registered with the given state.</summary>
    private static PhysicsWorld Wall(PhysicsState state)
    {
        var world = TestGeometry.FlatWorld();
        var model = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-2, 0, 0), new Vector3(2, 1, 2)), name: "wall");
        world.Objects.Register(WallId, new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] }, TestGeometry.At(100, 102, 0), 1f, state);
        return world;
    }

    // Retail CPhysicsObj::FindObjCollisions: an object is passed through as ethereal when it is ethereal
    // itself, or when it is not static and the mover is ethereal. So an ethereal mover (r = 0.5, from
    // y = 101 in 0.1 m frames) is stopped by a static wall at its face, y = 102 − 0.5, and walks through a
    // non-static one to y = 105, which is recorded as collided (with no collision normal) on the way.

    [Fact]
    public void EtherealMover_IsStoppedByAStaticWall()
    {
        var ghost = new Mover(Wall(PhysicsState.Static), Ghost(), MoverState.OnFloor(TestGeometry.At(100, 101, 0), 0f));
        ghost.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.InRange(ghost.Origin.Y, 101.5f - 0.1f, 101.5f + PhysicsConstants.Epsilon);
        Assert.All(ghost.Frames, f => Assert.DoesNotContain(WallId, f.Collided)); // static objects count as environment
        // It is stopped by a real collision with the wall's face (normal −Y), not by the ethereal overlap
        // test, which records no normal (validate_transition would then report +Z).
        var hits = ghost.Frames.Where(f => f.Result.CollisionNormalValid).ToList();
        Assert.NotEmpty(hits);
        Assert.All(hits, f => Assert.Equal(-1f, f.Result.CollisionNormal.Y, 4));
    }

    [Fact]
    public void EtherealMover_WalksThroughANonStaticWall_RecordingIt()
    {
        var ghost = new Mover(Wall(PhysicsState.None), Ghost(), MoverState.OnFloor(TestGeometry.At(100, 101, 0), 0f));
        ghost.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.InRange(ghost.Origin.Y, 105f - 0.001f, 105f + 0.001f);
        var inside = ghost.Frames.Where(f => f.Collided.Contains(WallId)).ToList();
        Assert.NotEmpty(inside);
        Assert.All(inside, f => Assert.False(f.Result.CollisionNormalValid));
    }

    [Fact]
    public void SolidMover_IsStoppedByTheNonStaticWall_TheControl()
    {
        var solid = new MoverDescription(0x5000_000B, Ghost().Spheres, 0.6f, 0.8f, PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var mover = new Mover(Wall(PhysicsState.None), solid, MoverState.OnFloor(TestGeometry.At(100, 101, 0), 0f));
        mover.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.InRange(mover.Origin.Y, 101.5f - 0.1f, 101.5f + PhysicsConstants.Epsilon);
        Assert.Contains(mover.Frames, f => f.Collided.Contains(WallId));
    }

    // A unit-height block, 2 m × 2 m (model space x, y in −1..1, z in 0..1), registered at scale 2.5: its
    // top is at z = 2.5 and it spans x, y in 97.5..102.5 around (100, 100). The BSP is queried in model
    // space and every offset it produces is multiplied back by the scale. The player's sphere 0 (centre
    // 0.475, radius 0.48) reaches 0.005 below its origin, so standing on the top puts the origin at 2.505.

    private const float Scale = 2.5f;

    private static PhysicsWorld ScaledBlock()
    {
        var world = TestGeometry.FlatWorld();
        var model = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-1, -1, 0), new Vector3(1, 1, 1)), name: "block");
        world.Objects.Register(WallId, new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] }, TestGeometry.At(100, 100, 0), Scale, PhysicsState.Static);
        return world;
    }

    [Fact]
    public void Player_StandsAndWalksOnAScaledBlock_AtItsScaledTop()
    {
        var player = new Mover(ScaledBlock(), MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(99, 99, 2.5f), 2.5f));
        player.Walk(new Vector3(0.1f, 0.1f, 0), 15); // to (100.5, 100.5), still on the top
        Assert.All(player.Frames, f => Assert.InRange(f.After.Z, 2.505f - 0.002f, 2.505f + 0.002f));
        Assert.InRange(player.Origin.X, 100.5f - 0.001f, 100.5f + 0.001f);
        Assert.True(player.State.Contact && player.State.OnWalkable);
    }

    [Fact]
    public void Player_FallingOntoAScaledBlock_LandsOnItsScaledTop()
    {
        // Airborne 0.3 m above the top, asked to fall 1 m: it lands at z = 2.505 (not 1.005, on the unscaled top).
        var player = new Mover(ScaledBlock(), MoverDescription.Player(), MoverState.Airborne(TestGeometry.At(100, 100, 2.8f)));
        player.Step(new Vector3(0, 0, -1f));
        Assert.InRange(player.Origin.Z, 2.505f - 0.002f, 2.505f + 0.002f);
        Assert.True(player.State.Contact && player.State.OnWalkable);
    }
}
