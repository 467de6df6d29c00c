using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>The retail polygon queries (CPolygon): sphere hits, walkable hits, point in polygon, crossed edge, adjustments.</summary>
public static class PolygonQuery
{
    /// <summary>
    /// Retail check_walkable: true when the sphere, pushed along <paramref name="up"/>, rests on the polygon
    /// (the polygon still holds the mover). <paramref name="small"/> selects check_small_walkable's tighter test.
    /// </summary>
    public static bool CheckWalkable(Polygon polygon, in Sphere sphere, Vector3 up, bool small)
        => throw new NotImplementedException();

    /// <summary>
    /// Retail find_crossed_edge: the outward edge normal (in the polygon's plane) of the edge the sphere
    /// centre has crossed, projected along <paramref name="up"/>. False when no edge was crossed.
    /// </summary>
    public static bool FindCrossedEdge(Polygon polygon, in Sphere sphere, Vector3 up, out Vector3 normal)
        => throw new NotImplementedException();
}
