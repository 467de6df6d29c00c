using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Dat.Tests.Support;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// The LandBlock's HasObjects flag decides whether its LandBlockInfo is read, as retail's lbi_exists does
/// (CLandBlock::UnPack reads it, acclient.c 351520; CLandBlock::InitLoad, 352062, fetches 0xXXYYFFFE only when it
/// is set and fails the landblock when that is absent; with it clear, init_buildings and init_static_objs find no
/// LandBlockInfo). The expected contents come from the written DAT objects, not from the loader.
/// </summary>
public class LandBlockInfoFlagTests
{
    private const uint Post = 0x02000001;

    [Fact]
    public void FlagSet_TheLandBlockInfoIsRead_ItsCellsBuildingsAndObjectsLoaded()
    {
        var dat = WorldDat.From(SceneLibrary.Load("cottage").World);
        var info = Assert.Single(dat.Infos);
        Assert.True(Assert.Single(dat.LandBlocks).HasObjects);          // the writer sets it beside its LandBlockInfo
        int cellObjects = dat.EnvCells.Sum(c => c.StaticObjects.Count);
        Assert.True(info.NumCells > 0 && info.Buildings.Count > 0 && info.Objects.Count + cellObjects > 0);
        using var dats = DatPath.Write(dat);
        using var files = dats.Open();
        var world = DatPath.Loader(files, dat);

        var block = world.LoadLandblock(dat.Landblocks[0]);

        Assert.Equal((int)info.NumCells, block.EnvCells.Count);
        Assert.Equal(info.Buildings.Count, block.Buildings.Count);
        Assert.Equal(info.Objects.Count + cellObjects, block.Objects.Count);
        Assert.Equal(64 + (int)info.NumCells, world.World.Cells.CellIds.Count());
    }

    [Fact]
    public void FlagSet_WithoutTheLandBlockInfo_IsRefusedNamingIt_AndTheWorldIsUnchanged()
    {
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)],
            [WorldWriter.Land(0x8041, hasObjects: true), WorldWriter.Info(0x8041, 0, (Post, new Vector3(30, 30, 0))), WorldWriter.Land(0x8040, hasObjects: true)]);
        using var files = dats.Open();
        var world = new DatWorld(files);
        world.LoadLandblock(0x8041);
        var cells = world.World.Cells.CellIds.Order().ToList();
        var objects = world.World.Objects.Records.Select(r => r.Id).ToList();

        var ex = Assert.Throws<DatObjectException>(() => world.LoadLandblock(0x8040));

        Assert.Equal("client_cell_1.dat: LandBlock 0x8040FFFF: hasObjects: set (the landblock has a LandBlockInfo), but client_cell_1.dat has no LandBlockInfo 0x8040FFFE.", ex.Message);
        Assert.Equal(cells, world.World.Cells.CellIds.Order());
        Assert.Equal(objects, world.World.Objects.Records.Select(r => r.Id));
        Assert.Equal([0x8041u], world.Loaded);
        Assert.False(world.World.Cells.HasLandblock(0x8040));
    }

    [Fact]
    public void FlagClear_ALandBlockInfoInTheFile_IsNotRead_TheLandblockIsItsTerrainAlone()
    {
        // The cottage written as retail would, then the flag cleared: its env cells, building and objects are all
        // in the file, and none is loaded (retail's lbi stays null, so init_buildings and init_static_objs add
        // nothing and no cell count is known).
        var dat = WorldDat.From(SceneLibrary.Load("cottage").World);
        dat.LandBlocks[0].HasObjects = false;
        using var dats = DatPath.Write(dat);
        using var files = dats.Open();
        var world = DatPath.Loader(files, dat);

        var block = world.LoadLandblock(dat.Landblocks[0]);

        Assert.Empty(block.EnvCells);
        Assert.Empty(block.Buildings);
        Assert.Empty(block.Objects);
        Assert.Equal(64, world.World.Cells.CellIds.Count());
        Assert.Empty(world.World.Objects.Records);

        // Not even looked at: a LandBlockInfo counting cells the file lacks, which a set flag refuses.
        using var odd = new TempDats([WorldWriter.Region(), WorldWriter.Post(Post)],
            [WorldWriter.Land(0x8040), WorldWriter.Info(0x8040, 2, (Post, new Vector3(10, 10, 0)))]);
        using var oddFiles = odd.Open();
        var plain = new DatWorld(oddFiles).LoadLandblock(0x8040);
        Assert.Empty(plain.EnvCells);
        Assert.Empty(plain.Objects);
    }
}
