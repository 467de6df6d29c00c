using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions;

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
    }

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

    /// <inheritdoc />
    internal override TransitionState FindEnvCollisions(Transition transition)
    {
        var path = transition.SpherePath;
        if ((path.CheckPos.CellId >> 16) == (Id >> 16))
        {
            // The usual case, the check position in this cell's landblock: no offset, so sphere 0 is passed as
            // it is (subtracting a zero offset would change no bit) and not copied.
            var triangle = FindTerrainPolygon(path.GlobalLowPoint);
            if (triangle is null)
                return TransitionState.OK;
            return transition.ValidateWalkable(path.GlobalSphere[0], triangle.Plane, isWater: false, waterDepth: 0f, Id);
        }
        var blockOffset = LandDefs.BlockOffset(path.CheckPos.CellId, Id);
        var walkable = FindTerrainPolygon(path.GlobalLowPoint - blockOffset);
        if (walkable is null)
            return TransitionState.OK;
        var check = path.GlobalSphere[0];
        check.Center -= blockOffset;
        return transition.ValidateWalkable(check, walkable.Plane, isWater: false, waterDepth: 0f, Id);
    }
}
