using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

public class TerrainTests
{
    /// <summary>The terrain diagonal as written in another public client (ACViewer's form of the same hash).</summary>
    private static bool ReferenceSwToNe(uint gx, uint gy) =>
        (unchecked(gx * gy * 0x0CCAC033u - gx * 0x421BE3BDu + gy * 0x6C1AC587u - 0x519B8F25u) & 0x80000000u) != 0;

    [Fact]
    public void Diagonal_MatchesTheIndependentFormOfTheRetailHash()
    {
        foreach (uint block in new uint[] { 0xA9B4, 0x0000, 0xFEFE, 0x7D64 })
        {
            var terrain = Terrain.Flat(block, 0);
            for (int x = 0; x < 8; x++)
                for (int y = 0; y < 8; y++)
                    Assert.Equal(ReferenceSwToNe((block >> 8) * 8 + (uint)x, (block & 0xFF) * 8 + (uint)y), terrain.IsSouthWestToNorthEastCut(x, y));
        }
    }

    [Fact]
    public void Diagonal_UsesBothCuts_AcrossALandblock()
    {
        var terrain = Terrain.Flat(0xA9B4, 0);
        int cuts = 0;
        for (int x = 0; x < 8; x++)
            for (int y = 0; y < 8; y++)
                cuts += terrain.IsSouthWestToNorthEastCut(x, y) ? 1 : 0;
        Assert.InRange(cuts, 1, 63);
    }

    [Fact]
    public void Triangles_FaceUp_AndFollowTheChosenDiagonal()
    {
        // Raise only the NE corner of cell (0,0): the cell's height at its centre depends on the cut.
        var h = new float[81];
        h[1 * 9 + 1] = 4f;
        var terrain = new Terrain(0xA9B4, h);
        var cell = new LandCell(0xA9B40001, terrain);
        var centre = new Vector3(12, 12, 0);
        var tri = cell.FindTerrainPolygon(centre)!;
        Assert.True(tri.Plane.Normal.Z > 0);
        float z = -(tri.Plane.D + tri.Plane.Normal.X * 12 + tri.Plane.Normal.Y * 12) / tri.Plane.Normal.Z;
        float expected = terrain.IsSouthWestToNorthEastCut(0, 0) ? 2f : 0f; // on the SW-NE diagonal the centre is halfway up
        Assert.Equal(expected, z, 4);
    }

    [Fact]
    public void FindTerrainPolygon_OutsideTheCell_IsNull()
    {
        var cell = new LandCell(0xA9B40001, Terrain.Flat(0xA9B4, 0));
        Assert.NotNull(cell.FindTerrainPolygon(new Vector3(0.01f, 23.99f, 0)));
        Assert.Null(cell.FindTerrainPolygon(new Vector3(24.5f, 3, 0)));
    }

    [Fact]
    public void Terrain_BadHeights_NameTheValue()
    {
        var h = new float[81];
        h[40] = float.PositiveInfinity;
        var ex = Assert.Throws<ArgumentException>(() => new Terrain(0xA9B4, h));
        Assert.Contains("heights[40]", ex.Message);
        Assert.Throws<ArgumentException>(() => new Terrain(0xA9B4, new float[80]));
    }
}
