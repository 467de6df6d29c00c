using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// The Region's height table is a constant of the whole world: read once per opened files (as retail reads its
/// Region at start-up), kept when the converted-object cache is emptied, shared by every world and landblock; a
/// Region that cannot give one is refused on every load with the same message.
/// </summary>
public class RegionReadsTests
{
    private const uint A = 0x8040, B = 0x8041;

    [Fact]
    public void TheRegion_IsReadOnce_AcrossWorlds_Landblocks_AndAnEmptiedCache()
    {
        using var dats = new TempDats([WorldWriter.Region()], [WorldWriter.Land(A), WorldWriter.Land(B)]);
        using var files = dats.Open();
        var reads = new List<uint>();
        files.Portal.Unpacking = reads.Add;

        var first = new DatWorld(files);
        first.LoadLandblock(A);
        first.LoadLandblock(B);
        files.Converted.Clear();
        var second = new DatWorld(files).LoadLandblock(A);

        int count = reads.Count(id => id == DatWorld.RegionId);
        Assert.True(count == 1, $"the Region was read {count} times by three loads over two worlds and an emptied cache, expected once (reads: {string.Join(", ", reads.Select(id => $"0x{id:X8}"))})."); 
        // The kept table still gives the heights: vertex (x, y) of landblock A stands at its table entry.
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                Assert.Equal(WorldWriter.TableHeight(WorldWriter.HeightIndex(A, x, y)), second.Terrain.HeightAt(x, y));
    }

    [Fact]
    public void AnAbsentRegion_IsRefusedOnEveryLoad_NamingIt()
    {
        using var dats = new TempDats([WorldWriter.Post(0x02000001)], [WorldWriter.Land(A)]);
        using var files = dats.Open();
        var world = new DatWorld(files);
        var reads = new List<uint>();
        files.Portal.Unpacking = reads.Add;

        for (int attempt = 0; attempt < 2; attempt++)
        {
            var ex = Assert.Throws<DatReadException>(() => world.LoadLandblock(A));
            Assert.Equal("client_portal.dat 0x13000000: is absent (expected a Region).", ex.Message);
        }
        Assert.Empty(world.World.Cells.CellIds);
        Assert.Empty(world.Loaded);
    }
}
