using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Geometry;

/// <summary>
/// A triangle prepared for <see cref="PolygonQuery.PointInPoly2D"/>'s test on the positive side: the start
/// and the X/Y direction of each edge are stored, so a test reads twelve floats instead of walking the
/// polygon's vertices. The products and differences are the same, in the same order, so every answer is
/// the same to the bit.
/// </summary>
internal readonly struct Triangle2D
{
    // Edge k runs from vertex k to vertex k + 1 (mod 3); PointInPoly2D tests edge 2 first, then 1, then 0.
    private readonly float _x0, _y0, _dx0, _dy0;
    private readonly float _x1, _y1, _dx1, _dy1;
    private readonly float _x2, _y2, _dx2, _dy2;

    /// <summary>Prepares the triangle with these three vertices.</summary>
    public Triangle2D(ReadOnlySpan<Vector3> vertices)
    {
        if (vertices.Length != 3)
            throw new ArgumentException($"a triangle has 3 vertices, got {vertices.Length}.", nameof(vertices));
        Vector3 a = vertices[0], b = vertices[1], c = vertices[2];
        (_x0, _y0, _dx0, _dy0) = (a.X, a.Y, b.X - a.X, b.Y - a.Y);
        (_x1, _y1, _dx1, _dy1) = (b.X, b.Y, c.X - b.X, c.Y - b.Y);
        (_x2, _y2, _dx2, _dy2) = (c.X, c.Y, a.X - c.X, a.Y - c.Y);
    }

    /// <summary>
    /// <see cref="PolygonQuery.PointInPoly2D"/> with <see cref="Sidedness.Positive"/>: no edge has the point
    /// strictly on its right (a NaN cross product rejects nothing, as there).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Contains(Vector3 point)
    {
        if (_dx2 * (point.Y - _y2) - _dy2 * (point.X - _x2) < 0f)
            return false;
        if (_dx1 * (point.Y - _y1) - _dy1 * (point.X - _x1) < 0f)
            return false;
        return !(_dx0 * (point.Y - _y0) - _dy0 * (point.X - _x0) < 0f);
    }
}
