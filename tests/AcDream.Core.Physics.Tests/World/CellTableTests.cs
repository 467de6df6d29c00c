using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

public class CellTableTests
{
    [Fact]
    public void LandAndIndoorCells_AreFoundByTheirIds_AndUnknownIdsAreNull()
    {
        var table = new CellTable<string>();
        table.Set(0xA9B40001, "land 1");
        table.Set(0xA9B40040, "land 64");
        table.Set(0xA9B40100, "indoor 0x100");
        table.Set(0xA9B50001, "land 1 of the block to the north");
        Assert.Equal("land 1", table.Get(0xA9B40001));
        Assert.Equal("land 64", table.Get(0xA9B40040));
        Assert.Equal("indoor 0x100", table.Get(0xA9B40100));
        Assert.Equal("land 1 of the block to the north", table.Get(0xA9B50001));
        Assert.Null(table.Get(0xA9B40002));
        Assert.Null(table.Get(0xA9B40101));
        Assert.Null(table.Get(0xA9B40000));
        Assert.Null(table.Get(0xA9B60001));
    }

    [Fact]
    public void ALandCell_IsFoundByItsGlobalCellCoordinates()
    {
        // Landblock 0xA9B4 starts at global cell (0xA9 * 8, 0xB4 * 8) = (1352, 1440); cell index 2 is x 0, y 1.
        var table = new CellTable<string>();
        table.Set(0xA9B40002, "x 0, y 1");
        Assert.Equal("x 0, y 1", table.GetLandAtGlobal(1352, 1441));
        Assert.Null(table.GetLandAtGlobal(1353, 1440));
        Assert.Null(table.GetLandAtGlobal(-1, 1441));
        Assert.Null(table.GetLandAtGlobal(1352, 2040));
    }
}
