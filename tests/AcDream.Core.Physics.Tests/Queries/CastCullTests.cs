using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// Casts at the edges of what a cast skips — a polygon's box widened by the radius, the segment against
/// that box, an object listed in two cells swept once — against hand-computed answers. Door scene: the slab
/// spans x 99.5..100.5, front face y = 99.991, z 0..2.2. Cottage: the same door at y 99.85 across the
/// doorway's portal (y = 100), its slab y 99.841..100.102, listed in the land cell and in the room.
/// </summary>
public class CastCullTests
{
    private const uint Land = 0xA9B40025, Door = 0x7000_0001;
    private const float DoorFront = 99.991f;

    private static Position At(float x, float y, float z) => new(Land, new Vector3(x, y, z));

    [Fact]
    public void SphereCast_PassingBesideTheSlab_CatchesItsFrontEdge_WithTheCentreOutsideTheFacesBox()
    {
        var q = new WorldQuery(SceneLibrary.Load("door").World);
        // The centre runs 0.29 m east of the slab's east side (x = 100.79), so the 0.3 m sphere meets the
        // vertical edge (100.5, 99.991) when the centre is 0.3 m from it: y = 99.991 − √(0.3² − 0.29²).
        float back = MathF.Sqrt(0.3f * 0.3f - 0.29f * 0.29f);
        Assert.True(q.SphereCast(At(100.79f, 98f, 1f), new Vector3(100.79f, 102f, 1f), 0.3f, out var hit));
        Assert.Equal(Door, hit.ObjectId);
        Assert.Equal((DoorFront - back - 98f) / 4f, hit.Fraction, 4);
        AssertVec.Near(Vector3.Normalize(new Vector3(0.29f, -back, 0)), hit.Normal, 1e-3f);
        AssertVec.Near(new Vector3(100.5f, DoorFront, 1f), hit.Point, 1e-3f);
    }

    [Fact]
    public void RayCast_OnADiagonal_HitsTheFrontFaceJustInsideItsCorner()
    {
        var q = new WorldQuery(SceneLibrary.Load("door").World);
        // From (99.6, 98) along (1.8, 4): at the front face x = 99.6 + 1.8 · 1.991 / 4 = 100.496, 4 mm
        // inside the slab's east edge.
        Assert.True(q.RayCast(At(99.6f, 98f, 1f), new Vector3(101.4f, 102f, 1f), out var hit));
        Assert.Equal(Door, hit.ObjectId);
        Assert.Equal((DoorFront - 98f) / 4f, hit.Fraction, 5);
        AssertVec.Near(new Vector3(0, -1, 0), hit.Normal);
        AssertVec.Near(new Vector3(99.6f + 1.8f * (DoorFront - 98f) / 4f, DoorFront, 1f), hit.Point, 1e-4f);
    }

    [Fact]
    public void SphereCasts_ThroughTheCottageDoorway_HitTheDoorListedInTheLandCellAndTheRoom_FromEitherSide()
    {
        var q = new WorldQuery(SceneLibrary.Load("cottage").World);
        // From outside: the front face y = 99.841 stops the centre at 99.541.
        Assert.True(q.SphereCast(At(100f, 97f, 1f), new Vector3(100f, 103f, 1f), 0.3f, out var inward));
        Assert.Equal(SurfaceKind.Object, inward.Kind);
        Assert.Equal(Door, inward.ObjectId);
        Assert.Equal(Land, inward.CellId);
        Assert.Equal((99.841f - 0.3f - 97f) / 6f, inward.Fraction, 4);
        AssertVec.Near(new Vector3(0, -1, 0), inward.Normal, 1e-4f);
        // From inside the room: the back face y = 100.102 stops the centre at 100.402.
        Assert.True(q.SphereCast(new Position(0xA9B40100, new Vector3(100f, 103f, 1f)), new Vector3(100f, 97f, 1f), 0.3f, out var outward));
        Assert.Equal(Door, outward.ObjectId);
        Assert.Equal((103f - 100.402f) / 6f, outward.Fraction, 4);
        AssertVec.Near(new Vector3(0, 1, 0), outward.Normal, 1e-4f);
    }

    [Fact]
    public void RayCast_PastFortyBallsBesideIt_HitsTheBallOnItsLine()
    {
        // More objects in the cast's box than the swept-object set first holds (16): forty balls 0.6 m north
        // of a diagonal ray (0.42 m from the line, radius 0.2: all missed), then one ball on the line.
        var world = TestGeometry.FlatWorld();
        var ball = new AcDream.Core.Physics.PhysicsSetup { Spheres = [new AcDream.Core.Physics.Sphere(Vector3.Zero, 0.2f)] };
        for (int i = 0; i < 40; i++)
        {
            float x = 90.5f + i * 0.5f;
            world.Objects.Register(0x7000_0200u + (uint)i, ball, TestGeometry.At(x, x + 0.6f, 1.5f), 1f, PhysicsState.Static);
        }
        const uint target = 0x7000_0300;
        world.Objects.Register(target, ball, TestGeometry.At(111f, 111f, 1.5f), 1f, PhysicsState.Static);
        var q = new WorldQuery(world);
        Assert.True(q.RayCast(TestGeometry.At(90f, 90f, 1.5f), new Vector3(112f, 112f, 1.5f), out var hit));
        Assert.Equal(target, hit.ObjectId);
        // The line meets the ball 0.2 m before its centre: (21·√2 − 0.2) / (22·√2) of the way.
        Assert.Equal((21f * MathF.Sqrt(2f) - 0.2f) / (22f * MathF.Sqrt(2f)), hit.Fraction, 4);
    }
}
