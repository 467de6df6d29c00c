using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>A world loaded from DAT files: landblocks whole or not at all, unloading, streaming, the shared cache.</summary>
public class DatWorldTests
{
    private const uint Post = 0x02000001;

    [Fact]
    public void ALandblock_BringsItsTerrainThroughTheHeightTable_AndItsObjects()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        using var files = dats.Open();
        var world = new DatWorld(files);
        var block = world.LoadLandblock(0x8040);
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                Assert.Equal(WorldWriter.TableHeight(WorldWriter.HeightIndex(0x8040, x, y)), block.Terrain.HeightAt(x, y));
        Assert.True(world.World.Cells.HasLandblock(0x8040));
        uint id = 0x7000_0000u | 0x8040u << 12;
        Assert.True(world.World.Objects.Contains(id));
        var position = world.World.Objects.PositionOf(id);
        Assert.Equal(Position.Outdoor(0x8040, new Vector3(96f, 100.9f, 0f)).CellId, position.CellId);
        Assert.Equal(new Vector3(96f, 100.9f, 0f), position.Frame.Origin);
        var setup = Assert.Single(block.Objects).Setup;
        Assert.Equal(0.6f, Assert.Single(setup.CylSpheres).Radius);
        Assert.Equal([0x8040u], world.Loaded);
    }

    [Fact]
    public void AnAbsentModel_FailsTheLoad_AndLeavesTheWorldAsItWas()
    {
        var info = WorldWriter.Info(0x8040, 0, (Post, new Vector3(10, 10, 0)), (0x02000099, new Vector3(20, 20, 0)));
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)], [WorldWriter.Land(0x8040, hasObjects: true), info]);
        using var files = dats.Open();
        var world = new DatWorld(files);
        var ex = Assert.Throws<DatReadException>(() => world.LoadLandblock(0x8040));
        Assert.Equal("client_portal.dat 0x02000099: is absent (expected a Setup).", ex.Message);
        Assert.False(world.World.Cells.HasLandblock(0x8040));
        Assert.Empty(world.World.Objects.Records);
        Assert.Empty(world.Loaded);
    }

    [Fact]
    public void AnAbsentEnvCell_FailsTheLoad_NamingIt()
    {
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)], [WorldWriter.Land(0x8040, hasObjects: true), WorldWriter.Info(0x8040, 2)]);
        using var files = dats.Open();
        var world = new DatWorld(files);
        var ex = Assert.Throws<DatObjectException>(() => world.LoadLandblock(0x8040));
        Assert.Equal("client_cell_1.dat: LandBlockInfo 0x8040FFFE: numCells: 2 cells (0x80400100 up), but client_cell_1.dat has no env cell 0x80400100.", ex.Message);
        Assert.False(world.World.Cells.HasLandblock(0x8040));
    }

    /// <summary>
    /// A landblock's env cells are 0x0100 to 0x0100 + numCells - 1, each present (retail's CLandBlockInfo::num_cells;
    /// ACE's Landblock.get_envcells): the cellar's second cell written as 0x0102 instead of 0x0101 (its portals
    /// following) leaves a gap, which is refused, naming the missing id, not read past; nothing is loaded.
    /// </summary>
    [Fact]
    public void EnvCells_AreNumberedFrom0x0100WithoutGaps_AGapIsRefusedNamingTheMissingCell()
    {
        var dat = Support.WorldDat.From(Scenes.SceneLibrary.Load("cellar").World);
        uint block = dat.Landblocks[0] << 16;
        Assert.Equal(2u, dat.Infos[0].NumCells);
        foreach (var cell in dat.EnvCells)
        {
            if (cell.Id == (block | 0x0101))
                cell.Id = block | 0x0102;
            foreach (var portal in cell.CellPortals)
                if (portal.OtherCellId == 0x0101)
                    portal.OtherCellId = 0x0102;
        }
        using var dats = Support.DatPath.Write(dat);
        using var files = dats.Open();
        var world = Support.DatPath.Loader(files, dat);

        var ex = Assert.Throws<DatObjectException>(() => world.LoadLandblock(dat.Landblocks[0]));

        Assert.Equal($"client_cell_1.dat: LandBlockInfo 0x{block | 0xFFFE:X8}: numCells: 2 cells (0x{block | 0x0100:X8} up), but client_cell_1.dat has no env cell 0x{block | 0x0101:X8}.", ex.Message);
        Assert.Equal("client_cell_1.dat", ex.File);
        Assert.Empty(world.World.Cells.CellIds);
        Assert.Empty(world.World.Objects.Records);
        Assert.Empty(world.Loaded);
    }

    [Fact]
    public void AnAbsentLandblock_OrRegion_IsNamed()
    {
        using var dats = new TempDats([WorldWriter.Post(Post)], [WorldWriter.Land(0x8040)]);
        using var files = dats.Open();
        var world = new DatWorld(files);
        Assert.Equal("client_cell_1.dat 0x8041FFFF: is absent (expected a LandBlock).", Assert.Throws<DatReadException>(() => world.LoadLandblock(0x8041)).Message);
        Assert.Equal("client_portal.dat 0x13000000: is absent (expected a Region).", Assert.Throws<DatReadException>(() => world.LoadLandblock(0x8040)).Message);
        Assert.Empty(world.World.Cells.CellIds);
    }

    [Fact]
    public void TheDescriber_GivesIds_AndADuplicateIsRefusedBeforeTheWorldIsTouched()
    {
        var info = WorldWriter.Info(0x8040, 0, (Post, new Vector3(10, 10, 0)), (Post, new Vector3(20, 20, 0)));
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)], [WorldWriter.Land(0x8040, hasObjects: true), info]);
        using var files = dats.Open();
        var seen = new List<(uint, int, uint, int)>();
        var world = new DatWorld(files, describe: (lb, i, owner, oi, p) =>
        {
            seen.Add((lb, i, owner, oi));
            return new DatObjectDescription(0x5000_0000u + (uint)i, 2f, PhysicsState.Static | PhysicsState.Ethereal, ShadowFlags.None);
        });
        world.LoadLandblock(0x8040);
        Assert.Equal([(0x8040u, 0, 0x8040FFFEu, 0), (0x8040u, 1, 0x8040FFFEu, 1)], seen);
        Assert.True(world.World.Objects.Contains(0x5000_0001));
        var same = new DatWorld(files, describe: (lb, i, owner, oi, p) => new DatObjectDescription(7, 1f, PhysicsState.Static, ShadowFlags.None));
        var ex = Assert.Throws<DatObjectException>(() => same.LoadLandblock(0x8040));
        Assert.Contains("client_cell_1.dat", ex.Message);
        Assert.Contains("0x8040FFFE", ex.Message);
        Assert.Contains("objects[1]: the describer gave id 0x00000007 twice", ex.Message);
        Assert.Empty(same.World.Cells.CellIds);
    }

    [Fact]
    public void AnObjectTheRegistryRefuses_TakesTheLandblockOutAgain()
    {
        // The second object's scale (the describer's) is refused when it is registered, after the cells and the
        // first object went in: all of them come out again, and a neighbour loaded before keeps its own.
        var info = WorldWriter.Info(0x8040, 0, (Post, new Vector3(10, 10, 0)), (Post, new Vector3(20, 20, 0)));
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)],
            [WorldWriter.Land(0x8040, hasObjects: true), info, WorldWriter.Land(0x8041, hasObjects: true), WorldWriter.Info(0x8041, 0, (Post, new Vector3(30, 30, 0)))]);
        using var files = dats.Open();
        var world = new DatWorld(files, describe: (lb, i, owner, oi, p) =>
            new DatObjectDescription(lb << 8 | (uint)i, lb == 0x8040 && i == 1 ? float.NaN : 1f, PhysicsState.Static, ShadowFlags.None));
        world.LoadLandblock(0x8041);
        var cells = world.World.Cells.CellIds.Order().ToList();
        var ex = Assert.Throws<ArgumentException>(() => world.LoadLandblock(0x8040));
        Assert.Contains("0x00804001", ex.Message);
        Assert.Equal(cells, world.World.Cells.CellIds.Order());
        Assert.Equal([0x804100u], world.World.Objects.Records.Select(r => r.Id));
        Assert.Equal([0x8041u], world.Loaded);
    }

    [Fact]
    public void Unloading_TakesOutTheCellsAndTheObjects()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        using var files = dats.Open();
        var world = new DatWorld(files);
        world.LoadLandblock(0x8040);
        world.UnloadLandblock(0x8040);
        Assert.False(world.World.Cells.HasLandblock(0x8040));
        Assert.Empty(world.World.Objects.Records);
        Assert.Empty(world.Loaded);
        Assert.Throws<ArgumentException>(() => world.UnloadLandblock(0x8040));
        world.LoadLandblock(0x8040);                                   // and back again
        Assert.True(world.World.Objects.Contains(0x7000_0000u | 0x8040u << 12));
    }

    [Fact]
    public void StreamAround_KeepsTheWindowAroundTheMover()
    {
        using var dats = WorldWriter.Grid(0x7F, 0x83, 0x3F, 0x41);
        using var files = dats.Open();
        var world = new DatWorld(files);
        Assert.Equal((9, 0), world.StreamAround(0x8040));
        Assert.Equal(Window(0x8040), world.Loaded.Order());
        // One landblock east: the west column goes, the east one comes.
        Assert.Equal((3, 3), world.StreamAround(0x8140));
        Assert.Equal(Window(0x8140), world.Loaded.Order());
        Assert.Equal(9, world.World.Objects.Records.Count());
        // At the grid's edge the landblocks the cell DAT lacks are skipped.
        Assert.Equal((2, 7), world.StreamAround(0x8341));
        Assert.Equal(new uint[] { 0x8240, 0x8241, 0x8340, 0x8341 }, world.Loaded.Order());
    }

    private static IEnumerable<uint> Window(uint centre)
    {
        var ids = new List<uint>();
        for (int dx = -1; dx <= 1; dx++)
            for (int dy = -1; dy <= 1; dy++)
                ids.Add((uint)(((int)(centre >> 8) + dx) << 8 | ((int)(centre & 0xFF) + dy)));
        return ids.Order();
    }

    [Fact]
    public void TwoWorlds_ShareTheConvertedSetups()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        using var files = dats.Open();
        var a = new DatWorld(files);
        var b = new DatWorld(files);
        var first = a.LoadLandblock(0x8040);
        var second = b.LoadLandblock(0x8040);
        Assert.Same(first.Objects[0].Setup, second.Objects[0].Setup);
        Assert.NotSame(a.World, b.World);
    }

    [Fact]
    public void AMoverWalksTheDatWorld_AsTheSameWorldBuiltInCode()
    {
        // The same two landblocks and posts, built directly: a run east across the border brushing a post must
        // give the same bits through either world.
        using var dats = WorldWriter.Grid(0x80, 0x81, 0x40, 0x40);
        using var files = dats.Open();
        var fromDat = new DatWorld(files);
        fromDat.LoadLandblock(0x8040);
        fromDat.LoadLandblock(0x8140);
        var direct = new PhysicsWorld();
        var post = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.6f, 4f)], Height = 4f, Radius = 0.6f };
        foreach (uint lb in new uint[] { 0x8040, 0x8140 })
        {
            var heights = new float[81];
            for (int x = 0; x < 9; x++)
                for (int y = 0; y < 9; y++)
                    heights[x * 9 + y] = WorldWriter.TableHeight(WorldWriter.HeightIndex(lb, x, y));
            direct.LoadLandblock(new Terrain(lb, heights));
            direct.Objects.Register(0x7000_0000u | lb << 12, post, Position.Outdoor(lb, new Vector3(96f, 100.9f, 0f)), 1f, PhysicsState.Static);
        }
        Assert.Equal(Walk(direct), Walk(fromDat.World));
    }

    private static List<string> Walk(PhysicsWorld world)
    {
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var state = engine.Place(player, Position.Outdoor(0x8040, new Vector3(60f, 100f, 17f))).Next;
        var body = BodyState.Creature();
        var trace = new List<string>();
        for (int frame = 0; frame < 30 * 20; frame++)
        {
            var step = engine.Step(player, state, body, 1.0 / 30, desiredVelocity: new Vector3(8f, 0f, 0f));
            state = step.Next;
            body = step.Body;
            var o = state.Position.Frame.Origin;
            trace.Add($"{state.Position.CellId:X8} {BitConverter.SingleToInt32Bits(o.X):X8} {BitConverter.SingleToInt32Bits(o.Y):X8} {BitConverter.SingleToInt32Bits(o.Z):X8} {state.Ground}");
        }
        Assert.True(trace.Exists(t => t.StartsWith("8140", StringComparison.Ordinal)), trace[^1]);
        return trace;
    }
}
