using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// Which surfaces a floor query accepts (normal Z at least floor_z, <see cref="PhysicsConstants.FloorZ"/> =
/// 0.664, on objects and on terrain alike) and how a cast's radius meets a scaled object, against answers
/// worked out by hand.
/// </summary>
public class FloorAndScaleQueryTests
{
    private const uint Roof = 0x7100_0001, Crate = 0x7100_0002;

    private static PhysicsSetup Part(BspTree tree) =>
        new() { Parts = [new SetupPart(new PhysicsModel(tree, name: "part"), Frame.Identity)] };

    [Fact]
    public void Floor_LooksThroughASteepRoof_ToTheGroundBeneath()
    {
        // A 2 × 2 × 0.1 m slab turned 60° about X, centred 3 m above flat ground at (100, 100): its top face's
        // normal is (0, −sin 60°, cos 60°), Z = 0.5, below floor_z, so a floor query from 10 m up looks through it
        // and finds the ground, z = 0. A ray cast down the same line meets the roof's top face instead, at the
        // slab's centre plane plus half its thickness measured along the vertical: 3 + 0.05 / cos 60° = 3.1 m.
        var world = TestGeometry.FlatWorld();
        var tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI / 3);
        world.Objects.Register(Roof, Part(BspShapes.Slab(Vector3.Zero, new Vector3(2, 2, 0.1f), tilt)), TestGeometry.At(100, 100, 3), 1f,
            PhysicsState.Static | PhysicsState.HasPhysicsBsp);
        var q = new WorldQuery(world);

        Assert.True(q.RayCast(TestGeometry.At(100, 100, 10), new Vector3(100, 100, -10), out var roof));
        Assert.Equal(Roof, roof.ObjectId);
        Assert.Equal(3.1f, roof.Point.Z, 3);
        Assert.Equal(0.5f, roof.Normal.Z, 4);

        Assert.True(q.TryFindFloor(TestGeometry.At(100, 100, 10), 20, out var floor));
        Assert.Equal(SurfaceKind.Terrain, floor.Kind);
        Assert.Equal(0f, floor.Point.Z, 5);
    }

    [Fact]
    public void Floor_OnTerrainSteeperThanFloorZ_IsNotFound()
    {
        // Terrain rising 30 m per 24 m cell along X (every vertex at 30 × its column): both triangles of every cell
        // lie in one plane with normal (−30, 0, 24) / √(30² + 24²), Z = 24 / 38.42 = 0.6247, below floor_z. At
        // x = 100 the ground is 30 × 100 / 24 = 125 m up: a ray down from 130 m meets it there, a floor query
        // finds nothing.
        var heights = new float[81];
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                heights[x * 9 + y] = 30f * x;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(new Terrain(TestGeometry.Landblock, heights));
        var q = new WorldQuery(world);
        var above = TestGeometry.At(100, 100, 130);

        Assert.True(q.RayCast(above, new Vector3(100, 100, 100), out var ground));
        Assert.Equal(SurfaceKind.Terrain, ground.Kind);
        Assert.Equal(125f, ground.Point.Z, 3);
        Assert.Equal(24f / MathF.Sqrt(30 * 30 + 24 * 24), ground.Normal.Z, 4);

        Assert.False(q.TryFindFloor(above, 30, out _), "a slope steeper than floor_z is no floor");
    }

    [Fact]
    public void SphereCast_AgainstAScaledBox_StopsItsRadiusFromTheScaledFace()
    {
        // A box of x, y −1..1, z 0..2 in its model, registered at (100, 100, 0) with scale 2: x, y 98..102, z 0..4.
        // A sphere of radius 0.5 cast from x = 94 to x = 100 at z = 1 touches the face x = 98 with its centre at
        // 97.5: fraction (97.5 − 94) / 6 = 0.58333, contact point (98, 100, 1), normal −X.
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(Crate, Part(BspShapes.Box(new Vector3(-1, -1, 0), new Vector3(1, 1, 2))), TestGeometry.At(100, 100, 0), 2f,
            PhysicsState.Static | PhysicsState.HasPhysicsBsp);
        var q = new WorldQuery(world);

        Assert.True(q.SphereCast(TestGeometry.At(94, 100, 1), new Vector3(100, 100, 1), 0.5f, out var hit));
        Assert.Equal(Crate, hit.ObjectId);
        Assert.Equal(3.5f / 6f, hit.Fraction, 4);
        AssertVec.Near(new Vector3(98, 100, 1), hit.Point, 1e-3f);
        AssertVec.Near(-Vector3.UnitX, hit.Normal, 1e-4f);
    }
}
