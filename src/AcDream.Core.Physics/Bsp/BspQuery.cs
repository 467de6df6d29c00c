using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Bsp;

/// <summary>
/// The retail geometric queries over a whole physics BSP tree (BSPTREE): they answer with plain values and
/// change nothing but what they are handed. The per-node recursions they drive live in
/// <see cref="BspNodeQuery"/>; the modes that take a transition and choose its response (find_collisions,
/// placement_insert, step_sphere_down…) live with the transition (Transitions.Responses.BspResponses).
/// Spheres and points are in the tree's own (unscaled) space. Nothing here allocates.
/// </summary>
internal static class BspQuery
{
    /// <summary>Retail BSPTREE::adjust_to_plane gives up after this many tries (hard-coded in retail).</summary>
    private const int AdjustIterations = 15;

    /// <summary>
    /// Retail BSPTREE::adjust_to_plane: finds how far along the move from <paramref name="currPos"/> to
    /// <paramref name="checkPos"/> the sphere can go without hitting the tree, and leaves
    /// <paramref name="checkPos"/> there. First it jumps to where the sphere touches the hit polygon's plane
    /// (<see cref="PolygonQuery.AdjustSphereToPoly"/>), re-aiming at each new polygon hit; then it bisects
    /// until the bracket is narrower than 0.02 of the move. 15 tries in all; false when the first stage
    /// uses them up.
    /// Retail quirk (acclient.c:360915): the first stage stops as soon as the touch time is exactly 1
    /// (already within a radius of the plane), leaving the bracket at [0, 1]; ACE inverts that test.
    /// </summary>
    public static bool AdjustToPlane(BspTree tree, ref Sphere checkPos, Vector3 currPos, Polygon hitPolygon, ref Vector3 contactPoint)
    {
        ArgumentNullException.ThrowIfNull(tree);
        ArgumentNullException.ThrowIfNull(hitPolygon);
        var movement = checkPos.Center - currPos;
        float lower = 0f;
        float upper = 1f;
        int tries = 0;
        Polygon? aim = hitPolygon;
        while (true)
        {
            float touch = PolygonQuery.AdjustSphereToPoly(aim!, checkPos, currPos, movement);
            if (touch == 1f)
                break;
            checkPos.Center = currPos + movement * touch;
            if (!BspNodeQuery.SphereIntersectsPoly(tree, 0, checkPos, movement, ref aim, ref contactPoint))
            {
                lower = touch;
                break;
            }
            tries++;
            upper = touch;
            if (tries >= AdjustIterations)
                return false;
        }
        while (tries < AdjustIterations)
        {
            float middle = (lower + upper) * 0.5f;
            checkPos.Center = currPos + movement * middle;
            if (BspNodeQuery.SphereIntersectsPoly(tree, 0, checkPos, movement, ref aim, ref contactPoint))
                upper = middle;
            else
                lower = middle;
            if (upper - lower < 0.02f)
                break;
            tries++;
        }
        checkPos.Center = currPos + movement * lower;
        return true;
    }

    /// <summary>Retail BSPTREE::point_inside_cell_bsp: true when the point is on the inside of every split on its path.</summary>
    public static bool PointInsideCellBsp(BspTree tree, Vector3 point)
    {
        ArgumentNullException.ThrowIfNull(tree);
        return BspNodeQuery.PointInsideCellBsp(tree, 0, point);
    }

    /// <summary>Retail BSPTREE::sphere_intersects_cell_bsp: whether the sphere is outside, partly or entirely inside the cell.</summary>
    public static BoundingType SphereIntersectsCellBsp(BspTree tree, in Sphere sphere)
    {
        ArgumentNullException.ThrowIfNull(tree);
        return BspNodeQuery.SphereIntersectsCellBsp(tree, 0, sphere);
    }

    /// <summary>Retail point_intersects_solid from the root: true when the point ends in a leaf with polygons.</summary>
    public static bool PointIntersectsSolid(BspTree tree, Vector3 point)
    {
        ArgumentNullException.ThrowIfNull(tree);
        return BspNodeQuery.PointIntersectsSolid(tree, 0, point);
    }

    /// <summary>Retail sphere_intersects_solid from the root: true when the sphere touches a polygon, or (with <paramref name="centerCheck"/>) its centre is in a solid leaf.</summary>
    public static bool SphereIntersectsSolid(BspTree tree, in Sphere sphere, bool centerCheck = true)
    {
        ArgumentNullException.ThrowIfNull(tree);
        return BspNodeQuery.SphereIntersectsSolid(tree, 0, sphere, centerCheck);
    }
}
