namespace AcDream.Core.Physics.Tests.Geometry;

public class LandDefsTests
{
    [Fact]
    public void BlockOffset_IsZeroWithinALandblock()
        => Assert.Equal(Vector3.Zero, LandDefs.BlockOffset(0xA9B40001, 0xA9B40105));

    [Fact]
    public void BlockOffset_IsOneBlockLengthPerLandblockStep()
    {
        // Landblock x is the high byte, y the low byte of the landblock id.
        Assert.Equal(new Vector3(192, 0, 0), LandDefs.BlockOffset(0xA9B40001, 0xAAB40001));
        Assert.Equal(new Vector3(0, -192, 0), LandDefs.BlockOffset(0xA9B40001, 0xA9B30001));
    }

    [Theory]
    [InlineData(0, 0, 0x00000001u)]
    [InlineData(0xA9 * 8 + 3, 0xB4 * 8 + 5, 0xA9B4001Eu)]   // cell (3,5): 3 * 8 + 5 + 1 = 30
    [InlineData(2039, 2039, 0xFEFE0040u)]
    [InlineData(-1, 0, 0u)]
    [InlineData(2040, 0, 0u)]
    public void LandCellAtGlobal_PacksLandblockAndCell(int gx, int gy, uint expected)
        => Assert.Equal(expected, LandDefs.LandCellAtGlobal(gx, gy));

    [Fact]
    public void LandCellAt_NumbersCellsColumnMajorFromOne()
    {
        Assert.Equal(0xA9B40001u, LandDefs.LandCellAt(0xA9B4, new Vector3(1, 1, 0)));
        Assert.Equal(0xA9B40002u, LandDefs.LandCellAt(0xA9B4, new Vector3(1, 25, 0)));
        Assert.Equal(0xA9B40009u, LandDefs.LandCellAt(0xA9B4, new Vector3(25, 1, 0)));
        Assert.Equal(0xA9B40040u, LandDefs.LandCellAt(0xA9B4, new Vector3(191.9f, 191.9f, 0)));
        Assert.Equal(0u, LandDefs.LandCellAt(0xA9B4, new Vector3(192f, 1, 0)));
    }
}
