using System.Threading.Tasks;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// World queries against hand-computed answers on the built-in scenes. Door: flat ground at z = 0, the
/// slab spans x 99.5..100.5, y 99.991..100.252, z 0..2.2 (front face y = 99.991), its foot cylinder
/// (radius 0.5 around (100, 100.12), 0.2 m tall) reaches y = 99.62. Cottage: the room spans
/// x 98..102, y 100..104, z 0..3. Cellar: the same room with a stairwell (x 100.5..102, y 101..104) down
/// to treads of 0.2 m per 0.3 m and a cellar floor at z = -1.2 from y = 102.5.
/// </summary>
public class WorldQueryTests
{
    private const uint Land = 0xA9B40025, Room = 0xA9B40100, Cellar = 0xA9B40101;
    private const uint Door = 0x7000_0001, Trunk = 0x7000_0002, Boulder = 0x7000_0003;
    private const float DoorFront = 99.991f;

    private static WorldQuery Query(string scene) => new(SceneLibrary.Load(scene).World);
    private static Position At(uint cell, float x, float y, float z) => new(cell, new Vector3(x, y, z));

    [Fact]
    public void SphereCast_StopsAtTheDoorsFrontFace()
    {
        var q = Query("door");
        Assert.True(q.SphereCast(At(Land, 100, 98, 1), new Vector3(100, 102, 1), 0.3f, out var hit));
        Assert.Equal(SurfaceKind.Object, hit.Kind);
        Assert.Equal(Door, hit.ObjectId);
        Assert.Equal(Land, hit.CellId);
        Assert.Equal((DoorFront - 0.3f - 98f) / 4f, hit.Fraction, 5);
        AssertVec.Near(new Vector3(0, -1, 0), hit.Normal);
        AssertVec.Near(new Vector3(100, DoorFront - 0.3f, 1), hit.Center, 1e-4f);
        AssertVec.Near(new Vector3(100, DoorFront, 1), hit.Point, 1e-4f);
    }

    [Fact]
    public void RayCast_AtFootHeight_HitsTheSlabNotTheFootCylinder_BecauseTheDoorCollidesByItsBspOnly()
    {
        var q = Query("door");
        // The foot cylinder's face is at y = 99.62; a HasPhysicsBsp object is never collided through it.
        Assert.True(q.RayCast(At(Land, 100, 98, 0.1f), new Vector3(100, 102, 0.1f), out var hit));
        Assert.Equal(Door, hit.ObjectId);
        Assert.Equal((DoorFront - 98f) / 4f, hit.Fraction, 5);
    }

    [Fact]
    public void RayCast_HitsACylinderOnlyObjectByItsCylinder_AndASphereOnlyObjectByItsSphere()
    {
        Assert.True(Query("trunk").RayCast(At(Land, 100, 98, 1), new Vector3(100, 102, 1), out var trunk));
        Assert.Equal(Trunk, trunk.ObjectId);
        Assert.Equal(1.4f / 4f, trunk.Fraction, 5);
        AssertVec.Near(new Vector3(0, -1, 0), trunk.Normal, 1e-4f);

        Assert.True(Query("boulder").RayCast(At(Land, 100, 97, 0.6f), new Vector3(100, 103, 0.6f), out var boulder));
        Assert.Equal(Boulder, boulder.ObjectId);
        Assert.Equal(2f / 6f, boulder.Fraction, 5);
    }

    [Fact]
    public void Casts_ThatMissEverything_ReturnFalse()
    {
        var q = Query("door");
        Assert.False(q.RayCast(At(Land, 90, 98, 1), new Vector3(90, 102, 1), out var hit));
        Assert.Equal(SurfaceKind.None, hit.Kind);
        Assert.False(q.SphereCast(At(Land, 98, 98, 1), new Vector3(98, 102, 1), 0.3f, out _));
        // Environment only: the door is not there.
        Assert.False(q.SphereCast(At(Land, 100, 98, 1), new Vector3(100, 102, 1), 0.3f, out _, QueryLayers.Environment));
        // The door itself ignored.
        Assert.False(q.SphereCast(At(Land, 100, 98, 1), new Vector3(100, 102, 1), 0.3f, out _, ignoreObjectId: Door));
    }

    [Fact]
    public void Casts_StartingInsideTheSlab_PassOutOfIt()
    {
        var q = Query("door");
        Assert.False(q.RayCast(At(Land, 100, 100.1f, 1), new Vector3(100, 102, 1), out _));
        Assert.False(q.SphereCast(At(Land, 100, 100.1f, 1), new Vector3(100, 98, 1), 0.3f, out _));
    }

    [Fact]
    public void SphereCast_StartingAgainstTheFrontFace_AndMovingIn_HitsAtFractionZero_ButMovingAwayIsFree()
    {
        var q = Query("door");
        Assert.True(q.SphereCast(At(Land, 100, DoorFront - 0.3f, 1), new Vector3(100, 101, 1), 0.3f, out var hit));
        Assert.Equal(0f, hit.Fraction);
        Assert.Equal(Door, hit.ObjectId);
        Assert.False(q.SphereCast(At(Land, 100, DoorFront - 0.3f, 1), new Vector3(100, 97, 1), 0.3f, out _));
    }

    [Fact]
    public void SphereCast_DownOntoTheGround_HitsTheTerrainOfTheLandCellUnderIt()
    {
        var q = Query("door");
        Assert.True(q.SphereCast(At(Land, 90, 90, 2), new Vector3(90, 90, -2), 0.5f, out var hit));
        Assert.Equal(SurfaceKind.Terrain, hit.Kind);
        Assert.Equal(0xA9B4001Cu, hit.CellId);      // x 90 → column 3, y 90 → row 3: 3 × 8 + 3 + 1 = 28
        Assert.Equal(1.5f / 4f, hit.Fraction, 5);
        AssertVec.Near(new Vector3(90, 90, 0), hit.Point, 1e-4f);
        AssertVec.Near(Vector3.UnitZ, hit.Normal, 1e-5f);
    }

    [Fact]
    public void Floor_OutsideIsTheTerrain_OnTheDoorIsItsTop_AndTooShortADropFindsNothing()
    {
        var q = Query("door");
        Assert.True(q.TryFindFloor(At(Land, 100, 98, 5), 10, out var ground));
        Assert.Equal(SurfaceKind.Terrain, ground.Kind);
        Assert.Equal(0f, ground.Point.Z, 5);
        Assert.Equal(Land, ground.CellId);
        AssertVec.Near(Vector3.UnitZ, ground.Normal, 1e-5f);

        Assert.True(q.TryFindFloor(At(Land, 100, 100.1f, 5), 10, out var top));
        Assert.Equal(Door, top.ObjectId);
        Assert.Equal(2.2f, top.Point.Z, 4);

        Assert.False(q.TryFindFloor(At(Land, 100, 98, 5), 4.9f, out _));
        Assert.True(q.TryFindFloor(At(Land, 100, 98, 0), 1, out var onIt));
        Assert.Equal(0f, onIt.Fraction);
    }

    [Fact]
    public void Floor_OnObjectsWithoutBsp_IsTheTopOfTheirCylinderOrSphere()
    {
        Assert.True(Query("trunk").TryFindFloor(At(Land, 100, 100, 10), 10, out var trunk));
        Assert.Equal(Trunk, trunk.ObjectId);
        Assert.Equal(4f, trunk.Point.Z, 4);
        Assert.True(Query("boulder").TryFindFloor(At(Land, 100, 100, 5), 10, out var boulder));
        Assert.Equal(Boulder, boulder.ObjectId);
        Assert.Equal(1.6f, boulder.Point.Z, 4);
    }

    [Fact]
    public void Floor_InTheCottage_IsTheRoomsFloor_NotTheTerrainBeneathIt()
    {
        var q = Query("cottage");
        Assert.True(q.TryFindFloor(At(Land, 100, 102, 2), 5, out var floor));
        Assert.Equal(SurfaceKind.EnvCell, floor.Kind);
        Assert.Equal(Room, floor.CellId);
        Assert.Equal(0f, floor.Point.Z, 5);
        // Above the roof (3.2 m), the roof is the floor: the building's shell.
        Assert.True(q.TryFindFloor(At(Land, 100, 102, 5), 5, out var roof));
        Assert.Equal(SurfaceKind.Building, roof.Kind);
        Assert.Equal(3.2f, roof.Point.Z, 4);
    }

    [Theory]
    [InlineData(101.15f, -0.2f)]   // first tread, y 101..101.3
    [InlineData(101.75f, -0.6f)]   // third tread, y 101.6..101.9
    [InlineData(103f, -1.2f)]      // the cellar floor
    public void Floor_DownTheStairwell_IsTheTreadOrTheCellarFloor(float y, float expected)
    {
        var q = Query("cellar");
        Assert.True(q.TryFindFloor(At(Room, 101.25f, y, 1), 5, out var floor));
        Assert.Equal(SurfaceKind.EnvCell, floor.Kind);
        Assert.Equal(Cellar, floor.CellId);
        Assert.Equal(expected, floor.Point.Z, 4);
    }

    [Fact]
    public void Cell_IsTheRoomIndoors_TheLandCellOutside_AndTheCellarDownTheStairs()
    {
        var cottage = Query("cottage");
        Assert.True(cottage.TryFindCell(At(Land, 100, 102, 1), out var inside));
        Assert.Equal(Room, inside.CellId);
        AssertVec.Near(new Vector3(100, 102, 1), inside.Origin);
        Assert.True(cottage.TryFindCell(At(Land, 100, 98, 1), out var outside));
        Assert.Equal(Land, outside.CellId);
        Assert.True(cottage.TryFindCell(At(Room, 100, 98, 1), out var outFromRoom));
        Assert.Equal(Land, outFromRoom.CellId);

        var cellar = Query("cellar");
        Assert.True(cellar.TryFindCell(At(Room, 101.25f, 103, -0.5f), out var down));
        Assert.Equal(Cellar, down.CellId);
    }

    [Fact]
    public void Cell_InANeighbouringLandblock_IsFoundInItsOwnFrame_AndAPointOutsideEveryLoadedCellIsNone()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        world.Cells.AddLandblock(Terrain.Flat(0xAAB4, 0f));   // the block to the east
        var q = new WorldQuery(world);
        Assert.True(q.TryFindCell(At(0xA9B40001, 200, 5, 0), out var east));
        Assert.Equal(0xAAB40001u, east.CellId);                     // x 200 - 192 = 8: column 0, row 0
        AssertVec.Near(new Vector3(8, 5, 0), east.Origin);
        Assert.False(q.TryFindCell(At(0xA9B40001, -5, 5, 0), out _));  // the block to the west is not loaded
        Assert.False(q.TryFindCell(At(0xA9B40001, 5, 200, 0), out _));
    }

    [Fact]
    public void OverlapSphere_FindsTheDoorByItsSlab_NotByItsFootCylinder()
    {
        var q = Query("door");
        Span<ObjectOverlap> found = stackalloc ObjectOverlap[4];
        Assert.Equal(1, q.OverlapSphere(At(Land, 100, 99.7f, 1), 0.3f, found));
        Assert.Equal(Door, found[0].ObjectId);
        Assert.Equal(ShadowShapeKind.Bsp, found[0].Kind);
        // Inside the foot cylinder's reach but 0.39 m from the slab: not overlapping (BSP-only dispatch).
        Assert.Equal(0, q.OverlapSphere(At(Land, 100, 99.6f, 0.1f), 0.3f, found));
        // Wholly inside the slab counts (retail's centre-in-solid test).
        Assert.Equal(1, q.OverlapSphere(At(Land, 100, 100.1f, 1), 0.05f, found));
        Assert.Equal(0, q.OverlapSphere(At(Land, 90, 90, 1), 2f, found));
        Assert.Equal(0, q.OverlapSphere(At(Land, 100, 100, 1), 2f, Span<ObjectOverlap>.Empty));
    }

    [Fact]
    public void OverlapSphere_ReportsEachObjectOnce_AndSkipsEtherealObjectsWhenAsked()
    {
        var trunk = Query("trunk");
        Span<ObjectOverlap> found = stackalloc ObjectOverlap[4];
        Assert.Equal(1, trunk.OverlapSphere(At(Land, 100.9f, 100, 1), 0.31f, found));
        Assert.Equal(ShadowShapeKind.Cylinder, found[0].Kind);
        Assert.Equal(0, trunk.OverlapSphere(At(Land, 100.9f, 100, 1), 0.29f, found));

        var world = SceneLibrary.Load("trunk").World;
        world.Objects.Register(0x7000_0009, new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 1f)] },
            At(Land, 103, 100, 1), 1f, PhysicsState.Ethereal);
        var q = new WorldQuery(world);
        Assert.Equal(2, q.OverlapSphere(At(Land, 101.5f, 100, 1), 1f, found));
        Assert.Equal(1, q.OverlapSphere(At(Land, 101.5f, 100, 1), 1f, found, QueryLayers.Objects));
        Assert.Equal(Trunk, found[0].ObjectId);
    }

    [Fact]
    public void OverlapBox_FindsTheCylinderExactly_AndNothingFarAway()
    {
        var q = Query("trunk");
        Span<ObjectOverlap> found = stackalloc ObjectOverlap[4];
        // The box's west face at x 100.55 is inside the 0.6 m radius; at 100.65 it is not.
        Assert.Equal(1, q.OverlapBox(At(Land, 101.05f, 100, 1), new Vector3(0.5f), found));
        Assert.Equal(0, q.OverlapBox(At(Land, 101.15f, 100, 1), new Vector3(0.5f), found));
        // Above the trunk's top (4 m): nothing.
        Assert.Equal(0, q.OverlapBox(At(Land, 100, 100, 5), new Vector3(0.5f), found));
    }

    [Fact]
    public void BadInput_ThrowsNamingTheField()
    {
        var q = Query("door");
        Assert.Contains("from.origin", Assert.Throws<ArgumentException>(() => q.RayCast(At(Land, float.NaN, 0, 0), Vector3.One, out _)).Message);
        Assert.Contains("to", Assert.Throws<ArgumentException>(() => q.RayCast(At(Land, 1, 1, 1), new Vector3(float.PositiveInfinity, 0, 0), out _)).Message);
        Assert.Contains("radius", Assert.Throws<ArgumentException>(() => q.SphereCast(At(Land, 1, 1, 1), Vector3.One, -1f, out _)).Message);
        Assert.Contains("point.cell", Assert.Throws<ArgumentException>(() => q.TryFindCell(At(0x12340001, 1, 1, 1), out _)).Message);
        Assert.Contains("maxDrop", Assert.Throws<ArgumentException>(() => q.TryFindFloor(At(Land, 1, 1, 1), float.NaN, out _)).Message);
        Assert.Contains("halfExtents.Y", Assert.Throws<ArgumentException>(() => q.OverlapBox(At(Land, 1, 1, 1), new Vector3(1, -1, 1), Span<ObjectOverlap>.Empty)).Message);
    }

    [Fact]
    public void EveryQuery_AllocatesNothingOnceWarm()
    {
        var q = Query("cottage");
        var buffer = new ObjectOverlap[8];
        void All()
        {
            q.SphereCast(At(Land, 100, 97, 1), new Vector3(100, 103, 1), 0.3f, out _);
            q.RayCast(At(Land, 97, 97, 1), new Vector3(103, 103, 1), out _);
            q.TryFindFloor(At(Land, 100, 102, 2), 5, out _);
            q.TryFindCell(At(Land, 100, 102, 1), out _);
            q.OverlapSphere(At(Land, 100, 99.8f, 1), 1f, buffer);
            q.OverlapBox(At(Land, 100, 99.8f, 1), new Vector3(1), buffer);
            q.CameraArm(At(Room, 100, 101, 1.5f), new Vector3(100, 106, 1.5f));
        }
        void TenTimes()
        {
            for (int i = 0; i < 10; i++)
                All();
        }
        Assert.Equal(0, Allocations.PerRound(All, TenTimes));
    }

    [Fact]
    public void QueriesOnASharedWorld_FromEightThreads_MatchTheSequentialAnswers()
    {
        var world = SceneLibrary.Load("cottage").World;
        static float[] Sweep(WorldQuery q)
        {
            var answers = new float[64];
            for (int i = 0; i < answers.Length; i++)
            {
                float x = 97f + i * 0.1f;
                answers[i] = q.SphereCast(new Position(Land, new Vector3(x, 97, 1)), new Vector3(x, 106, 1), 0.3f, out var hit) ? hit.Fraction : -1f;
            }
            return answers;
        }
        var expected = Sweep(new WorldQuery(world));
        Assert.Contains(expected, f => f > 0f && f < 1f);
        var results = new float[8][];
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 8 }, t => results[t] = Sweep(new WorldQuery(world)));
        foreach (var r in results)
            Assert.Equal(expected, r);
    }
}
