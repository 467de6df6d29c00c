using System;
using System.Numerics;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>
/// The terrain of one landblock: a 9×9 grid of heights (metres) at the corners of its 8×8 land cells,
/// each cell cut into two triangles along the diagonal retail picks from the cell's global coordinates,
/// and the 9×9 terrain words whose terrain types make cells water (docs/water.md).
/// </summary>
public sealed class Terrain
{
    /// <summary>Vertices per side of a landblock's height grid.</summary>
    public const int VerticesPerSide = 9;

    private const int VertexCount = VerticesPerSide * VerticesPerSide;
    private const int CellsPerSide = VerticesPerSide - 1;

    private readonly float[] _heights;
    // The terrain words as the landblock stores them (retail CLandBlockStruct::terrain), [x * 9 + y].
    private readonly ushort[] _words;
    // Each land cell's water type, [x * 8 + y] (retail CLandCell::water_type, set by CalcWater).
    private readonly WaterType[] _cellWater;

    /// <summary>
    /// Creates dry terrain from 81 heights, indexed [x * 9 + y] (x east, y north), in metres (finite, within
    /// ±<see cref="InputLimits.MaxCoordinate"/>), for a landblock inside the retail world
    /// (<see cref="LandDefs.IsValidLandblock"/>: x and y bytes 0x00..0xFE). Every terrain word is 0
    /// (terrain type 0, BarrenRock: solid).
    /// </summary>
    public Terrain(uint landblock, ReadOnlySpan<float> heights)
        : this(landblock, heights, new ushort[VertexCount], "terrain")
    {
    }

    /// <summary>
    /// <see cref="Terrain(uint, ReadOnlySpan{float})"/> with the name its exceptions give the terrain:
    /// "<paramref name="name"/>.heights[5]".
    /// </summary>
    public Terrain(uint landblock, ReadOnlySpan<float> heights, string name)
        : this(landblock, heights, new ushort[VertexCount], name)
    {
    }

    /// <summary>
    /// Creates terrain from 81 heights and the 81 terrain words of the same vertices, both indexed
    /// [x * 9 + y] (x east, y north), as a landblock stores them: a DAT LandBlock's <c>Height</c> entries
    /// through the region's height table, and its <c>Terrain</c> entries as they are (bits 0–1 road, 2–6
    /// terrain type, 11–15 scenery; physics reads only the type, <see cref="TerrainTypeOf"/>), which make
    /// cells water (docs/water.md). Heights as in <see cref="Terrain(uint, ReadOnlySpan{float})"/>; any
    /// 16-bit word is accepted. <paramref name="name"/> names the terrain in exceptions (e.g. the DAT file
    /// and landblock it was read from): "<paramref name="name"/>.terrain: …".
    /// </summary>
    public Terrain(uint landblock, ReadOnlySpan<float> heights, ReadOnlySpan<ushort> terrainWords, string name = "terrain")
    {
        ArgumentNullException.ThrowIfNull(name);
        if (heights.Length != VertexCount)
            throw new ArgumentException($"{name}.heights: expected {VertexCount} values (9×9), got {heights.Length}.", nameof(heights));
        if (terrainWords.Length != VertexCount)
            throw new ArgumentException($"{name}.terrain: expected {VertexCount} terrain words (9×9), got {terrainWords.Length}.", nameof(terrainWords));
        // Each height's field name is built only for a refusal's message (a DAT landblock load makes 81).
        for (int i = 0; i < heights.Length; i++)
            if (!Guard.IsCoordinate(heights[i]))
                Guard.Coordinate(heights[i], $"{name}.heights[{i}]");
        if (landblock > 0xFFFF)
            throw new ArgumentException($"{name}.landblock: 0x{landblock:X} is not a 16-bit landblock id.", nameof(landblock));
        Guard.LandblockInWorld(landblock, $"{name}.landblock");
        Landblock = landblock;
        _heights = heights.ToArray();
        _words = terrainWords.ToArray();
        _cellWater = new WaterType[CellsPerSide * CellsPerSide];
        WaterType = CalcWater();
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

    /// <summary>The terrain word at grid vertex (x, y), as given.</summary>
    public ushort TerrainWordAt(int x, int y) => _words[x * VerticesPerSide + y];

    /// <summary>The terrain type of a terrain word: bits 2–6, 0..31 (retail <c>(word &gt;&gt; 2) &amp; 0x1F</c>).</summary>
    public static int TerrainTypeOf(ushort word) => (word >> 2) & 0x1F;

    /// <summary>
    /// True for the water terrain types 0x10..0x14 (WaterRunning, WaterStandingFresh, WaterShallowSea,
    /// WaterShallowStillSea, WaterDeepSea): retail's table TERRAIN_SURF_CHAR says WATER for these and SOLID
    /// for every other type.
    /// </summary>
    public static bool IsWaterType(int terrainType) => terrainType >= 0x10 && terrainType <= 0x14;

    /// <summary>True when grid vertex (x, y)'s terrain type is water.</summary>
    public bool IsWaterAt(int x, int y) => IsWaterType(TerrainTypeOf(TerrainWordAt(x, y)));

    /// <summary>The landblock's water type (retail CLandBlockStruct::water_type, set by CalcWater).</summary>
    public WaterType WaterType { get; }

    /// <summary>Land cell (x, y)'s water type (x, y 0..7; retail CLandCell::water_type, set by CalcWater).</summary>
    public WaterType CellWaterType(int x, int y) => _cellWater[x * CellsPerSide + y];

    /// <summary>
    /// Retail CLandBlockStruct::CalcWater (acclient.c:354565) with CalcCellWater (acclient.c:353607): a cell
    /// with a water corner is PartiallyWater, with four EntirelyWater; the landblock is EntirelyWater when
    /// every cell is, NotWater when none has water, else PartiallyWater. Retail runs it only at full detail
    /// (8 cells a side), which our terrain always is.
    /// </summary>
    private WaterType CalcWater()
    {
        bool blockHasWater = false, blockAllWater = true;
        for (int x = 0; x < CellsPerSide; x++)
        {
            for (int y = 0; y < CellsPerSide; y++)
            {
                bool hasWater = false, allWater = true;
                for (int vx = x; vx <= x + 1; vx++)
                {
                    for (int vy = y; vy <= y + 1; vy++)
                    {
                        if (IsWaterAt(vx, vy)) hasWater = true;
                        else allWater = false;
                    }
                }
                var cell = !hasWater ? WaterType.NotWater : allWater ? WaterType.EntirelyWater : WaterType.PartiallyWater;
                _cellWater[x * CellsPerSide + y] = cell;
                blockHasWater |= hasWater;
                blockAllWater &= cell == WaterType.EntirelyWater;
            }
        }
        return !blockHasWater ? WaterType.NotWater : blockAllWater ? WaterType.EntirelyWater : WaterType.PartiallyWater;
    }

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
        bool cut = IsSouthWestToNorthEastCut(x, y);
        // The cell's name is built only for a refusal's message (a landblock makes 64 of these): a refused
        // triangle is made again under its full name, which refuses it the same way.
        try
        {
            return Triangles(cut, sw, se, ne, nw, "terrain");
        }
        catch (ArgumentException)
        {
            return Triangles(cut, sw, se, ne, nw, $"terrain 0x{Landblock:X4} cell ({x},{y})");
        }
    }

    private static (Polygon First, Polygon Second) Triangles(bool southWestToNorthEast, Vector3 sw, Vector3 se, Vector3 ne, Vector3 nw, string name) =>
        southWestToNorthEast
            ? (new Polygon([sw, se, ne], PolygonSides.Single, name), new Polygon([sw, ne, nw], PolygonSides.Single, name))
            : (new Polygon([sw, se, nw], PolygonSides.Single, name), new Polygon([se, ne, nw], PolygonSides.Single, name));
}
