using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// Water on land from the terrain types, each rule as the 2013 decompile has it (docs/water.md): the
/// terrain-type table, CalcCellWater/CalcWater, get_water_depth/calc_water_depth, and what
/// find_env_collisions and validate_walkable do with them.
/// </summary>
public class WaterTests
{
    private const uint Block = TestGeometry.Landblock;
    private const int N = Terrain.VerticesPerSide;

    /// <summary>A terrain word: road bits 0–1, terrain type bits 2–6, scenery bits 11–15.</summary>
    private static ushort Word(int type, int road = 0, int scenery = 0) => (ushort)(road | (type << 2) | (scenery << 11));

    /// <summary>Flat terrain at 0 whose vertex (x, y) is WaterDeepSea (0x14) where <paramref name="water"/> says, else Grassland (1).</summary>
    private static Terrain Lake(Func<int, int, bool> water, uint block = Block)
    {
        var words = new ushort[N * N];
        for (int x = 0; x < N; x++)
            for (int y = 0; y < N; y++)
                words[x * N + y] = Word(water(x, y) ? 0x14 : 0x01);
        return new Terrain(block, new float[N * N], words);
    }

    // TERRAIN_SURF_CHAR[32] as the client's data holds it (acclient_data.h): SOLID ×16, WATER ×5, SOLID ×11.
    private static readonly bool[] SurfCharIsWater =
    [
        false, false, false, false, false, false, false, false, false, false, false, false, false, false, false, false,
        true, true, true, true, true,
        false, false, false, false, false, false, false, false, false, false, false,
    ];

    [Fact]
    public void TheTerrainTypeTable_IsRetailsAndOnlyBits2To6Count()
    {
        for (int type = 0; type < 32; type++)
        {
            Assert.Equal(SurfCharIsWater[type], Terrain.IsWaterType(type));
            // Road and scenery bits set around the type change nothing (CalcCellWater reads (word >> 2) & 0x1F).
            var words = new ushort[N * N];
            Array.Fill(words, Word(type, road: 3, scenery: 31));
            var terrain = new Terrain(Block, new float[N * N], words);
            Assert.Equal(type, Terrain.TerrainTypeOf(terrain.TerrainWordAt(4, 4)));
            Assert.Equal(SurfCharIsWater[type] ? WaterType.EntirelyWater : WaterType.NotWater, terrain.WaterType);
        }
    }

    [Fact]
    public void DryTerrain_HasNoWater()
    {
        var terrain = Terrain.Flat(Block, 0f);
        Assert.Equal(WaterType.NotWater, terrain.WaterType);
        for (int x = 0; x < 8; x++)
            for (int y = 0; y < 8; y++)
                Assert.Equal(WaterType.NotWater, terrain.CellWaterType(x, y));
    }

    [Fact]
    public void OneWaterVertex_MakesItsFourCellsPartlyWater()
    {
        // CalcCellWater: a cell has water when any of its four corners is water.
        var terrain = Lake((x, y) => x == 2 && y == 3);
        for (int x = 0; x < 8; x++)
            for (int y = 0; y < 8; y++)
            {
                bool touches = x is 1 or 2 && y is 2 or 3;
                Assert.Equal(touches ? WaterType.PartiallyWater : WaterType.NotWater, terrain.CellWaterType(x, y));
            }
        Assert.Equal(WaterType.PartiallyWater, terrain.WaterType);
    }

    [Fact]
    public void FourWaterCorners_MakeACellEntirelyWater()
    {
        // Vertices x, y in 0..2 water: cells (0..1, 0..1) have four water corners, the ring around them some.
        var terrain = Lake((x, y) => x <= 2 && y <= 2);
        Assert.Equal(WaterType.EntirelyWater, terrain.CellWaterType(0, 0));
        Assert.Equal(WaterType.EntirelyWater, terrain.CellWaterType(1, 1));
        Assert.Equal(WaterType.PartiallyWater, terrain.CellWaterType(2, 0));
        Assert.Equal(WaterType.PartiallyWater, terrain.CellWaterType(0, 2));
        Assert.Equal(WaterType.PartiallyWater, terrain.CellWaterType(2, 2));
        Assert.Equal(WaterType.NotWater, terrain.CellWaterType(3, 3));
        Assert.Equal(WaterType.PartiallyWater, terrain.WaterType);
    }

    [Fact]
    public void ALandblockIsEntirelyWater_OnlyWhenAll81VerticesAre()
    {
        Assert.Equal(WaterType.EntirelyWater, Lake((_, _) => true).WaterType);
        // One dry vertex in a corner: its one cell is only partly water, so the landblock is too (CalcWater).
        var almost = Lake((x, y) => !(x == 8 && y == 8));
        Assert.Equal(WaterType.PartiallyWater, almost.WaterType);
        Assert.Equal(WaterType.PartiallyWater, almost.CellWaterType(7, 7));
        Assert.Equal(WaterType.EntirelyWater, almost.CellWaterType(6, 7));
    }

    [Fact]
    public void ALandCell_TakesItsWaterTypeFromTheTerrain()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Lake((x, y) => x <= 2 && y <= 2));
        Assert.Equal(WaterType.EntirelyWater, ((LandCell)world.Cells.Get((Block << 16) | 1)!).WaterType);    // cell (0, 0)
        Assert.Equal(WaterType.PartiallyWater, ((LandCell)world.Cells.Get((Block << 16) | 17)!).WaterType);  // cell (2, 0)
        Assert.Equal(WaterType.NotWater, ((LandCell)world.Cells.Get((Block << 16) | 28)!).WaterType);        // cell (3, 3)
    }

    // ---- get_water_depth / calc_water_depth ---------------------------------------------------------------
    // Cell (3, 4) spans x 72..96, y 96..120; its centre lines are x = 84, y = 108. Only its south-west
    // corner (vertex (3, 4)) is water, so the cell is partly water: calc_water_depth answers 0.45 for the
    // corner on the point's side when it is water, 0.1 when it is solid.

    private static LandCell PartlyWaterCell(Func<int, int, bool> water) =>
        new((Block << 16) | (3 * 8 + 4 + 1), Lake(water));

    [Fact]
    public void APartlyWaterCell_ReadsTheDepthAtTheCornerOnThePointsSide()
    {
        var cell = PartlyWaterCell((x, y) => x == 3 && y == 4);
        Assert.Equal(WaterType.PartiallyWater, cell.WaterType);
        Assert.Equal(0.45f, cell.WaterDepth(new Vector3(78, 102, 0)));   // south-west quarter: the water corner
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(90, 102, 0)));    // south-east: solid
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(78, 114, 0)));    // north-west: solid
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(90, 114, 0)));    // north-east: solid

        var northEast = PartlyWaterCell((x, y) => x == 4 && y == 5);
        Assert.Equal(0.45f, northEast.WaterDepth(new Vector3(90, 114, 0)));
        Assert.Equal(0.1f, northEast.WaterDepth(new Vector3(78, 102, 0)));
    }

    [Fact]
    public void OnACentreLine_TheWestAndSouthCornerIsRead_NotACEs()
    {
        // CLandBlock::get_terrain's kept comparison (acclient.c:352030), (2x + 1) * 12 >= X, indexes the corners
        // as calc_water_depth does: on the centre line the west (south) corner. ACE's X % 24 >= 12 would read
        // the east (north) one and answer 0.1 here.
        var cell = PartlyWaterCell((x, y) => x == 3 && y == 4);
        Assert.Equal(0.45f, cell.WaterDepth(new Vector3(84, 108, 0)));
        Assert.Equal(0.45f, cell.WaterDepth(new Vector3(84, 100, 0)));
        Assert.Equal(0.45f, cell.WaterDepth(new Vector3(80, 108, 0)));
        // Just past the lines: the solid corners.
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(84.001f, 100, 0)));
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(80, 108.001f, 0)));
    }

    [Fact]
    public void OnTheCellsEastEdge_TheEastCornerIsRead_NotACEs()
    {
        // X = 96 is the cell's east edge (the triangles hold it). Retail: 96 > 84, the east corner (solid, 0.1).
        // ACE's 96 % 24 = 0 reads the west corner (water, 0.45).
        var cell = PartlyWaterCell((x, y) => x == 3 && y == 4);
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(96, 100, 0)));
        Assert.Equal(0.1f, cell.WaterDepth(new Vector3(78, 120, 0)));
    }

    [Fact]
    public void DryAndEntirelyWaterCells_HaveFixedDepths()
    {
        Assert.Equal(0f, PartlyWaterCell((_, _) => false).WaterDepth(new Vector3(78, 102, 0)));
        // get_water_depth: ENTIRELY_WATER answers 0.89999998 (the float 0.9) wherever the point is.
        var deep = PartlyWaterCell((x, y) => x is 3 or 4 && y is 4 or 5);
        Assert.Equal(WaterType.EntirelyWater, deep.WaterType);
        Assert.Equal(0.9f, deep.WaterDepth(new Vector3(78, 102, 0)));
        Assert.Equal(0.9f, deep.WaterDepth(new Vector3(95, 119, 0)));
    }

    // ---- the transition ------------------------------------------------------------------------------------
    // A one-sphere walker (r 0.5, centre 0.5 above its origin, step-down 0.8) on flat terrain at z 0.

    private static MoverDescription Walker(PhysicsState state = PhysicsState.Gravity, ObjectInfoState info = ObjectInfoState.IsPlayer) =>
        new(0x5000_0009, [new Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f, state, info);

    private static PhysicsWorld World(params Terrain[] terrains)
    {
        var world = new PhysicsWorld();
        foreach (var terrain in terrains)
            world.Cells.AddLandblock(terrain);
        return world;
    }

    [Fact]
    public void AMoverStandingInWater_SinksTheDepthAndItsContactPlaneIsWater()
    {
        // Cells (0..1, 0..1) entirely water (depth 0.9), the ring around them partly. validate_walkable adds
        // the depth to the sphere's height over the plane (acclient.c:314222): a sphere resting 0.9 below the
        // terrain touches it, and set_contact_plane gets is_water = the cell is not NOT_WATER (acclient.c:355043).
        var world = World(Lake((x, y) => x <= 2 && y <= 2));
        var mover = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(30, 30, -0.9f), -0.9f));
        mover.Step(new Vector3(0.1f, 0, 0));
        Assert.Equal(-0.9f, mover.Origin.Z, 1e-5f);
        Assert.True(mover.State.Contact && mover.State.OnWalkable);
        Assert.True(mover.State.ContactPlaneIsWater);
    }

    [Fact]
    public void InAPartlyWaterCell_TheSolidSideIsShallowButStillWater()
    {
        // Cell (2, 0) spans x 48..72: its west corners (vertices (2, 0), (2, 1)) are water, its east ones dry.
        // West of x = 60 the sphere rests 0.45 down; east of it 0.1 down, and the contact plane is still water.
        var world = World(Lake((x, y) => x <= 2 && y <= 2));
        var west = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(55, 10, -0.45f), -0.45f));
        west.Step(new Vector3(0, 0.1f, 0));
        Assert.Equal(-0.45f, west.Origin.Z, 1e-5f);
        Assert.True(west.State.ContactPlaneIsWater);

        var east = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(65, 10, -0.1f), -0.1f));
        east.Step(new Vector3(0, 0.1f, 0));
        Assert.Equal(-0.1f, east.Origin.Z, 1e-5f);
        Assert.True(east.State.ContactPlaneIsWater);
    }

    [Fact]
    public void OnDryLand_TheContactPlaneIsNotWater()
    {
        var world = World(Lake((x, y) => x <= 2 && y <= 2));
        var mover = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(150, 150, 0), 0f));
        mover.Step(new Vector3(0.1f, 0, 0));
        Assert.Equal(0f, mover.Origin.Z, 1e-5f);
        Assert.True(mover.State.Contact);
        Assert.False(mover.State.ContactPlaneIsWater);
    }

    [Fact]
    public void WalkingOutOfWater_TheShallowerGroundPushesTheSphereUp()
    {
        // Out of the entirely-water cell (1, 0) (0.9 down) into cell (2, 0), x 48..72, whose west corners are
        // water (0.45 down): the sphere is 0.45 below where it rests there, and validate_walkable pushes it up
        // by that much (its Adjusted arm), no step-up needed. Then out of (2, 0)'s dry side (0.1 down) into the
        // dry cell (3, 0): up 0.1 to the terrain.
        var world = World(Lake((x, y) => x <= 2 && y <= 2));
        var deep = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(47.9f, 10, -0.9f), -0.9f));
        deep.Step(new Vector3(0.2f, 0, 0));
        Assert.Equal(48.1f, deep.Origin.X, 1e-4f);
        Assert.Equal(-0.45f, deep.Origin.Z, 1e-5f);
        Assert.True(deep.State.ContactPlaneIsWater);

        var shallow = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(71.9f, 10, -0.1f), -0.1f));
        shallow.Step(new Vector3(0.2f, 0, 0));
        Assert.Equal(72.1f, shallow.Origin.X, 1e-4f);
        Assert.Equal(0f, shallow.Origin.Z, 1e-5f);
        Assert.False(shallow.State.ContactPlaneIsWater);
    }

    [Fact]
    public void AnEntirelyWaterLandblock_StopsAPlayer_ButNotAMissile()
    {
        // find_env_collisions (acclient.c:355030): over a cell of an all-water landblock, COLLIDED for every
        // mover but the camera (IS_VIEWER) and a missile (MISSILE); the missile flies on into the landblock. The dry landblock 0xA9B4 meets the
        // all-water 0xAAB4 at x = 192.
        var world = World(Terrain.Flat(Block, 0f), Lake((_, _) => true, 0xAAB4));
        var start = MoverState.OnFloor(TestGeometry.At(191.8f, 50, 0), 0f);

        var player = new Mover(world, Walker(), start);
        player.Step(new Vector3(0.4f, 0, 0));
        Assert.True(player.Origin.X < 192f, $"the player entered the all-water landblock: x = {player.Origin.X}");
        Assert.Equal(Block, player.State.Position.CellId >> 16);

        var missile = new Mover(world, Walker(PhysicsState.Missile), start);
        missile.Step(new Vector3(0.4f, 0, 0));
        Assert.Equal(0xAAB4u, missile.State.Position.CellId >> 16);
    }
}
