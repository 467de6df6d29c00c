using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Bsp;

/// <summary>
/// The retail per-node recursions of a physics BSP (BSPNODE / BSPLEAF virtuals) over the flat layout of
/// <see cref="BspTree"/>. Each takes the tree and a node index (the root is 0) and recurses by index; a
/// missing child (index −1) is empty space. Every node — internal or leaf — first tests the query sphere
/// against its bounding sphere, as retail does; a leaf with no polygons never hits anything.
/// Internal nodes route by the split plane: at or beyond <c>radius − EPSILON</c> on one side the query
/// goes to that side only, otherwise to both.
/// </summary>
internal static class BspNodeQuery
{
    private const float Epsilon = PhysicsConstants.Epsilon;

    private static float SplitDistance(in BspNode node, Vector3 point)
        => VectorMath.Dot(node.SplitPlane.Normal, point) + node.SplitPlane.D;

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::sphere_intersects_poly: the first polygon the moving sphere hits from its
    /// front (see <see cref="PolygonQuery.PosHitsSphere"/>), front subtree before back. True on a hit, with
    /// <paramref name="hitPolygon"/> and <paramref name="contactPoint"/> set. On a miss
    /// <paramref name="hitPolygon"/> may still have been set to a polygon grazed from behind (retail quirk).
    /// </summary>
    public static bool SphereIntersectsPoly(BspTree tree, int index, in Sphere checkPos, Vector3 movement, ref Polygon? hitPolygon, ref Vector3 contactPoint)
    {
        // A walk down the tree; only a straddled split recurses (into its front), its back is the next step.
        while (index >= 0)
        {
            ref readonly var node = ref tree.NodeArray[index];
            if (node.IsLeaf)
            {
                if (node.PolygonCount == 0 || !node.Bounds.Intersects(checkPos))
                    return false;
                var polygons = tree.PolygonArray;
                var indices = tree.IndexArray;
                for (int k = 0; k < node.PolygonCount; k++)
                    if (PolygonQuery.PosHitsSphere(polygons[indices[node.FirstPolygon + k]], checkPos, movement, ref contactPoint, ref hitPolygon))
                        return true;
                return false;
            }
            if (!node.Bounds.Intersects(checkPos))
                return false;
            float distance = SplitDistance(node, checkPos.Center);
            float reach = checkPos.Radius - Epsilon;
            if (distance >= reach)
                index = node.Front;
            else if (distance <= -reach)
                index = node.Back;
            else
            {
                if (SphereIntersectsPoly(tree, node.Front, checkPos, movement, ref hitPolygon, ref contactPoint))
                    return true;
                index = node.Back;
            }
        }
        return false;
    }

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::sphere_intersects_solid: true when the sphere touches a polygon, or — with
    /// <paramref name="centerCheck"/> — when its centre lies in a solid leaf. A straddled split passes the
    /// centre check only to the side that holds the centre (front when exactly on the plane). Retail quirk:
    /// a solid leaf answers the centre check before its bounding sphere is tested, and a solid leaf with no
    /// polygons is never solid.
    /// </summary>
    public static bool SphereIntersectsSolid(BspTree tree, int index, in Sphere checkPos, bool centerCheck)
    {
        // A walk down the tree; only a straddled split recurses (into its front), its back is the next step.
        while (index >= 0)
        {
            ref readonly var node = ref tree.NodeArray[index];
            if (node.IsLeaf)
            {
                if (node.PolygonCount == 0)
                    return false;
                if (centerCheck && node.Solid)
                    return true;
                if (!node.Bounds.Intersects(checkPos))
                    return false;
                var polygons = tree.PolygonArray;
                var indices = tree.IndexArray;
                for (int k = 0; k < node.PolygonCount; k++)
                    if (PolygonQuery.HitsSphere(polygons[indices[node.FirstPolygon + k]], checkPos))
                        return true;
                return false;
            }
            if (!node.Bounds.Intersects(checkPos))
                return false;
            float distance = SplitDistance(node, checkPos.Center);
            float reach = checkPos.Radius - Epsilon;
            if (distance >= reach)
                index = node.Front;
            else if (distance <= -reach)
                index = node.Back;
            else
            {
                // The centre check goes only to the side that holds the centre (front when on the plane).
                bool centerInFront = distance >= 0f;
                if (SphereIntersectsSolid(tree, node.Front, checkPos, centerCheck && centerInFront))
                    return true;
                index = node.Back;
                centerCheck = centerCheck && !centerInFront;
            }
        }
        return false;
    }

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::sphere_intersects_solid_poly, used by placement: like
    /// <see cref="SphereIntersectsSolid"/> but reports the polygon hit in <paramref name="hitPolygon"/> and
    /// the centre-in-solid finding in <paramref name="centerSolid"/>. Routing at the split planes uses
    /// <paramref name="radius"/> (which placement grows) instead of the sphere's radius; the polygon tests
    /// use the sphere itself. On a straddle the side holding the centre is searched first, and the other
    /// side only (without centre check) when no polygon was found. Returns true on a polygon hit, otherwise
    /// the centre-solid flag.
    /// </summary>
    public static bool SphereIntersectsSolidPoly(BspTree tree, int index, in Sphere checkPos, float radius, ref bool centerSolid, ref Polygon? hitPolygon, bool centerCheck)
    {
        if (index < 0)
            return false;
        ref readonly var node = ref tree.NodeArray[index];
        if (node.IsLeaf)
        {
            if (node.PolygonCount == 0)
                return false;
            if (centerCheck && node.Solid)
                centerSolid = true;
            if (!node.Bounds.Intersects(checkPos))
                return centerSolid;
            var polygons = tree.PolygonArray;
            var indices = tree.IndexArray;
            for (int k = 0; k < node.PolygonCount; k++)
            {
                var polygon = polygons[indices[node.FirstPolygon + k]];
                if (PolygonQuery.HitsSphere(polygon, checkPos))
                {
                    hitPolygon = polygon;
                    return true;
                }
            }
            return centerSolid;
        }
        if (!node.Bounds.Intersects(checkPos))
            return false;
        float distance = SplitDistance(node, checkPos.Center);
        float reach = radius - Epsilon;
        if (distance >= reach)
            return SphereIntersectsSolidPoly(tree, node.Front, checkPos, radius, ref centerSolid, ref hitPolygon, centerCheck);
        if (distance <= -reach)
            return SphereIntersectsSolidPoly(tree, node.Back, checkPos, radius, ref centerSolid, ref hitPolygon, centerCheck);
        int first = distance < 0f ? node.Back : node.Front;
        int second = distance < 0f ? node.Front : node.Back;
        SphereIntersectsSolidPoly(tree, first, checkPos, radius, ref centerSolid, ref hitPolygon, centerCheck);
        if (hitPolygon is null)
            return SphereIntersectsSolidPoly(tree, second, checkPos, radius, ref centerSolid, ref hitPolygon, false);
        return centerSolid;
    }

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::hits_walkable: true when some polygon is walkable ground for the sphere —
    /// it faces up more than <paramref name="walkableAllowance"/>, the sphere hits it, and a half-radius disc
    /// under the centre still lies on it (check_small_walkable).
    /// </summary>
    public static bool HitsWalkable(BspTree tree, int index, in Sphere validPos, Vector3 up, float walkableAllowance)
    {
        // A walk down the tree; only a straddled split recurses (into its front), its back is the next step.
        while (index >= 0)
        {
            ref readonly var node = ref tree.NodeArray[index];
            if (node.IsLeaf)
            {
                if (node.PolygonCount == 0 || !node.Bounds.Intersects(validPos))
                    return false;
                var polygons = tree.PolygonArray;
                var indices = tree.IndexArray;
                for (int k = 0; k < node.PolygonCount; k++)
                {
                    var polygon = polygons[indices[node.FirstPolygon + k]];
                    if (PolygonQuery.WalkableHitsSphere(polygon, validPos, up, walkableAllowance)
                        && PolygonQuery.CheckSmallWalkable(polygon, validPos, up))
                        return true;
                }
                return false;
            }
            if (!node.Bounds.Intersects(validPos))
                return false;
            float distance = SplitDistance(node, validPos.Center);
            float reach = validPos.Radius - Epsilon;
            if (distance >= reach)
                index = node.Front;
            else if (distance <= -reach)
                index = node.Back;
            else
            {
                if (HitsWalkable(tree, node.Front, validPos, up, walkableAllowance))
                    return true;
                index = node.Back;
            }
        }
        return false;
    }

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::find_walkable, the step-down search: every walkable polygon the sphere hits
    /// lifts <paramref name="validPos"/> back along <paramref name="movement"/> onto its plane
    /// (<see cref="PolygonQuery.AdjustSphereToPlane"/>, which lowers <paramref name="walkInterp"/>); the last
    /// polygon that moved it is reported in <paramref name="polygon"/> and <paramref name="changed"/> is set.
    /// Retail quirk: the sphere is moved as the search goes, so later polygons and the routing of later
    /// nodes see the adjusted sphere; no polygon stops the search.
    /// </summary>
    public static void FindWalkable(BspTree tree, int index, ref Sphere validPos, ref Polygon? polygon, Vector3 movement, Vector3 up,
        float walkableAllowance, ref float walkInterp, ref bool changed)
    {
        // A walk down the tree; only a straddled split recurses (into its front), its back is the next step
        // (tested with the sphere as the front left it, as the recursion does).
        while (index >= 0)
        {
            ref readonly var node = ref tree.NodeArray[index];
            if (node.IsLeaf)
            {
                if (node.PolygonCount == 0 || !node.Bounds.Intersects(validPos))
                    return;
                var polygons = tree.PolygonArray;
                var indices = tree.IndexArray;
                for (int k = 0; k < node.PolygonCount; k++)
                {
                    var candidate = polygons[indices[node.FirstPolygon + k]];
                    if (PolygonQuery.WalkableHitsSphere(candidate, validPos, up, walkableAllowance)
                        && PolygonQuery.AdjustSphereToPlane(candidate, ref validPos, movement, ref walkInterp))
                    {
                        changed = true;
                        polygon = candidate;
                    }
                }
                return;
            }
            if (!node.Bounds.Intersects(validPos))
                return;
            float distance = SplitDistance(node, validPos.Center);
            float reach = validPos.Radius - Epsilon;
            if (distance >= reach)
                index = node.Front;
            else if (distance <= -reach)
                index = node.Back;
            else
            {
                FindWalkable(tree, node.Front, ref validPos, ref polygon, movement, up, walkableAllowance, ref walkInterp, ref changed);
                index = node.Back;
            }
        }
    }

    /// <summary>
    /// Retail BSPNODE/BSPLEAF::point_intersects_solid: follows the point down the tree (back when the
    /// distance is negative, front otherwise — a point exactly on a split goes front; ACE sends it back)
    /// and is true when it ends in a leaf that holds polygons. Retail quirk: the leaf's solid flag is not
    /// read; any leaf with polygons counts. A missing child is empty space.
    /// </summary>
    public static bool PointIntersectsSolid(BspTree tree, int index, Vector3 point)
    {
        var nodes = tree.NodeArray;
        while (index >= 0)
        {
            ref readonly var node = ref nodes[index];
            if (node.IsLeaf)
                return node.PolygonCount != 0;
            index = SplitDistance(node, point) < 0f ? node.Back : node.Front;
        }
        return false;
    }

    /// <summary>
    /// Retail BSPNODE::point_inside_cell_bsp: walks the chain of front children; false as soon as the point
    /// is behind a split by more than EPSILON, true at the end of the chain. A leaf ends the chain (retail
    /// leaves have a zero split plane, which reads as "in plane" and has no front child).
    /// </summary>
    public static bool PointInsideCellBsp(BspTree tree, int index, Vector3 point)
    {
        var nodes = tree.NodeArray;
        while (index >= 0)
        {
            ref readonly var node = ref nodes[index];
            if (SplitDistance(node, point) < -Epsilon)
                return false;
            index = node.Front;
        }
        return true;
    }

    /// <summary>
    /// Retail BSPNODE::sphere_intersects_cell_bsp: along the chain of front children, with the sphere
    /// grown by 0.01: behind any split → <see cref="BoundingType.Outside"/>; in front of every split →
    /// <see cref="BoundingType.EntirelyInside"/>; straddling one → <see cref="BoundingType.PartiallyInside"/>
    /// unless a later split has it outside. Retail quirk: a leaf in the chain has a zero split plane, so it
    /// always reads as straddled (never entirely inside); this is reproduced by the leaves' zero plane.
    /// </summary>
    public static BoundingType SphereIntersectsCellBsp(BspTree tree, int index, in Sphere sphere)
    {
        var nodes = tree.NodeArray;
        float reach = sphere.Radius + 0.01f;
        bool straddled = false;
        while (index >= 0)
        {
            ref readonly var node = ref nodes[index];
            float distance = SplitDistance(node, sphere.Center);
            if (distance <= -reach)
                return BoundingType.Outside;
            if (distance < reach)
                straddled = true;
            index = node.Front;
        }
        return straddled ? BoundingType.PartiallyInside : BoundingType.EntirelyInside;
    }
}
