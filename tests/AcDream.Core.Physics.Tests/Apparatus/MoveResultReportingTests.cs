using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// When a MoveResult reports a collision normal and collided object ids (documented on MoveResult):
/// retail reports a blocking object once, in the frame of first contact, never in the refused frames that
/// follow (CTransition::find_transitional_position returns before its first sub-step), and never lists
/// static objects (CPhysicsObj::FindObjCollisions counts them as environment, and only for a mover
/// without contact).
/// </summary>
public class MoveResultReportingTests
{
    private const uint RockId = 0x7000_0042;
    private static readonly PhysicsSetup Rock = new() { Spheres = [new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f)], Height = 1f, Radius = 0.5f };

    [Fact]
    public void Door_IsReportedInTheFirstContactFrame_AndNotInTheRefusedFramesAfter()
    {
        var mover = TestScenes.Player(TestScenes.Door(), TestScenes.DoorOrigin.X, TestScenes.DoorOrigin.Y - 1.2f);
        MoveResult result;
        int frame = 0;
        do
        {
            result = mover.Step(new Vector3(0f, 0.1f, 0f));
            Assert.True(++frame < 20, "the player never reached the door");
        }
        while (result.CollidedObjects.Length == 0);

        Assert.True(result.Succeeded);
        Assert.Equal(new[] { TestScenes.DoorId }, result.CollidedObjects.ToArray());
        Assert.Equal(TestScenes.DoorId, result.LastCollidedObject);
        Assert.True(result.CollisionNormalValid);
        Assert.Equal(-1f, result.CollisionNormal.Y, 3);              // the slab's front face
        Assert.True(result.Next.SlidingNormalValid);                  // carried into the next frame

        for (int i = 0; i < 3; i++)
        {
            var refused = mover.Step(new Vector3(0f, 0.1f, 0f));
            Assert.False(refused.Succeeded);
            Assert.False(refused.CollisionNormalValid);
            Assert.Equal(0, refused.CollidedObjects.Length);
            Assert.Equal(0u, refused.LastCollidedObject);
        }
    }

    [Theory]
    [InlineData(PhysicsState.Static | PhysicsState.ReportCollisions, false)]
    [InlineData(PhysicsState.ReportCollisions, true)]
    public void StaticObjects_AreNeverListed_ButStillGiveANormal(PhysicsState state, bool listed)
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(RockId, Rock, TestGeometry.At(100f, 100f, 0f), 1f, state);
        var mover = TestScenes.Player(world, 100f, 98.5f);
        MoveResult result;
        int frame = 0;
        do
        {
            result = mover.Step(new Vector3(0f, 0.1f, 0f));
            Assert.True(++frame < 20, "the player never reached the rock");
        }
        while (!result.CollisionNormalValid);

        Assert.Equal(listed, result.CollidedObjects.Length == 1);
        Assert.Equal(listed ? RockId : 0u, result.LastCollidedObject);
        Assert.False(result.CollidedWithEnvironment);                 // grounded: never environment
        Assert.True(mover.Origin.Y < 100f - 0.5f, $"the player went through the rock to y {mover.Origin.Y}");
    }

    [Fact]
    public void StaticObject_HitByAMoverWithoutContact_CountsAsEnvironment()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(RockId, Rock, TestGeometry.At(100f, 100f, 0f), 1f, PhysicsState.Static);
        var engine = new PhysicsEngine(world);
        var start = MoverState.Airborne(TestGeometry.At(100f, 98.6f, 0.3f));
        var target = start.Position;
        target.Frame.Origin += new Vector3(0f, 0.5f, 0f);
        var result = engine.Resolve(TestScenes.SeedPlayer(), start, target);

        Assert.Equal(0, result.CollidedObjects.Length);
        Assert.True(result.CollidedWithEnvironment);
        // From the air, touching a sphere records a landing candidate, not a normal (CSphere::land_on_sphere).
        Assert.False(result.CollisionNormalValid);
    }
}
