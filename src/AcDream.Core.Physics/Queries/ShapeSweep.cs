using System;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Queries;

/// <summary>
/// The first contact of a swept sphere (radius 0 for a ray) with one placed shape, by the exact times of
/// impact of <see cref="TimeOfImpact"/>: faces are met only from their front (single-sided polygons), so a
/// cast that starts inside a closed solid passes out of it; a sphere already touching a shape hits it at
/// fraction 0 only when it moves into it. Sphere and cylinder obstacles whose solid holds the cast's start
/// are ignored for the same reason. Everything here is in the query's landblock frame unless named local.
/// </summary>
internal static class ShapeSweep
{
    /// <summary>The best contact so far: fraction, normal (query frame), and whether there is one.</summary>
    internal struct Best
    {
        public float Fraction;
        public Vector3 Normal;
        public bool Found;

        public static Best None(float limit) => new() { Fraction = limit };

        /// <summary>Keeps the contact when it is earlier (the first found wins a tie, so results follow the fixed test order).</summary>
        public bool Offer(float fraction, Vector3 normal)
        {
            if (Found ? !(fraction < Fraction) : !(fraction <= Fraction))
                return false;
            Fraction = fraction;
            Normal = normal;
            Found = true;
            return true;
        }
    }

    /// <summary>
    /// Sweeps against every polygon of a BSP tree placed at <paramref name="frame"/> in landblock space
    /// shifted by <paramref name="blockShift"/> from the query's frame, with a uniform scale. Leaves whose
    /// bounding sphere the swept sphere cannot reach are skipped. With <paramref name="walkableOnly"/> only
    /// surfaces a mover could stand on (normal Z at least floor_z) count. True when it improved <paramref name="best"/>.
    /// </summary>
    public static bool Tree(BspTree tree, in Frame frame, Vector3 blockShift, float scale, Vector3 c, Vector3 d, float r,
        bool walkableOnly, ref Best best) =>
        // The frame's matrix once (Frame's own transforms rebuild it from the quaternion at each call).
        Tree(tree, frame.Matrix, frame.Origin, blockShift, scale, c, d, r, walkableOnly, ref best);

    /// <summary>
    /// <see cref="Tree(BspTree, in Frame, Vector3, float, Vector3, Vector3, float, bool, ref Best)"/> with the frame
    /// given as its rotation matrix (built from the frame's quaternion, as an indoor cell keeps it) and origin.
    /// </summary>
    public static bool Tree(BspTree tree, in RotationMatrix matrix, Vector3 origin, Vector3 blockShift, float scale, Vector3 c, Vector3 d, float r,
        bool walkableOnly, ref Best best)
    {
        float inv = 1f / scale;
        var lc = matrix.FrameToLocal(c - blockShift, origin) * inv;
        var ld = matrix.FrameToLocal(d) * inv;
        float lr = r * inv;
        var end = lc + ld * best.Fraction;
        bool improved = false;
        var nodes = tree.NodeArray;
        var polygons = tree.PolygonArray;
        var indices = tree.IndexArray;
        if (!Reaches(nodes[0].Bounds, lc, end, lr))
            return false;
        // How far from a polygon's box a kept contact's centre can lie: MayReach's reach and a little for rounding.
        float grow = lr + TimeOfImpact.ContactSlop + BoxSlack;
        var sweptMin = Vector3.Min(lc, end) - new Vector3(grow);
        var sweptMax = Vector3.Max(lc, end) + new Vector3(grow);
        for (int i = 0; i < nodes.Length; i++)
        {
            ref readonly var node = ref nodes[i];
            if (!node.IsLeaf || node.PolygonCount == 0 || !Reaches(node.Bounds, lc, end, lr))
                continue;
            for (int k = 0; k < node.PolygonCount; k++)
            {
                var polygon = polygons[indices[node.FirstPolygon + k]];
                if (!BoxesMeet(polygon, sweptMin, sweptMax) || !SegmentMeetsBox(polygon, lc, end, grow) || !MayReach(polygon, lc, end, lr))
                    continue;
                if (!TimeOfImpact.Polygon(lc, ld, lr, polygon, out var hit))
                    continue;
                var normal = matrix.FrameToGlobal(hit.Normal);
                if (walkableOnly && !(normal.Z >= PhysicsConstants.FloorZ))
                    continue;
                if (best.Offer(hit.Time, normal))
                {
                    improved = true;
                    end = lc + ld * best.Fraction;
                    sweptMin = Vector3.Min(lc, end) - new Vector3(grow);
                    sweptMax = Vector3.Max(lc, end) + new Vector3(grow);
                }
            }
        }
        return improved;
    }

    /// <summary>Sweeps against one landblock-space polygon shifted by <paramref name="blockShift"/> (terrain).</summary>
    public static bool Polygon(Polygon polygon, Vector3 blockShift, Vector3 c, Vector3 d, float r, bool walkableOnly, ref Best best)
    {
        var local = c - blockShift;
        if (!MayReach(polygon, local, local + d * best.Fraction, r) || !TimeOfImpact.Polygon(c, d, r, polygon, blockShift, out var hit))
            return false;
        if (walkableOnly && !(hit.Normal.Z >= PhysicsConstants.FloorZ))
            return false;
        return best.Offer(hit.Time, hit.Normal);
    }

    /// <summary>Sweeps against a world-Z cylinder (query frame); ignored when the start lies inside it.</summary>
    public static bool Cylinder(in CylSphere cylinder, Vector3 c, Vector3 d, float r, bool walkableOnly, ref Best best)
    {
        if (Vector3.DistanceSquared(TimeOfImpact.ClosestPointOnCylinder(c, cylinder), c) == 0f)
            return false;
        if (!TimeOfImpact.Cylinder(c, d, r, cylinder, out var hit))
            return false;
        if (walkableOnly && !(hit.Normal.Z >= PhysicsConstants.FloorZ))
            return false;
        return best.Offer(hit.Time, hit.Normal);
    }

    /// <summary>Sweeps against a sphere obstacle (query frame); ignored when the start lies inside it.</summary>
    public static bool Sphere(in Sphere sphere, Vector3 c, Vector3 d, float r, bool walkableOnly, ref Best best)
    {
        if (Vector3.DistanceSquared(sphere.Center, c) < sphere.Radius * sphere.Radius)
            return false;
        if (!TimeOfImpact.Sphere(c, d, r, sphere, out var hit))
            return false;
        if (walkableOnly && !(hit.Normal.Z >= PhysicsConstants.FloorZ))
            return false;
        return best.Offer(hit.Time, hit.Normal);
    }

    // Slack on the polygon's box for float rounding of the local coordinates (the cast is expressed in the tree's
    // space in float): far above it for coordinates of a few hundred metres.
    private const float BoxSlack = 1e-3f;

    /// <summary>
    /// The cheapest test: false when the polygon's box and the box of the segment swept so far, both
    /// widened as in <see cref="SegmentMeetsBox"/>, do not meet (the swept box is passed widened).
    /// </summary>
    private static bool BoxesMeet(Polygon polygon, Vector3 sweptMin, Vector3 sweptMax) =>
        VectorMath.BoxesMeet(polygon.BoxMin, polygon.BoxMax, sweptMin, sweptMax);

    /// <summary>
    /// The next test before the exact one, after <see cref="BoxesMeet"/>: false when the segment from <paramref name="a"/> to
    /// <paramref name="b"/> (the start and the best contact so far) misses the polygon's box widened by
    /// <paramref name="grow"/> (radius + contact slop + slack). An accepted contact has its centre on that
    /// segment within radius + slop of the polygon, so inside the widened box: every contact
    /// <see cref="TimeOfImpact.Polygon(Vector3, Vector3, float, Polygon, out Geometry.ImpactHit)"/> could report that <see cref="Best.Offer"/> would keep passes; the
    /// rest would cost the exact test's closest point, face, edges and vertices for nothing. A slab test
    /// (a diagonal cast's own box holds far more polygons than the cast comes near), with the entry and exit
    /// fractions compared with a margin far above their rounding.
    /// </summary>
    private static bool SegmentMeetsBox(Polygon polygon, Vector3 a, Vector3 b, float grow)
    {
        var lo = polygon.BoxMin - new Vector3(grow);
        var hi = polygon.BoxMax + new Vector3(grow);
        var d = b - a;
        float enter = 0f, exit = 1f;
        Slab(a.X, d.X, lo.X, hi.X, ref enter, ref exit);
        Slab(a.Y, d.Y, lo.Y, hi.Y, ref enter, ref exit);
        Slab(a.Z, d.Z, lo.Z, hi.Z, ref enter, ref exit);
        return enter <= exit + 1e-4f;
    }

    // Narrows [enter, exit] to the fractions at which a + t·d lies between lo and hi on one axis (an axis the
    // segment does not cross is left to BoxesMeet, which already found it inside the slab).
    private static void Slab(float a, float d, float lo, float hi, ref float enter, ref float exit)
    {
        if (!(MathF.Abs(d) > 1e-6f))
            return;
        float t0 = (lo - a) / d, t1 = (hi - a) / d;
        enter = MathF.Max(enter, MathF.Min(t0, t1));
        exit = MathF.Min(exit, MathF.Max(t0, t1));
    }

    /// <summary>
    /// A cheap test before the exact one: false when the swept sphere stays clear of the polygon's plane
    /// (wholly in front of it, or wholly behind it), or stays behind a single-sided face — the cases in
    /// which <see cref="TimeOfImpact.Polygon(Vector3, Vector3, float, Polygon, out ImpactHit)"/> finds nothing.
    /// </summary>
    private static bool MayReach(Polygon polygon, Vector3 a, Vector3 b, float r)
    {
        var plane = polygon.Plane;
        float s0 = Vector3.Dot(plane.Normal, a) + plane.D;
        float s1 = Vector3.Dot(plane.Normal, b) + plane.D;
        if (s0 < 0f && s1 <= 0f && polygon.Sides == PolygonSides.Single)
            return false;
        float reach = r + TimeOfImpact.ContactSlop;
        return !(s0 > reach && s1 > reach) && !(s0 < -reach && s1 < -reach);
    }

    /// <summary>True when a sphere of radius <paramref name="r"/> moving from <paramref name="a"/> to <paramref name="b"/> can touch <paramref name="bounds"/>.</summary>
    public static bool Reaches(in Sphere bounds, Vector3 a, Vector3 b, float r)
    {
        var closest = TimeOfImpact.ClosestPointOnSegment(bounds.Center, a, b);
        float reach = bounds.Radius + r + PhysicsConstants.Epsilon;
        return Vector3.DistanceSquared(closest, bounds.Center) <= reach * reach;
    }
}
