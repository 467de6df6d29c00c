using System;
using System.Numerics;

namespace AcDream.Core.Physics.Geometry;

/// <summary>
/// Exact time of impact of a sphere (centre <c>c</c>, radius <c>r</c>) moving by <c>d</c> over the sweep
/// fraction t ∈ [0, 1], against polygons (face, edges, vertices), world-Z cylinders and spheres. Not a
/// retail algorithm: the runtime's casts are built on it (<see cref="Queries.ShapeSweep"/>), and the benchmark's
/// reference sweep measures the retail sub-stepping against it. Every test is the
/// smallest root of the distance equation |c + t·d − shape| = r; shapes are convex, so a sphere that is
/// not approaching a shape at t = 0 never reaches it later in the same straight sweep.
/// </summary>
internal static class TimeOfImpact
{
    /// <summary>
    /// A sphere closer to a shape than its radius plus this slop counts as touching: it is stopped at t = 0
    /// when it moves into the shape, and ignored when it moves along or away (metres).
    /// </summary>
    public const float ContactSlop = 1e-5f;

    /// <summary>
    /// A sphere smaller than this is cast as a ray (metres): a ray meets a polygon only through its face, by
    /// crossing the plane from the front inside the edges (within <see cref="InsideTolerance"/>, so a ray
    /// through the seam of two faces hits one of them), and a ray touching a polygon at its start is judged
    /// by the face's normal. Edges and vertices are not tested: a ray touches one only on the face's
    /// boundary or while lying in its plane, and a contact normal from an edge to a centre on it has no
    /// direction (it was NaN).
    /// </summary>
    internal const float RayRadius = 1e-4f;

    /// <summary>A sphere touching a shape "moves into it" when the normal component of its displacement is below −this × |d|.</summary>
    public const float ApproachTolerance = 1e-6f;

    /// <summary>Time of impact with the front of an infinite plane (the sphere starts at least r in front of it).</summary>
    public static bool Plane(Vector3 c, Vector3 d, float r, Plane plane, out float t)
    {
        t = 0f;
        float s0 = Vector3.Dot(plane.Normal, c) + plane.D;
        float vn = Vector3.Dot(plane.Normal, d);
        if (!(vn < 0f) || s0 < r)
            return false;
        t = (s0 - r) / -vn;
        return t <= 1f;
    }

    /// <summary>Time of impact with a point (a vertex), the sphere starting outside r of it and moving into it.</summary>
    public static bool Point(Vector3 c, Vector3 d, float r, Vector3 p, out float t, out Vector3 normal)
    {
        t = 0f;
        normal = default;
        var m = c - p;
        float a = Vector3.Dot(d, d);
        float b = Vector3.Dot(m, d);
        float cc = Vector3.Dot(m, m) - r * r;
        if (cc < 0f || b >= 0f || a <= 0f)
            return false;
        // b² − a·cc by Lagrange's identity: a·r² − |m × d|², without subtracting two huge squares (far
        // from the point, b² and a·|m|² agree in every float digit and their difference is rounding).
        float disc = a * r * r - Vector3.Cross(m, d).LengthSquared();
        if (disc <= a * GrazeDepth(r))
            return false;
        // The smaller root in the form that does not cancel: cc / (−b + √disc).
        t = cc / (-b + MathF.Sqrt(disc));
        if (t < 0f || t > 1f)
            return false;
        return Approaching(m + t * d, d, out normal);
    }

    /// <summary>Time of impact with a segment's interior (the edge cylinder between its end points), the sphere starting outside r of the line and moving into it.</summary>
    public static bool Segment(Vector3 c, Vector3 d, float r, Vector3 a, Vector3 b, out float t, out Vector3 normal)
    {
        t = 0f;
        normal = default;
        var e = b - a;
        float l2 = Vector3.Dot(e, e);
        if (l2 <= 0f)
            return false;
        var m = c - a;
        float md = Vector3.Dot(m, e), dd = Vector3.Dot(d, e);
        // The parts of the offset and of the motion across the line: |m⊥ + t d⊥|² = r².
        var mp = m - (md / l2) * e;
        var dp = d - (dd / l2) * e;
        float qa = Vector3.Dot(dp, dp);
        float qb = Vector3.Dot(mp, dp);
        float qc = Vector3.Dot(mp, mp) - r * r;
        if (qa <= 1e-12f || qc < 0f || qb >= 0f)
            return false;
        // qb² − qa·qc by Lagrange's identity (see Point): the old form lost every digit far from the edge.
        float disc = qa * r * r - Vector3.Cross(mp, dp).LengthSquared();
        if (disc <= qa * GrazeDepth(r))
            return false;
        t = qc / (-qb + MathF.Sqrt(disc));
        if (t < 0f || t > 1f)
            return false;
        float s = (md + t * dd) / l2;
        if (s < 0f || s > 1f)
            return false;
        return Approaching(mp + t * dp, d, out normal);
    }

    /// <summary>
    /// r² − (r − slop)²: a path whose closest approach to a point or a line is more than r − <see cref="ContactSlop"/>
    /// only grazes it (the discriminant over the squared speed is r² minus the squared closest approach). A
    /// tangent path's discriminant is rounding, whose square root tilted the normal by 1e-3 and let a sphere
    /// rolling along a face stop on its far edge.
    /// </summary>
    private static float GrazeDepth(float r)
    {
        float inner = MathF.Max(r - ContactSlop, 0f);
        return r * r - inner * inner;
    }

    /// <summary>
    /// The contact normal from the feature to the sphere's centre, and whether the sphere moves into the
    /// feature there: a tangential graze (the motion along the surface, as a sphere rolling over an edge of
    /// the floor it lies on) is not a contact, as for a touching start (<see cref="Resting"/>). False also
    /// when the offset is too short to give a direction (a radius that vanishes in rounding).
    /// </summary>
    private static bool Approaching(Vector3 away, Vector3 d, out Vector3 normal)
    {
        float len = away.Length();
        normal = len > 0f ? away / len : default;
        return len > 0f && Vector3.Dot(normal, d) < -ApproachTolerance * d.Length();
    }

    /// <summary>Time of impact with a sphere obstacle.</summary>
    public static bool Sphere(Vector3 c, Vector3 d, float r, in Sphere obstacle, out ImpactHit hit)
    {
        hit = default;
        var m = c - obstacle.Center;
        float dist = m.Length();
        float reach = r + obstacle.Radius;
        if (dist < reach + ContactSlop)
            return Resting(m, dist, d, Vector3.UnitZ, out hit);
        if (!Point(c, d, reach, obstacle.Center, out float t, out var n))
            return false;
        hit = new ImpactHit(t, n, ImpactFeature.Sphere);
        return true;
    }

    /// <summary>
    /// Time of impact with a convex polygon: its face (from the front; from either side unless
    /// <see cref="PolygonSides.Single"/>), its edges and its vertices, whichever comes first.
    /// </summary>
    public static bool Polygon(Vector3 c, Vector3 d, float r, Polygon polygon, out ImpactHit hit) =>
        Polygon(c, d, r, polygon, Vector3.Zero, out hit);

    /// <summary>
    /// <see cref="Polygon(Vector3, Vector3, float, Polygon, out ImpactHit)"/> for a polygon placed
    /// <paramref name="shift"/> from the frame of <paramref name="start"/> (a neighbouring landblock's
    /// terrain). A ray's edge test runs in the start's frame, where the shifted corners of terrain are exact, so
    /// it stays watertight across landblock seams (shifting the start instead rounds it differently for each
    /// landblock).
    /// </summary>
    internal static bool Polygon(Vector3 start, Vector3 d, float r, Polygon polygon, Vector3 shift, out ImpactHit hit)
    {
        hit = default;
        var c = start - shift;
        var plane = polygon.Plane;
        var n = plane.Normal;
        // Measured from a corner, not as n·c + D: far from the frame's origin D carries a rounding of several
        // micrometres, which a ray at a grazing angle turns into millimetres along its path.
        float s0 = Vector3.Dot(n, c - polygon.Vertices[0]);
        float vn = Vector3.Dot(n, d);
        bool ray = r < RayRadius;
        // A single-sided polygon is met only from its front: a start behind it is not touching it, and an
        // edge or corner contact counts only with the centre in front of the plane at that moment. (A start
        // behind the plane can still reach the front: over a convex ridge of terrain, a sphere low above one
        // face is behind the next face's plane, and lands on that face after crossing the ridge.)
        bool behind = false;
        if (s0 < 0f)
        {
            if (polygon.Sides == PolygonSides.Single)
            {
                // A sweep that still ends behind the plane (s0 + vn < 0) cannot meet the front, and returning
                // here is exact, not an approximation of the edge and corner rule below (s0 + t·vn ≥ 0): Segment
                // and Point report only t in [0, 1] (t < 0, t > 1 and NaN are refused), and with vn > 0 the
                // rounded product t·vn is at most vn (the exact product is, and rounding is monotone and keeps
                // vn), so the rounded s0 + t·vn is at most the rounded s0 + vn, which is negative (also when the
                // JIT fuses the multiply and add). Without it, the far faces of a closed solid a mover walks
                // at (the door's slab) had their edges and corners solved on every sweep.
                if (ray || !(vn > 0f) || s0 + vn < 0f)
                    return false;
                behind = true;
            }
            else
            {
                n = -n;
                s0 = -s0;
                vn = -vn;
            }
        }

        float best = float.PositiveInfinity;
        var bestNormal = Vector3.Zero;
        var feature = ImpactFeature.None;
        if (!behind)
        {
            // A start touching the polygon (within the slop) is judged at once. Its distance from the polygon is
            // at least its distance from the plane less the polygon's flatness and the rounding (RestingMargin), so
            // a start farther than that from the plane cannot be touching it: the distance is not worked out.
            if (!(s0 >= r + ContactSlop + RestingMargin(c, polygon)))
            {
                // Over the face the distance is the plane's and the direction the normal, exactly: the difference
                // of the centre and its projection, far from the frame's origin, carries the rounding of both
                // (1e-5 rad of tilt at 200 m), enough to read a sphere rolling on the face as moving into it.
                var projected = c - s0 * n;
                bool overFace = Inside(projected, polygon);
                var away = overFace ? s0 * n : c - ClosestPointOnPolygon(c, polygon);
                float dist = overFace ? s0 : away.Length();
                // Either way the sweep must go more than the slop into the polygon, or deeper than the slop behind
                // its plane: a ray lying in a face's plane is within rounding of it, on either side (a tilted
                // face's plane and a point on it are each a few micrometres off at 60 m).
                if (dist < r + ContactSlop)
                    return Resting(ray || overFace ? n : away, ray || overFace ? 1f : dist, d, n, out hit, ContactSlop);
            }

            if (vn < -ApproachTolerance * d.Length() && s0 + vn - r < -ContactSlop)
            {
                float t = (s0 - r) / -vn;
                var contact = c + t * d - r * n;
                if (t >= 0f && t <= 1f && (ray ? RayThrough(start, d, polygon, shift) : Inside(contact, polygon, InsideTolerance(contact))))
                {
                    best = t;
                    bestNormal = n;
                    feature = ImpactFeature.Face;
                }
            }
        }
        if (ray)
            return Found(best, bestNormal, feature, out hit);
        var v = polygon.Vertices;
        bool singleSided = polygon.Sides == PolygonSides.Single;
        // An edge or a corner is solved only when its box meets the box the centre sweeps until the best
        // contact so far (every contact that could replace it lies there): after a face contact, or beside
        // a far edge, most are not.
        EdgeReach(c, d, r, MathF.Min(best, 1f), polygon, out var reachMin, out var reachMax);
        for (int i = 0; i < v.Length; i++)
        {
            var a = v[i];
            var b = v[(i + 1) % v.Length];
            if (!EdgeMeetsBox(a, b, reachMin, reachMax))
                continue;
            if (Segment(c, d, r, a, b, out float te, out var ne) && te < best && (!singleSided || s0 + te * vn >= 0f))
            {
                best = te;
                bestNormal = ne;
                feature = ImpactFeature.Edge;
            }
            if (Point(c, d, r, a, out float tv, out var nv) && tv < best && (!singleSided || s0 + tv * vn >= 0f))
            {
                best = tv;
                bestNormal = nv;
                feature = ImpactFeature.Vertex;
            }
        }
        return Found(best, bestNormal, feature, out hit);
    }

    private static bool Found(float time, Vector3 normal, ImpactFeature feature, out ImpactHit hit)
    {
        hit = feature == ImpactFeature.None ? default : new ImpactHit(time, normal, feature);
        return feature != ImpactFeature.None;
    }

    /// <summary>
    /// The box that holds the centre of every edge or corner contact <see cref="Segment"/> and <see cref="Point"/>
    /// report at a time up to <paramref name="limit"/>, widened by the radius: the centre then lies on the sweep
    /// from <paramref name="c"/> to <c>c + limit·d</c>, within the radius of a point of the edge (its perpendicular
    /// offset is a root of the distance equation and its place along the line is checked within the segment). The
    /// margin — a centimetre plus 1e-5 of the largest coordinate, displacement and radius — is far above the
    /// rounding of those roots and of the box (a few float steps of the same magnitudes), so an edge whose box
    /// misses this one has no contact to offer: skipping it changes no answer.
    /// </summary>
    internal static void EdgeReach(Vector3 c, Vector3 d, float r, float limit, Polygon polygon, out Vector3 min, out Vector3 max)
    {
        var end = c + limit * d;
        float largest = MathF.Max(VectorMath.MaxAbs(polygon.BoxMin), VectorMath.MaxAbs(polygon.BoxMax));
        var grow = new Vector3(r + 0.01f + 1e-5f * (largest + VectorMath.MaxAbs(c) + VectorMath.MaxAbs(d) + r));
        min = Vector3.Min(c, end) - grow;
        max = Vector3.Max(c, end) + grow;
    }

    /// <summary>Whether the box of the edge from <paramref name="a"/> to <paramref name="b"/> meets the box from <paramref name="min"/> to <paramref name="max"/>.</summary>
    internal static bool EdgeMeetsBox(Vector3 a, Vector3 b, Vector3 min, Vector3 max) =>
        VectorMath.BoxesMeet(Vector3.Min(a, b), Vector3.Max(a, b), min, max);

    /// <summary>
    /// How much nearer than its plane a point can be to a polygon, with rounding: a vertex may lie off the plane
    /// through vertex 0 by twice the flatness a polygon is accepted with (1 mm plus a millionth of its largest
    /// coordinate each way), and the distances are rounded at the scale of the point's and the polygon's
    /// coordinates (a few float steps). A centimetre plus ten millionths of those coordinates is far above both.
    /// </summary>
    private static float RestingMargin(Vector3 c, Polygon polygon)
    {
        float largest = MathF.Max(VectorMath.MaxAbs(polygon.BoxMin), VectorMath.MaxAbs(polygon.BoxMax));
        return 0.01f + 1e-5f * (largest + VectorMath.MaxAbs(c));
    }


    /// <summary>
    /// Time of impact with a solid world-Z cylinder (retail CylSphere: low point, radius, height): the
    /// side and caps analytically, the rims (a torus, a quartic) by conservative advancement on the exact
    /// distance to within 1e-6 m.
    /// </summary>
    public static bool Cylinder(Vector3 c, Vector3 d, float r, in CylSphere cylinder, out ImpactHit hit)
    {
        hit = default;
        var low = cylinder.LowPoint;
        float top = low.Z + cylinder.Height;
        float radius = cylinder.Radius;
        var closest = ClosestPointOnCylinder(c, cylinder);
        var away = c - closest;
        float dist = away.Length();
        if (dist < r + ContactSlop)
            return Resting(away, dist, d, Vector3.UnitZ, out hit);

        float best = float.PositiveInfinity;
        var bestNormal = Vector3.Zero;
        var feature = ImpactFeature.None;

        // Side: the 2-D circle of radius R + r while the centre's height is within the cylinder's.
        var m2 = new Vector2(c.X - low.X, c.Y - low.Y);
        var d2 = new Vector2(d.X, d.Y);
        float reach = radius + r;
        float qa = Vector2.Dot(d2, d2), qb = Vector2.Dot(m2, d2), qc = Vector2.Dot(m2, m2) - reach * reach;
        if (qa > 0f && qc >= 0f && qb < 0f)
        {
            float disc = qb * qb - qa * qc;
            if (disc >= 0f)
            {
                float t = (-qb - MathF.Sqrt(disc)) / qa;
                float z = c.Z + t * d.Z;
                if (t >= 0f && t <= 1f && z >= low.Z && z <= top)
                {
                    var p2 = Vector2.Normalize(m2 + t * d2);
                    best = t;
                    bestNormal = new Vector3(p2, 0f);
                    feature = ImpactFeature.CylinderSide;
                }
            }
        }
        // Caps: planes r above the top and r below the bottom, within the disc.
        if (d.Z < 0f && c.Z >= top + r)
            TryCap(c, d, (c.Z - (top + r)) / -d.Z, low, radius, Vector3.UnitZ, ref best, ref bestNormal, ref feature);
        if (d.Z > 0f && c.Z <= low.Z - r)
            TryCap(c, d, ((low.Z - r) - c.Z) / d.Z, low, radius, -Vector3.UnitZ, ref best, ref bestNormal, ref feature);

        // Rims: conservative advancement (the distance to a convex solid is 1-Lipschitz along the path).
        float speed = d.Length();
        if (speed > 0f)
        {
            float limit = MathF.Min(best, 1f);
            float t = 0f;
            for (int i = 0; i < 200 && t < limit; i++)
            {
                var p = c + t * d;
                var q = ClosestPointOnCylinder(p, cylinder);
                float gap = Vector3.Distance(p, q) - r;
                if (gap <= 1e-6f)
                {
                    if (t < best - 1e-6f)
                    {
                        best = t;
                        bestNormal = Vector3.Normalize(p - q);
                        feature = ImpactFeature.CylinderRim;
                    }
                    break;
                }
                t += gap / speed;
            }
        }
        if (feature == ImpactFeature.None)
            return false;
        hit = new ImpactHit(best, bestNormal, feature);
        return true;
    }

    private static void TryCap(Vector3 c, Vector3 d, float t, Vector3 low, float radius, Vector3 normal,
        ref float best, ref Vector3 bestNormal, ref ImpactFeature feature)
    {
        if (t < 0f || t > 1f || t >= best)
            return;
        var p = c + t * d;
        float dx = p.X - low.X, dy = p.Y - low.Y;
        if (dx * dx + dy * dy > radius * radius)
            return;
        best = t;
        bestNormal = normal;
        feature = ImpactFeature.CylinderCap;
    }

    /// <summary>A touching sphere: a hit at t = 0 when it moves into the shape (by more than <paramref name="minDepth"/> over the sweep), none otherwise.</summary>
    private static bool Resting(Vector3 away, float dist, Vector3 d, Vector3 fallbackNormal, out ImpactHit hit, float minDepth = 0f)
    {
        var normal = dist > 1e-7f ? away / dist : fallbackNormal;
        float into = Vector3.Dot(normal, d);
        if (into < -ApproachTolerance * d.Length() && into < -minDepth)
        {
            hit = new ImpactHit(0f, normal, ImpactFeature.Resting);
            return true;
        }
        hit = default;
        return false;
    }

    /// <summary>Whether a point on (or near) a convex polygon's plane projects inside it, with a tolerance in metres.</summary>
    public static bool Inside(Vector3 p, Polygon polygon, float tolerance = 0f)
    {
        var n = polygon.Plane.Normal;
        var v = polygon.Vertices;
        for (int i = 0; i < v.Length; i++)
        {
            var edge = v[(i + 1) % v.Length] - v[i];
            var inward = Vector3.Cross(n, edge);
            float len = inward.Length();
            if (Vector3.Dot(inward, p - v[i]) < -tolerance * len)
                return false;
        }
        return true;
    }

    /// <summary>
    /// Whether a ray from <paramref name="c"/> along <paramref name="d"/> passes through a convex polygon
    /// (placed <paramref name="shift"/> from the ray's frame), edges and corners included, watertight: every
    /// corner is projected along the ray onto a plane across it (a shear, as in Woop, Benthin and Wald's
    /// watertight ray/triangle test), and the ray passes through when the 2-D cross products of consecutive
    /// corners all have one sign. A corner's projection is the same number in every polygon that shares it
    /// (terrain corners shift exactly between landblocks), so the cross product of a shared edge is exactly
    /// negated in the neighbour and a ray through an edge or a corner passes through one of the polygons
    /// around it whatever the rounding. (Testing the plane's crossing point instead let shallow rays through
    /// the seams of terrain: the two planes' rounding moved their crossing points up to a millimetre apart,
    /// each outside its own triangle.)
    /// </summary>
    private static bool RayThrough(Vector3 c, Vector3 d, Polygon polygon, Vector3 shift)
    {
        float ax = MathF.Abs(d.X), ay = MathF.Abs(d.Y), az = MathF.Abs(d.Z);
        int kz = az >= ax && az >= ay ? 2 : ay >= ax ? 1 : 0;
        float dz = Component(d, kz);
        float sx = Component(d, (kz + 1) % 3) / dz, sy = Component(d, (kz + 2) % 3) / dz;
        var v = polygon.Vertices;
        var first = Project(v[0] + shift - c, kz, sx, sy);
        var previous = first;
        bool below = false, above = false;
        for (int i = 1; i <= v.Length; i++)
        {
            var next = i < v.Length ? Project(v[i] + shift - c, kz, sx, sy) : first;
            float side = previous.X * next.Y - previous.Y * next.X;
            below |= side < 0f;
            above |= side > 0f;
            previous = next;
        }
        return !(below && above);
    }

    private static Vector2 Project(Vector3 p, int kz, float sx, float sy)
    {
        float z = Component(p, kz);
        return new Vector2(Component(p, (kz + 1) % 3) - sx * z, Component(p, (kz + 2) % 3) - sy * z);
    }

    private static float Component(Vector3 v, int k) => k == 0 ? v.X : k == 1 ? v.Y : v.Z;

    /// <summary>
    /// How far outside a polygon's edges a face contact still counts: 1 µm plus four float steps of the
    /// contact's largest coordinate, the rounding of the contact point itself (at 200 m from the frame's
    /// origin a float step is 15 µm, so a fixed 1 µm let a ray through the seam of two terrain triangles).
    /// </summary>
    private static float InsideTolerance(Vector3 p) =>
        1e-6f + 4.8e-7f * VectorMath.MaxAbs(p);

    /// <summary>The point of a convex polygon closest to <paramref name="p"/>.</summary>
    public static Vector3 ClosestPointOnPolygon(Vector3 p, Polygon polygon)
    {
        var plane = polygon.Plane;
        var projected = p - (Vector3.Dot(plane.Normal, p) + plane.D) * plane.Normal;
        if (Inside(projected, polygon))
            return projected;
        var v = polygon.Vertices;
        var best = v[0];
        float bestDist = float.PositiveInfinity;
        for (int i = 0; i < v.Length; i++)
        {
            var q = ClosestPointOnSegment(p, v[i], v[(i + 1) % v.Length]);
            float dist = Vector3.DistanceSquared(p, q);
            if (dist < bestDist)
            {
                bestDist = dist;
                best = q;
            }
        }
        return best;
    }

    /// <summary>The point of a segment closest to <paramref name="p"/>.</summary>
    public static Vector3 ClosestPointOnSegment(Vector3 p, Vector3 a, Vector3 b)
    {
        var e = b - a;
        float l2 = Vector3.Dot(e, e);
        if (l2 <= 0f)
            return a;
        float s = Math.Clamp(Vector3.Dot(p - a, e) / l2, 0f, 1f);
        return a + s * e;
    }

    /// <summary>The point of a solid world-Z cylinder closest to <paramref name="p"/>.</summary>
    public static Vector3 ClosestPointOnCylinder(Vector3 p, in CylSphere cylinder)
    {
        var low = cylinder.LowPoint;
        float dx = p.X - low.X, dy = p.Y - low.Y;
        float rho = MathF.Sqrt(dx * dx + dy * dy);
        float k = rho > cylinder.Radius ? cylinder.Radius / rho : 1f;
        return new Vector3(low.X + dx * k, low.Y + dy * k, Math.Clamp(p.Z, low.Z, low.Z + cylinder.Height));
    }
}
