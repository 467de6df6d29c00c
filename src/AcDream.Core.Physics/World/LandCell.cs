using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.World;

/// <summary>
/// An outdoor 24 m × 24 m cell of a landblock (retail CLandCell): two terrain triangles, and optionally
/// the <see cref="Building"/> whose shell stands in it.
/// </summary>
public sealed class LandCell : Cell
{
    private readonly Polygon _first;
    private readonly Polygon _second;
    // The same triangles prepared for the point-in-triangle test that the cell search and the terrain test
    // run on every insert.
    private readonly Triangle2D _firstXY;
    private readonly Triangle2D _secondXY;
    // The cell's square, landblock-local: west and south edges (LandDefs.LandCellCorner), east and north
    // (those plus the cell length, in float as before).
    private readonly float _west, _south, _east, _north;
    // Water (docs/water.md): the cell's type, whether its whole landblock is water, and for a partly-water
    // cell the depth at each corner as calc_water_depth answers it (0.45 water, 0.1 solid), with the centre
    // lines that pick the corner.
    private readonly bool _blockEntirelyWater;
    private readonly float _centreX, _centreY;
    private readonly float _depthSW, _depthSE, _depthNW, _depthNE;

    /// <summary>Creates land cell <paramref name="id"/> from its landblock's terrain.</summary>
    internal LandCell(uint id, Terrain terrain) : base(id)
    {
        uint index = id & 0xFFFF;
        if (index < 1 || index > 64)
            throw new System.ArgumentException($"cell 0x{id:X8}: an outdoor cell index must be 1..64.", nameof(id));
        if ((id >> 16) != terrain.Landblock)
            throw new System.ArgumentException($"cell 0x{id:X8}: is not in the terrain's landblock 0x{terrain.Landblock:X4}.", nameof(id));
        int x = (int)((index - 1) / 8), y = (int)((index - 1) % 8);
        (_first, _second) = terrain.CellTriangles(x, y);
        _firstXY = new Triangle2D(_first.Vertices);
        _secondXY = new Triangle2D(_second.Vertices);
        var corner = LandDefs.LandCellCorner(id);
        (_west, _south) = (corner.X, corner.Y);
        (_east, _north) = (corner.X + PhysicsConstants.LandCellLength, corner.Y + PhysicsConstants.LandCellLength);
        WaterType = terrain.CellWaterType(x, y);
        _blockEntirelyWater = terrain.WaterType == WaterType.EntirelyWater;
        // CLandBlock::get_terrain's centre line, ((double)x + x + 1) * (24 * 0.5): 24 x + 12, exact in float.
        _centreX = (2 * x + 1) * (PhysicsConstants.LandCellLength * 0.5f);
        _centreY = (2 * y + 1) * (PhysicsConstants.LandCellLength * 0.5f);
        _depthSW = CornerDepth(terrain, x, y);
        _depthSE = CornerDepth(terrain, x + 1, y);
        _depthNW = CornerDepth(terrain, x, y + 1);
        _depthNE = CornerDepth(terrain, x + 1, y + 1);
    }

    // calc_water_depth's answer for a corner (acclient.c:353645): 0.44999999 (0.45f) when its terrain type is
    // water, 0.1 when it is solid.
    private static float CornerDepth(Terrain terrain, int x, int y) => terrain.IsWaterAt(x, y) ? 0.45f : 0.1f;

    /// <summary>
    /// How much of the cell is water (retail CObjCell::water_type): from its four corners' terrain types
    /// (<see cref="Terrain.CellWaterType"/>). A mover standing here sinks <see cref="WaterDepth"/> into the
    /// ground and its contact plane is water (docs/water.md).
    /// </summary>
    public WaterType WaterType { get; }

    /// <summary>
    /// Retail CObjCell::get_water_depth (acclient.c:347232) at a landblock-local point of this cell: 0 when the
    /// cell is dry, 0.9 (0.89999998f) when it is entirely water, and for a partly-water cell
    /// CLandBlockStruct::calc_water_depth (acclient.c:353645): 0.45 when the corner on the point's side of the
    /// cell's centre lines is water, 0.1 when it is solid. A point on a centre line takes the west (south)
    /// corner, as CLandBlock::get_terrain's kept comparison <c>(2x + 1) · 12 &gt;= X</c> (acclient.c:352030)
    /// reads; ACE's <c>X % 24 &gt;= 12</c> differs there and on the east/north edge (docs/open-questions.md).
    /// </summary>
    internal float WaterDepth(Vector3 localPoint)
    {
        switch (WaterType)
        {
            case WaterType.NotWater:
                return 0f;
            case WaterType.EntirelyWater:
                return 0.9f;
            default:
                bool east = localPoint.X > _centreX, north = localPoint.Y > _centreY;
                return east ? (north ? _depthNE : _depthSE) : (north ? _depthNW : _depthSW);
        }
    }

    /// <summary>Whether the cell's whole landblock is water (<see cref="Terrain.WaterType"/>): then the landblock stops movers (retail find_env_collisions, acclient.c:355030).</summary>
    internal bool BlockEntirelyWater => _blockEntirelyWater;

    /// <summary>The south-west corner of the cell's square, landblock-local (X, Y; 24 m × the cell's column and row, exact).</summary>
    internal Vector2 SouthWest => new(_west, _south);

    /// <summary>The cell's two terrain triangles (landblock-local), for the world queries.</summary>
    internal (Polygon First, Polygon Second) Triangles => (_first, _second);

    /// <summary>The building standing in this cell, or null.</summary>
    public Building? Building { get; internal set; }

    /// <summary>The terrain triangle under a landblock-local point (by X and Y), or null when outside the cell.</summary>
    /// <remarks>Retail's test is <see cref="PolygonQuery.PointInPoly2D"/> (positive side) on each triangle in turn.</remarks>
    internal Polygon? FindTerrainPolygon(Vector3 point)
    {
        if (_firstXY.Contains(point)) return _first;
        if (_secondXY.Contains(point)) return _second;
        return null;
    }

    /// <summary>Retail point_in_cell for land: the point's X/Y lie on one of the triangles.</summary>
    public bool ContainsPoint(Vector3 point) => _firstXY.Contains(point) || _secondXY.Contains(point);

    /// <summary>The horizontal distance from the cell's 24 m square.</summary>
    internal override float DistanceOutside(Vector3 point)
    {
        // Inside (the usual case: every move validates its start) the distance is 0: both differences below
        // are then at most 0, whose maximum with 0 is 0, so the answer is the one computed below.
        if (point.X >= _west && point.X <= _east && point.Y >= _south && point.Y <= _north)
            return 0f;
        float dx = System.MathF.Max(System.MathF.Max(_west - point.X, point.X - _east), 0f);
        float dy = System.MathF.Max(System.MathF.Max(_south - point.Y, point.Y - _north), 0f);
        if (dx == 0f && dy == 0f)
            return 0f;
        return System.MathF.Sqrt(dx * dx + dy * dy);
    }
}
