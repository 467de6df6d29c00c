using System;
using System.Numerics;

namespace AcDream.Core.Physics.Geometry;

/// <summary>
/// The retail polygon queries (CPolygon): sphere hits, walkable hits, point in polygon, crossed edge,
/// adjustments. All are allocation-free and work on the polygon's own (unscaled, local) space.
/// </summary>
/// <remarks>
/// Edge convention used throughout: for the edge from vertex <c>a</c> (the previous vertex) to vertex
/// <c>b</c>, <c>inward = N × (b − a)</c> points into the polygon (vertices are counter-clockwise seen from
/// the front), so a point is on the inner side of that edge when <c>(p − a)·inward ≥ 0</c>.
/// Retail ignores the polygon's sidedness in every sphere test; only <see cref="PolygonHitsRay"/> reads it.
/// </remarks>
internal static class PolygonQuery
{
    private const float Epsilon = PhysicsConstants.Epsilon;

    /// <summary>Signed distance of <paramref name="point"/> from the polygon's plane.</summary>
    private static float PlaneDistance(Polygon polygon, Vector3 point)
    {
        var plane = polygon.Plane;
        return VectorMath.Dot(plane.Normal, point) + plane.D;
    }

    /// <summary>
    /// The sphere centre moved along <paramref name="up"/> onto the polygon's plane, as retail's
    /// check_walkable, check_small_walkable and find_crossed_edge project it (acclient.c:360226, :360311,
    /// :360396): the distance over N·up is a double on the x87 stack, and the centre moves as
    /// <see cref="MoveBack"/> moves it. False when the plane is parallel to <paramref name="up"/>
    /// (|N·up| &lt; EPSILON).
    /// </summary>
    private static bool ProjectAlongUp(Polygon polygon, Vector3 center, Vector3 up, out Vector3 point)
    {
        var n = polygon.Plane.Normal;
        double upDot = (double)n.Y * up.Y + (double)n.Z * up.Z + (double)up.X * n.X;
        point = center;
        if (Math.Abs(upDot) < Epsilon)
            return false;
        double along = ((double)n.Z * center.Z + (double)n.Y * center.Y + (double)center.X * n.X + polygon.Plane.D) / upDot;
        point = MoveBack(center, along, up);
        return true;
    }

    /// <summary>
    /// <paramref name="point"/> − <paramref name="k"/>·<paramref name="v"/> as retail's x87 code evaluates it
    /// where it moves a sphere centre (check_walkable, find_crossed_edge, adjust_sphere_to_plane): X by the
    /// double product, Y and Z by products first stored as floats.
    /// </summary>
    private static Vector3 MoveBack(Vector3 point, double k, Vector3 v) =>
        new((float)(point.X - k * v.X), point.Y - (float)(k * v.Y), point.Z - (float)(k * v.Z));

    /// <summary>
    /// The single-pass edge walk shared by retail polygon_hits_sphere, check_walkable and
    /// check_small_walkable: true when a disc of squared radius <paramref name="radiusSquared"/> around
    /// <paramref name="point"/> (a point in the polygon's plane) touches the polygon.
    /// Retail quirk (acclient.c:359915): an edge whose outer side holds the point but whose span misses
    /// its foot only marks the result false; a later vertex within the disc still returns true, and an
    /// outside point that no test rejects is reported as a hit when the walk ends.
    /// </summary>
    private static bool DiscTouchesSinglePass(Polygon polygon, Vector3 point, float radiusSquared)
    {
        var vertices = polygon.Vertices;
        var normal = polygon.Plane.Normal;
        bool result = true;
        int previous = vertices.Length - 1;
        for (int i = 0; i < vertices.Length; i++)
        {
            var start = vertices[previous];
            previous = i;
            var edge = vertices[i] - start;
            var offset = point - start;
            var inward = Vector3.Cross(normal, edge);
            float side = VectorMath.Dot(offset, inward);
            if (side < 0f)
            {
                // Outside this edge: too far from its line means no contact at all.
                if (VectorMath.Dot(inward, inward) * radiusSquared < side * side)
                    return false;
                float along = VectorMath.Dot(offset, edge);
                if (along >= 0f && along <= VectorMath.Dot(edge, edge))
                    return true;
                result = false;
            }
            if (VectorMath.Dot(offset, offset) <= radiusSquared)
                return true;
        }
        return result;
    }

    /// <summary>
    /// Retail CPolygon::polygon_hits_sphere, the single-pass test: true when the sphere, shrunk by
    /// <see cref="PhysicsConstants.Epsilon"/>, reaches the polygon. <paramref name="contactPoint"/> receives
    /// the sphere centre projected onto the plane whenever the plane is within reach (even on a miss,
    /// as retail writes it before the edge walk). Retail uses it only as a cross-check of the precise test.
    /// </summary>
    public static bool PolygonHitsSphere(Polygon polygon, in Sphere sphere, ref Vector3 contactPoint)
    {
        float distance = PlaneDistance(polygon, sphere.Center);
        float reach = sphere.Radius - Epsilon;
        if (reach < MathF.Abs(distance))
            return false;
        contactPoint = sphere.Center - polygon.Plane.Normal * distance;
        return DiscTouchesSinglePass(polygon, contactPoint, reach * reach - distance * distance);
    }

    /// <summary>
    /// Retail CPolygon::polygon_hits_sphere_slow_but_sure (ACE polygon_hits_sphere_precise): true when the
    /// sphere, shrunk by <see cref="PhysicsConstants.Epsilon"/>, reaches the polygon. Touching exactly at the
    /// shrunk radius counts. When the projected centre is inside every edge it is a hit; otherwise the
    /// edges are walked again, and an edge whose line is out of reach ends the test with a miss.
    /// <paramref name="contactPoint"/> receives the centre projected onto the plane whenever the plane is within reach.
    /// </summary>
    public static bool PolygonHitsSpherePrecise(Polygon polygon, in Sphere sphere, ref Vector3 contactPoint)
    {
        float distance = PlaneDistance(polygon, sphere.Center);
        float reach = sphere.Radius - Epsilon;
        if (reach < MathF.Abs(distance))
            return false;
        var normal = polygon.Plane.Normal;
        var point = sphere.Center - normal * distance;
        contactPoint = point;
        float discSquared = reach * reach - distance * distance;

        var vertices = polygon.Vertices;
        int previous = vertices.Length - 1;
        bool inside = true;
        for (int i = 0; i < vertices.Length; i++)
        {
            var start = vertices[previous];
            previous = i;
            if (VectorMath.Dot(point - start, Vector3.Cross(normal, vertices[i] - start)) < 0f)
            {
                inside = false;
                break;
            }
        }
        if (inside)
            return true;

        // Second pass: the point is outside some edge; find an edge or vertex within the disc. This is the
        // single-pass walk: with the point outside an edge, a walk that ends without deciding is a miss.
        return DiscTouchesSinglePass(polygon, point, discSquared);
    }

    /// <summary>Retail CPolygon::hits_sphere: the precise test without a contact point.</summary>
    public static bool HitsSphere(Polygon polygon, in Sphere sphere)
    {
        var contact = Vector3.Zero;
        return PolygonHitsSpherePrecise(polygon, sphere, ref contact);
    }

    /// <summary>
    /// Retail CPolygon::pos_hits_sphere: the precise hit, counted only when the sphere moves into the
    /// polygon's front (<c>movement·N &lt; 0</c>). Retail quirk (acclient.c:360493): a geometric hit sets
    /// <paramref name="struckPolygon"/> even when the direction gate then rejects it; find_collisions uses
    /// that "grazed from behind" polygon for its negative-polygon handling.
    /// </summary>
    public static bool PosHitsSphere(Polygon polygon, in Sphere sphere, Vector3 movement, ref Vector3 contactPoint, ref Polygon? struckPolygon)
    {
        bool hit = PolygonHitsSpherePrecise(polygon, sphere, ref contactPoint);
        if (hit)
            struckPolygon = polygon;
        if (VectorMath.Dot(movement, polygon.Plane.Normal) >= 0f)
            return false;
        return hit;
    }

    /// <summary>
    /// Retail CPolygon::walkable_hits_sphere: true when the polygon faces up enough
    /// (<c>N·up &gt; walkableAllowance</c>, strictly) and the sphere hits it (precise test). Retail also runs
    /// the single-pass test and, when the two disagree, runs both again for a debugger; that has no effect
    /// and is left out.
    /// </summary>
    public static bool WalkableHitsSphere(Polygon polygon, in Sphere sphere, Vector3 up, float walkableAllowance)
    {
        if (!(VectorMath.Dot(polygon.Plane.Normal, up) > walkableAllowance))
            return false;
        return HitsSphere(polygon, sphere);
    }

    /// <summary>
    /// Retail check_walkable / check_small_walkable: projects the sphere centre along <paramref name="up"/>
    /// onto the polygon's plane and tells whether a disc of the sphere's radius there (half the radius when
    /// <paramref name="small"/>) touches the polygon, i.e. the polygon still holds the mover. False when the
    /// plane is parallel to <paramref name="up"/> (|N·up| &lt; EPSILON; retail tests the absolute value, ACE does not).
    /// </summary>
    public static bool CheckWalkable(Polygon polygon, in Sphere sphere, Vector3 up, bool small)
    {
        if (!ProjectAlongUp(polygon, sphere.Center, up, out var point))
            return false;
        float radiusSquared = sphere.Radius * sphere.Radius;
        if (small)
            radiusSquared *= 0.25f;
        return DiscTouchesSinglePass(polygon, point, radiusSquared);
    }

    /// <summary>Retail check_small_walkable: <see cref="CheckWalkable"/> with a half-radius disc.</summary>
    public static bool CheckSmallWalkable(Polygon polygon, in Sphere sphere, Vector3 up)
        => CheckWalkable(polygon, sphere, up, small: true);

    /// <summary>
    /// Retail find_crossed_edge: projects the sphere centre along <paramref name="up"/> onto the polygon's
    /// plane and returns, for the first edge (in vertex order, starting with the edge from the last vertex
    /// to vertex 0) whose outer side holds that point, the unit edge normal <c>N × edge</c> in the polygon's
    /// plane. That normal points from the crossed edge back into the polygon (retail uses it as the
    /// collision normal of a precipice slide). False when no edge was crossed or the plane is parallel to
    /// <paramref name="up"/>; <paramref name="normal"/> is then zero.
    /// </summary>
    public static bool FindCrossedEdge(Polygon polygon, in Sphere sphere, Vector3 up, out Vector3 normal)
    {
        normal = Vector3.Zero;
        var planeNormal = polygon.Plane.Normal;
        if (!ProjectAlongUp(polygon, sphere.Center, up, out var point))
            return false;
        var vertices = polygon.Vertices;
        int previous = vertices.Length - 1;
        for (int i = 0; i < vertices.Length; i++)
        {
            var start = vertices[previous];
            previous = i;
            var inward = Vector3.Cross(planeNormal, vertices[i] - start);
            if (VectorMath.Dot(point - start, inward) < 0f)
            {
                // Retail normalizes with the length and its reciprocal in double (acclient.c:360396).
                normal = VectorMath.Scale(inward, 1.0 / Math.Sqrt(VectorMath.LengthSquaredWide(inward)));
                return true;
            }
        }
        return false;
    }

    /// <summary>
    /// Retail CPolygon::point_in_polygon: true when <paramref name="point"/> (assumed in or near the plane)
    /// is on the inner side of every edge; a point exactly on an edge counts as inside.
    /// </summary>
    public static bool PointInPolygon(Polygon polygon, Vector3 point)
    {
        var vertices = polygon.Vertices;
        var normal = polygon.Plane.Normal;
        int previous = vertices.Length - 1;
        for (int i = 0; i < vertices.Length; i++)
        {
            var start = vertices[previous];
            previous = i;
            if (VectorMath.Dot(point - start, Vector3.Cross(normal, vertices[i] - start)) < 0f)
                return false;
        }
        return true;
    }

    /// <summary>
    /// Retail CPolygon::point_in_poly2D: the point-in-polygon test in the XY plane only (used for terrain).
    /// With <see cref="Sidedness.Positive"/> the point must be on the left of every edge (a polygon wound
    /// counter-clockwise seen from +Z holds it); with any other side, on the right of every edge (clockwise).
    /// Points on an edge count as inside. Retail walks the edges backwards from the last vertex; the order
    /// does not change the answer.
    /// </summary>
    public static bool PointInPoly2D(Polygon polygon, Vector3 point, Sidedness side)
    {
        var vertices = polygon.Vertices;
        var end = vertices[0];
        for (int i = vertices.Length - 1; i >= 0; i--)
        {
            var start = vertices[i];
            // Z of the 2D cross product edge × (point − start): positive when the point is left of the edge.
            float cross = (end.X - start.X) * (point.Y - start.Y) - (end.Y - start.Y) * (point.X - start.X);
            if (side == Sidedness.Positive ? cross < 0f : cross > 0f)
                return false;
            end = start;
        }
        return true;
    }

    /// <summary>
    /// Retail CPolygon::adjust_sphere_to_plane, used while stepping down: moves <paramref name="validPos"/>
    /// back along <paramref name="movement"/> until it rests tangent to the polygon's plane, on the side it
    /// comes from, and lowers <paramref name="walkInterp"/> to the fraction of the move that remains. Refused
    /// (false, nothing changed) when the move is parallel to the plane (|N·movement| ≤ EPSILON), when it would
    /// not lower <paramref name="walkInterp"/>, or when the new fraction drops below −0.5.
    /// </summary>
    public static bool AdjustSphereToPlane(Polygon polygon, ref Sphere validPos, Vector3 movement, ref float walkInterp)
    {
        // Retail evaluates this on the x87 stack at double precision (acclient.c:359533): the distance, the
        // approach, the back-off fraction and the new walk fraction stay double; the centre moves as MoveBack
        // moves it; the walk fraction is stored as a float before its lower bound is tested.
        var n = polygon.Plane.Normal;
        var c = validPos.Center;
        double distance = (double)n.Y * c.Y + (double)n.Z * c.Z + (double)c.X * n.X + polygon.Plane.D;
        double approach = (double)n.Z * movement.Z + (double)n.Y * movement.Y + (double)n.X * movement.X;
        double gap;
        if (approach <= Epsilon)
        {
            if (approach >= -Epsilon)
                return false;
            gap = distance - validPos.Radius;
        }
        else
        {
            gap = -validPos.Radius - distance;
        }
        double backOff = gap / approach;
        double interpWide = (1.0 - backOff) * walkInterp;
        float interp = (float)interpWide;
        if (interpWide >= walkInterp || interp < -0.5f)
            return false;
        validPos.Center = MoveBack(c, backOff, movement);
        walkInterp = interp;
        return true;
    }

    /// <summary>
    /// Retail CPolygon::adjust_sphere_to_poly: the fraction of <paramref name="movement"/>, from
    /// <paramref name="currPos"/>, at which a sphere of <paramref name="checkPos"/>'s radius becomes tangent to
    /// the polygon's plane. Returns exactly 1 when the start is already closer to the plane than the radius
    /// and 0 when the move is parallel to it (|N·movement| &lt; EPSILON).
    /// Retail quirk: the decompile lost the comparison that flips the radius's sign (acclient.c:359497,
    /// bare x87 flags); ACE recovers it as "the move is no longer than the radius", kept here.
    /// </summary>
    public static float AdjustSphereToPoly(Polygon polygon, in Sphere checkPos, Vector3 currPos, Vector3 movement)
    {
        float distance = PlaneDistance(polygon, currPos);
        if (checkPos.Radius > MathF.Abs(distance))
            return 1f;
        float approach = Vector3.Dot(movement, polygon.Plane.Normal);
        if (MathF.Abs(approach) < Epsilon)
            return 0f;
        float target = checkPos.Radius;
        if (movement.LengthSquared() <= target * target)
            target = -target;
        return (target - distance) / approach;
    }

    /// <summary>
    /// Retail CPolygon::adjust_to_placement_poly: pushes <paramref name="struck"/> (and
    /// <paramref name="other"/>, the mover's other sphere, by the same amount) along the polygon's normal so
    /// that its centre ends <paramref name="radius"/> from the plane. Without <paramref name="solidCheck"/>
    /// the target is always the front; with it, the target side flips once when the centre is in solid and
    /// once more when the centre is on or behind the plane.
    /// Retail quirk (acclient.c:360136): the two flips cancel, so a centre both in solid and behind the
    /// plane is pushed to the front. ACE negates once when either holds; retail is kept.
    /// </summary>
    public static void AdjustToPlacementPoly(Polygon polygon, ref Sphere struck, ref Sphere other, float radius, bool centerSolid, bool solidCheck)
    {
        float distance = PlaneDistance(polygon, struck.Center);
        float target = radius;
        if (solidCheck)
        {
            if (centerSolid)
                target = -target;
            if (distance <= 0f)
                target = -target;
        }
        var push = polygon.Plane.Normal * (target - distance);
        struck.Center += push;
        other.Center += push;
    }

    /// <summary>
    /// Retail Plane::compute_time_of_intersection: the ray parameter where it meets the plane; false when
    /// the ray is parallel (|dir·N| &lt; EPSILON) or the plane is behind the origin (time &lt; 0).
    /// </summary>
    public static bool ComputeTimeOfIntersection(in Plane plane, Vector3 origin, Vector3 direction, out float time)
    {
        time = 0f;
        float approach = Vector3.Dot(direction, plane.Normal);
        if (MathF.Abs(approach) < Epsilon)
            return false;
        time = (Vector3.Dot(origin, plane.Normal) + plane.D) * (-1f / approach);
        return time >= 0f;
    }

    /// <summary>
    /// Retail CPolygon::polygon_hits_ray: true when the ray from <paramref name="origin"/> along
    /// <paramref name="direction"/> meets the polygon; <paramref name="time"/> is the ray parameter of the
    /// plane crossing. A single-sided polygon is hit only from its front (dir·N ≤ 0); double-sided ones from
    /// both sides. The only polygon query that reads the sidedness.
    /// </summary>
    public static bool PolygonHitsRay(Polygon polygon, Vector3 origin, Vector3 direction, out float time)
    {
        time = 0f;
        if (polygon.Sides == PolygonSides.Single && Vector3.Dot(direction, polygon.Plane.Normal) > 0f)
            return false;
        if (!ComputeTimeOfIntersection(polygon.Plane, origin, direction, out time))
            return false;
        return PointInPolygon(polygon, origin + direction * time);
    }
}
