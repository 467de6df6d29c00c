using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The terrain of one landblock: a 9×9 grid of heights (metres) at the corners of its 8×8 land cells,
/// each cell cut into two triangles along the diagonal retail picks from the cell's global coordinates.
/// </summary>
public sealed class Terrain
{
    /// <summary>Vertices per side of a landblock's height grid.</summary>
    public const int VerticesPerSide = 9;

    private readonly float[] _heights;

    /// <summary>
    /// Creates terrain from 81 heights, indexed [x * 9 + y] (x east, y north), in metres (finite, within
    /// ±<see cref="InputLimits.MaxCoordinate"/>), for a landblock inside the retail world
    /// (<see cref="LandDefs.IsValidLandblock"/>: x and y bytes 0x00..0xFE).
    /// </summary>
    public Terrain(uint landblock, ReadOnlySpan<float> heights, string name = "terrain")
    {
        if (heights.Length != VerticesPerSide * VerticesPerSide)
            throw new ArgumentException($"{name}.heights: expected {VerticesPerSide * VerticesPerSide} values (9×9), got {heights.Length}.", nameof(heights));
        for (int i = 0; i < heights.Length; i++)
            Guard.Coordinate(heights[i], $"{name}.heights[{i}]");
        if (landblock > 0xFFFF)
            throw new ArgumentException($"{name}.landblock: 0x{landblock:X} is not a 16-bit landblock id.", nameof(landblock));
        Guard.LandblockInWorld(landblock, $"{name}.landblock");
        Landblock = landblock;
        _heights = heights.ToArray();
    }

    /// <summary>Flat terrain at one height.</summary>
    public static Terrain Flat(uint landblock, float height)
    {
        Span<float> h = stackalloc float[VerticesPerSide * VerticesPerSide];
        h.Fill(height);
        return new Terrain(landblock, h);
    }

    /// <summary>The landblock id (high 16 bits of its cell ids).</summary>
    public uint Landblock { get; }

    /// <summary>The height at grid vertex (x, y).</summary>
    public float HeightAt(int x, int y) => _heights[x * VerticesPerSide + y];

    /// <summary>
    /// Retail's terrain diagonal: true when cell (x, y) of this landblock is cut south-west to north-east.
    /// The choice hashes the cell's global coordinates with retail's constants 214614067, 1813693831,
    /// 1109124029 and 1369149221 in 32-bit wrap-around arithmetic (ACE LandblockStruct.ConstructPolygons;
    /// holtburger terrain_collision.rs); the top bit of the hash decides.
    /// </summary>
    public bool IsSouthWestToNorthEastCut(int x, int y)
    {
        uint gx = (Landblock >> 8) * 8 + (uint)x;
        uint gy = (Landblock & 0xFF) * 8 + (uint)y;
        uint hash = unchecked(gy * (gx * 214614067u + 1813693831u) - gx * 1109124029u - 1369149221u);
        return (hash & 0x80000000u) != 0;
    }

    /// <summary>Builds the two triangles of land cell (x, y), counter-clockwise from above, landblock-local.</summary>
    internal (Polygon First, Polygon Second) CellTriangles(int x, int y)
    {
        float s = PhysicsConstants.LandCellLength;
        var sw = new Vector3(x * s, y * s, HeightAt(x, y));
        var se = new Vector3((x + 1) * s, y * s, HeightAt(x + 1, y));
        var ne = new Vector3((x + 1) * s, (y + 1) * s, HeightAt(x + 1, y + 1));
        var nw = new Vector3(x * s, (y + 1) * s, HeightAt(x, y + 1));
        string name = $"terrain 0x{Landblock:X4} cell ({x},{y})";
        if (IsSouthWestToNorthEastCut(x, y))
            return (new Polygon([sw, se, ne], PolygonSides.Single, name), new Polygon([sw, ne, nw], PolygonSides.Single, name));
        return (new Polygon([sw, se, nw], PolygonSides.Single, name), new Polygon([se, ne, nw], PolygonSides.Single, name));
    }
}
