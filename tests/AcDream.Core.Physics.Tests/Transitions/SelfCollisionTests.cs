using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>A mover that is also registered as an object (as a client registers every physics object) never collides with its own rows.</summary>
public class SelfCollisionTests
{
    [Fact]
    public void AMoverRegisteredAsAnObject_WalksThroughItsOwnShapes()
    {
        // The mover's own cylinder (radius 0.5, height 2) is registered at its start; it walks 1 m away in
        // 0.1 m frames. Tested against itself it would be stuck inside at once; skipped, it ends 1 m along.
        var world = Support.TestGeometry.FlatWorld();
        var mover = new MoverDescription(0x5000_000D, [new AcDream.Core.Physics.Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f,
            PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var start = Support.TestGeometry.At(100, 100, 0);
        world.Objects.Register(mover.ObjectId, new AcDream.Core.Physics.PhysicsSetup { CylSpheres = [new AcDream.Core.Physics.CylSphere(Vector3.Zero, 0.5f, 2f)] },
            start, 1f, PhysicsState.Static);
        var walker = new Support.Mover(world, mover, MoverState.OnFloor(start, 0f));
        walker.Walk(new Vector3(0, 0.1f, 0), 10);
        Assert.InRange(walker.Origin.Y, 101f - 0.001f, 101f + 0.001f);
        Assert.All(walker.Frames, f => Assert.False(f.Result.CollisionNormalValid));
    }
}
