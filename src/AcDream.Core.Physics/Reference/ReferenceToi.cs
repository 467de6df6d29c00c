using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Reference;

/// <summary>Which feature of a shape a swept sphere touched first.</summary>
public enum ReferenceFeature : byte
{
    /// <summary>No contact.</summary>
    None = 0,
    /// <summary>The sphere already touched the shape and was moving into it (time 0).</summary>
    Resting,
    /// <summary>A polygon's face (its interior).</summary>
    Face,
    /// <summary>A polygon's edge.</summary>
    Edge,
    /// <summary>A polygon's vertex.</summary>
    Vertex,
    /// <summary>A cylinder's curved side.</summary>
    CylinderSide,
    /// <summary>A cylinder's top or bottom disc.</summary>
    CylinderCap,
    /// <summary>A cylinder's top or bottom rim (found by conservative advancement).</summary>
    CylinderRim,
    /// <summary>A sphere.</summary>
    Sphere,
}

/// <summary>The first contact of a swept sphere: when (fraction of the sweep), the contact normal (pointing from the shape to the sphere's centre), and the feature.</summary>
public readonly struct ReferenceHit
{
    /// <summary>Creates a hit.</summary>
    public ReferenceHit(float time, Vector3 normal, ReferenceFeature feature)
    {
        Time = time;
        Normal = normal;
        Feature = feature;
    }

    /// <summary>The fraction of the displacement travelled at first contact, in [0, 1].</summary>
    public float Time { get; }
    /// <summary>The unit contact normal, from the shape towards the sphere's centre.</summary>
    public Vector3 Normal { get; }
    /// <summary>The feature touched.</summary>
    public ReferenceFeature Feature { get; }

    /// <inheritdoc />
    public override string ToString() => $"t={Time} n={Normal} {Feature}";
}

/// <summary>
/// Exact time of impact of a sphere (centre <c>c</c>, radius <c>r</c>) moving by <c>d</c> over the sweep
/// fraction t ∈ [0, 1], against polygons (face, edges, vertices), world-Z cylinders and spheres. Not a
/// retail algorithm: the ground truth the retail sub-stepping is measured against. Every test is the
/// smallest root of the distance equation |c + t·d − shape| = r; shapes are convex, so a sphere that is
/// not approaching a shape at t = 0 never reaches it later in the same straight sweep.
/// </summary>
public static class ReferenceToi
{
    /// <summary>
    /// A sphere closer to a shape than its radius plus this slop counts as touching: it is stopped at t = 0
    /// when it moves into the shape, and ignored when it moves along or away (metres).
    /// </summary>
    public const float ContactSlop = 1e-5f;

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

    /// <summary>Time of impact with a point (a vertex), the sphere starting outside r of it.</summary>
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
        float disc = b * b - a * cc;
        if (disc < 0f)
            return false;
        t = (-b - MathF.Sqrt(disc)) / a;
        if (t < 0f || t > 1f)
            return false;
        normal = Vector3.Normalize(m + t * d);
        return true;
    }

    /// <summary>Time of impact with a segment's interior (the edge cylinder between its end points), the sphere starting outside r of the line.</summary>
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
        // |m⊥ + t d⊥|² = r², multiplied through by |e|².
        float qa = l2 * Vector3.Dot(d, d) - dd * dd;
        float qb = l2 * Vector3.Dot(m, d) - md * dd;
        float qc = l2 * (Vector3.Dot(m, m) - r * r) - md * md;
        if (qa <= 1e-12f * l2 || qc < 0f || qb >= 0f)
            return false;
        float disc = qb * qb - qa * qc;
        if (disc < 0f)
            return false;
        t = (-qb - MathF.Sqrt(disc)) / qa;
        if (t < 0f || t > 1f)
            return false;
        float s = (md + t * dd) / l2;
        if (s < 0f || s > 1f)
            return false;
        var p = c + t * d;
        var q = a + s * e;
        normal = Vector3.Normalize(p - q);
        return true;
    }

    /// <summary>Time of impact with a sphere obstacle.</summary>
    public static bool Sphere(Vector3 c, Vector3 d, float r, in Sphere obstacle, out ReferenceHit hit)
    {
        hit = default;
        var m = c - obstacle.Center;
        float dist = m.Length();
        float reach = r + obstacle.Radius;
        if (dist < reach + ContactSlop)
            return Resting(m, dist, d, Vector3.UnitZ, out hit);
        if (!Point(c, d, reach, obstacle.Center, out float t, out var n))
            return false;
        hit = new ReferenceHit(t, n, ReferenceFeature.Sphere);
        return true;
    }

    /// <summary>
    /// Time of impact with a convex polygon: its face (from the front; from either side unless
    /// <see cref="PolygonSides.Single"/>), its edges and its vertices, whichever comes first.
    /// </summary>
    public static bool Polygon(Vector3 c, Vector3 d, float r, Polygon polygon, out ReferenceHit hit)
    {
        hit = default;
        var plane = polygon.Plane;
        var n = plane.Normal;
        float s0 = Vector3.Dot(n, c) + plane.D;
        if (s0 < 0f)
        {
            if (polygon.Sides == PolygonSides.Single)
                return false;
            n = -n;
            s0 = -s0;
        }
        var closest = ClosestPointOnPolygon(c, polygon);
        var away = c - closest;
        float dist = away.Length();
        if (dist < r + ContactSlop)
            return Resting(away, dist, d, n, out hit);

        float best = float.PositiveInfinity;
        var bestNormal = Vector3.Zero;
        var feature = ReferenceFeature.None;
        float vn = Vector3.Dot(n, d);
        if (vn < 0f)
        {
            float t = (s0 - r) / -vn;
            if (t >= 0f && t <= 1f && Inside(c + t * d - r * n, polygon, 1e-6f))
            {
                best = t;
                bestNormal = n;
                feature = ReferenceFeature.Face;
            }
        }
        var v = polygon.Vertices;
        for (int i = 0; i < v.Length; i++)
        {
            var a = v[i];
            var b = v[(i + 1) % v.Length];
            if (Segment(c, d, r, a, b, out float te, out var ne) && te < best)
            {
                best = te;
                bestNormal = ne;
                feature = ReferenceFeature.Edge;
            }
            if (Point(c, d, r, a, out float tv, out var nv) && tv < best)
            {
                best = tv;
                bestNormal = nv;
                feature = ReferenceFeature.Vertex;
            }
        }
        if (feature == ReferenceFeature.None)
            return false;
        hit = new ReferenceHit(best, bestNormal, feature);
        return true;
    }

    /// <summary>
    /// Time of impact with a solid world-Z cylinder (retail CylSphere: low point, radius, height): the
    /// side and caps analytically, the rims (a torus, a quartic) by conservative advancement on the exact
    /// distance to within 1e-6 m.
    /// </summary>
    public static bool Cylinder(Vector3 c, Vector3 d, float r, in CylSphere cylinder, out ReferenceHit hit)
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
        var feature = ReferenceFeature.None;

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
                    feature = ReferenceFeature.CylinderSide;
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
                        feature = ReferenceFeature.CylinderRim;
                    }
                    break;
                }
                t += gap / speed;
            }
        }
        if (feature == ReferenceFeature.None)
            return false;
        hit = new ReferenceHit(best, bestNormal, feature);
        return true;
    }

    private static void TryCap(Vector3 c, Vector3 d, float t, Vector3 low, float radius, Vector3 normal,
        ref float best, ref Vector3 bestNormal, ref ReferenceFeature feature)
    {
        if (t < 0f || t > 1f || t >= best)
            return;
        var p = c + t * d;
        float dx = p.X - low.X, dy = p.Y - low.Y;
        if (dx * dx + dy * dy > radius * radius)
            return;
        best = t;
        bestNormal = normal;
        feature = ReferenceFeature.CylinderCap;
    }

    /// <summary>A touching sphere: a hit at t = 0 when it moves into the shape, none otherwise.</summary>
    private static bool Resting(Vector3 away, float dist, Vector3 d, Vector3 fallbackNormal, out ReferenceHit hit)
    {
        var normal = dist > 1e-7f ? away / dist : fallbackNormal;
        float into = Vector3.Dot(normal, d);
        if (into < -ApproachTolerance * d.Length())
        {
            hit = new ReferenceHit(0f, normal, ReferenceFeature.Resting);
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
