using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// Work the engine keeps from one move or sub-step to the next (not retail; changes no result): the spheres
/// at the last current position, and the last interpolated rotation.
/// </summary>
public class RememberedWorkTests
{
    [Fact]
    public void AnotherMoverStartingWhereTheLastMoveStarted_GetsItsOwnSpheres()
    {
        var path = new AcDream.Core.Physics.Transitions.SpherePath();
        var start = TestGeometry.At(100, 100, 0);

        // Two one-sphere movers with the same lowest point (the sphere's foot at the origin) and different spheres.
        path.Reset();
        path.InitSphere([new Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 1f);
        path.InitPath(null, in start, in start);
        Assert.Equal(new Vector3(100, 100, 0.5f), path.GlobalCurrCenter[0].Center);

        path.Reset();
        path.InitSphere([new Sphere(new Vector3(0, 0, 0.3f), 0.3f)], 1f);
        path.InitPath(null, in start, in start);

        Assert.Equal(new Vector3(100, 100, 0.3f), path.GlobalCurrCenter[0].Center);
        Assert.Equal(0.3f, path.GlobalCurrCenter[0].Radius);
    }

    [Fact]
    public void AMoverTurningAsItMoves_EndsFacingTheTarget()
    {
        // 2 m in sub-steps of one radius (5 sub-steps), turning a quarter turn about Z: each sub-step
        // turns part of the way (retail interpolate_rotation), and the last one reaches the target's.
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var start = MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f);
        var quarter = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
        var target = new Position(start.Position.CellId, new Frame(new Vector3(102, 100, 0), quarter));

        var result = engine.Resolve(MoverDescription.Player(), start, target);

        Assert.True(result.Succeeded);
        var q = result.Next.Position.Frame.Orientation;
        Assert.Equal(quarter.Z, q.Z, 1e-6f);
        Assert.Equal(quarter.W, q.W, 1e-6f);
        Assert.Equal(102f, result.Next.Position.Origin.X, 1e-4f);
    }
}
