using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// How far along a straight stretch a viewer sphere that starts in a cell provably touches nothing and stays
/// that cell's only cell (not retail; the camera arm's skip, see <see cref="Transition"/>'s viewer
/// sub-steps): indoors here, outdoors in <see cref="ClearFractionOutdoors"/>. The test is conservative: every obstacle's "might matter" zone is widened by
/// <see cref="Margin"/> (far above float rounding of the coordinates and of the walked sub-steps' sums),
/// and any doubt shortens the stretch. For each sphere centre on the cleared part of the segment:
/// <list type="bullet">
/// <item>no polygon of the cell's physics BSP lies within the radius (retail's polygon tests need the
/// sphere, shrunk by EPSILON, to reach the polygon), judged by the polygon's plane band and widened box;</item>
/// <item>no shape the viewer would test of an object listed in the cell has the box its test needs the
/// sphere to meet within the radius (see <see cref="FirstNearObject"/>);</item>
/// <item>the cell search (find_cell_list) lists only the cell and finds the centre in it: the centre is in
/// front of every split of the cell's containment chain, the sphere stays off the plane of every portal
/// to the outside, and a split of every neighbour's containment chain has the sphere outside it.</item>
/// </list>
/// Then a sub-step there inserts into the cell, finds nothing and is accepted: its only effect is the
/// check position moving by the sub-step.
/// </summary>
internal static class ViewerClearance
{
    /// <summary>How much farther than the sphere's radius an obstacle must stay (1 cm).</summary>
    public const float Margin = 0.01f;

    /// <summary>
    /// The drift allowed between the ideal sub-step centres (start + i × sub-step) and the sums a walk
    /// would compute in float, well inside <see cref="Margin"/>.
    /// </summary>
    public const float DriftBudget = 0.004f;

    /// <summary>Beyond this coordinate magnitude the float rounding is no longer negligible beside the margin: nothing is skipped.</summary>
    public const float MaxCoordinate = 4096f;

    // Retail sphere_intersects_cell_bsp grows the sphere by this much (BspNodeQuery.SphereIntersectsCellBsp).
    private const float CellBspGrowth = 0.01f;

    /// <summary>
    /// The fraction of the segment <paramref name="a"/>→<paramref name="b"/> (landblock space of
    /// <paramref name="cell"/>) before which a sphere of <paramref name="radius"/> is clear in the sense
    /// above; <see cref="float.PositiveInfinity"/> when the whole segment is. <paramref name="cellAlone"/> is
    /// the fraction before which the third condition alone holds (the cell search lists only the cell and
    /// finds the centre in it), whatever the polygons and objects; infinity when the whole segment.
    /// </summary>
    public static float ClearFraction(CellGraph cells, ShadowObjectRegistry objects, EnvCell cell, Vector3 a, Vector3 b, float radius, ObjectInfo mover, out float cellAlone)
    {
        float reach = radius + Margin;
        var la = cell.ToLocal(a);
        var lb = cell.ToLocal(b);
        float limit = StaysInFront(cell.CellBsp, la, lb);
        cellAlone = 0f;
        foreach (var portal in cell.Portals)
        {
            if (limit <= 0f)
                return 0f;
            if (portal.LeadsOutside)
            {
                // find_cell_list adds the outside cells when a sphere is within radius + EPSILON of the plane.
                var plane = portal.Polygon.Plane;
                float band = reach + PhysicsConstants.Epsilon;
                limit = MathF.Min(limit, FirstWithin(VectorMath.Distance(plane, la), VectorMath.Distance(plane, lb), -band, band));
            }
            else if (cells.Get(portal.OtherCellId) is EnvCell other)
            {
                var shift = LandDefs.BlockOffset(cell.Id, other.Id);
                limit = MathF.Min(limit, FirstNotOutside(other, other.ToLocal(a - shift), other.ToLocal(b - shift), reach + CellBspGrowth));
            }
        }
        cellAlone = MathF.Max(limit, 0f);
        if (limit > 0f && cell.PhysicsBsp is { } bsp)
            limit = MathF.Min(limit, FirstNearPolygon(bsp, la, lb, reach, limit));
        if (limit > 0f)
            limit = MathF.Min(limit, FirstNearObject(objects.ObjectsInCell(cell.Id), cell.Id, mover, a, b, reach));
        return MathF.Max(limit, 0f);
    }

    /// <summary>
    /// <see cref="ClearFraction"/> for a path starting in an outdoor cell without a building: the cell search
    /// (add_all_outside_cells) lists only the cell under the centre while the centre stays more than the radius
    /// inside the cell's square on both axes (check_add_cell_boundary), here the grown radius; the viewer's arm
    /// of validate_walkable finds nothing while the sphere's bottom stays above the terrain's plane (here the
    /// grown sphere above both triangles' planes, whichever is under it); the cell's objects as indoors. The
    /// caller checks that each passed-over centre lies on the cell's triangles (the cell holds it).
    /// </summary>
    public static float ClearFractionOutdoors(ShadowObjectRegistry objects, LandCell cell, Vector3 a, Vector3 b, float radius, ObjectInfo mover)
    {
        if (cell.Building is not null)
            return 0f;
        float reach = radius + Margin;
        var corner = LandDefs.LandCellCorner(cell.Id);
        const float size = PhysicsConstants.LandCellLength;
        float limit = MathF.Min(FirstOutside(a.X, b.X, corner.X + reach, corner.X + size - reach),
            FirstOutside(a.Y, b.Y, corner.Y + reach, corner.Y + size - reach));
        var (first, second) = cell.Triangles;
        limit = MathF.Min(limit, FirstWithin(VectorMath.Distance(first.Plane, a), VectorMath.Distance(first.Plane, b), float.NegativeInfinity, reach));
        limit = MathF.Min(limit, FirstWithin(VectorMath.Distance(second.Plane, a), VectorMath.Distance(second.Plane, b), float.NegativeInfinity, reach));
        if (limit > 0f)
            limit = MathF.Min(limit, FirstNearObject(objects.ObjectsInCell(cell.Id), cell.Id, mover, a, b, reach));
        return MathF.Max(limit, 0f);
    }

    /// <summary>The first fraction of [0, 1] at which v0 + t (v1 − v0) is outside [lo, hi]; infinity when it never is.</summary>
    private static float FirstOutside(float v0, float v1, float lo, float hi)
    {
        float enter = 0f, exit = 1f;
        Within(v0, v1, lo, hi, ref enter, ref exit);
        if (!(enter <= 0f && enter <= exit))
            return 0f;
        return exit >= 1f ? float.PositiveInfinity : exit;
    }

    /// <summary>
    /// Retail point_in_cell asks every split of the containment chain to have the point no more than EPSILON
    /// behind it: the first fraction at which the centre comes nearer than <see cref="Margin"/> in front of a
    /// split. A leaf's zero plane (distance exactly its D everywhere) is judged as retail judges it.
    /// </summary>
    private static float StaysInFront(BspTree tree, Vector3 la, Vector3 lb)
    {
        var nodes = tree.NodeArray;
        float first = float.PositiveInfinity;
        for (int index = 0; index >= 0; index = nodes[index].Front)
        {
            var plane = nodes[index].SplitPlane;
            if (plane.Normal == Vector3.Zero)
            {
                if (!(plane.D >= -PhysicsConstants.Epsilon))
                    return 0f;
                continue;
            }
            first = MathF.Min(first, FirstWithin(VectorMath.Distance(plane, la), VectorMath.Distance(plane, lb), float.NegativeInfinity, Margin));
        }
        return first;
    }

    /// <summary>
    /// Retail sphere_intersects_cell_bsp finds a neighbour's cell outside when the sphere lies at least its
    /// radius + 0.01 behind one split of the chain: the first fraction at which no split has the sphere that
    /// far behind (the covered stretches, each a run of fractions from one split, are chained from 0).
    /// </summary>
    private static float FirstNotOutside(EnvCell other, Vector3 la, Vector3 lb, float reach)
    {
        var nodes = other.CellBsp.NodeArray;
        float covered = 0f;
        bool grew = true;
        for (int pass = 0; grew && pass < nodes.Length; pass++)
        {
            grew = false;
            for (int index = 0; index >= 0; index = nodes[index].Front)
            {
                var plane = nodes[index].SplitPlane;
                float enter = 0f, exit = 1f;
                Within(VectorMath.Distance(plane, la), VectorMath.Distance(plane, lb), float.NegativeInfinity, -reach, ref enter, ref exit);
                if (enter <= covered && exit > covered)
                {
                    covered = exit;
                    grew = true;
                }
            }
            if (covered >= 1f)
                return float.PositiveInfinity;
        }
        return covered;
    }

    /// <summary>
    /// The first fraction at which the sphere, grown to <paramref name="reach"/>, may reach a polygon of the
    /// tree: inside both the polygon's plane band and its widened box. Leaves whose bounding sphere the grown
    /// sphere cannot reach before <paramref name="limit"/> are passed (retail's own tests cull by them too).
    /// </summary>
    private static float FirstNearPolygon(BspTree tree, Vector3 la, Vector3 lb, float reach, float limit)
    {
        var nodes = tree.NodeArray;
        var polygons = tree.PolygonArray;
        var indices = tree.IndexArray;
        var d = lb - la;
        for (int i = 0; i < nodes.Length; i++)
        {
            ref readonly var node = ref nodes[i];
            if (!node.IsLeaf || node.PolygonCount == 0)
                continue;
            var end = la + d * MathF.Min(limit, 1f);
            var closest = Geometry.TimeOfImpact.ClosestPointOnSegment(node.Bounds.Center, la, end);
            float far = node.Bounds.Radius + reach;
            if (Vector3.DistanceSquared(closest, node.Bounds.Center) > far * far)
                continue;
            for (int k = 0; k < node.PolygonCount; k++)
            {
                var polygon = polygons[indices[node.FirstPolygon + k]];
                float enter = 0f, exit = 1f;
                // The plane band first: it alone passes most of a room's polygons (floor, ceiling, the walls beside the arm).
                Within(VectorMath.Distance(polygon.Plane, la), VectorMath.Distance(polygon.Plane, lb), -reach, reach, ref enter, ref exit);
                if (!(enter <= exit && enter < limit))
                    continue;
                Within(la.X, lb.X, polygon.BoxMin.X - reach, polygon.BoxMax.X + reach, ref enter, ref exit);
                Within(la.Y, lb.Y, polygon.BoxMin.Y - reach, polygon.BoxMax.Y + reach, ref enter, ref exit);
                Within(la.Z, lb.Z, polygon.BoxMin.Z - reach, polygon.BoxMax.Z + reach, ref enter, ref exit);
                if (enter <= exit && enter < limit)
                    limit = enter;
            }
            if (limit <= 0f)
                return 0f;
        }
        return limit;
    }

    /// <summary>
    /// The first fraction at which the sphere, grown to <paramref name="reach"/>, may touch a shape of an
    /// object listed in the cell, by the rules of <see cref="ObjectCollisions"/>: the objects it passes
    /// untested (the mover itself, an ethereal object that ignores collisions, a creature for the viewer,
    /// a missile or PvP exemption) are left out, and of the others only the rows of the dispatched rung
    /// count, each by the box its test needs the sphere to meet: a BSP part's polygon box
    /// (<see cref="Responses.PartCollision.MayTouchPolygons"/>; its placed bounding sphere when the object is an
    /// ethereal obstruction, which that cull does not apply to), a cylinder's upright slab, a sphere's bounds,
    /// these last two as the registry's reach box takes them (<see cref="ShadowEntry.Margin"/> wider).
    /// </summary>
    private static float FirstNearObject(ShadowObjectRegistry.CellObjects objects, uint cellId, ObjectInfo mover, Vector3 a, Vector3 b, float reach)
    {
        float first = float.PositiveInfinity;
        var sweptMin = Vector3.Min(a, b) - new Vector3(reach);
        var sweptMax = Vector3.Max(a, b) + new Vector3(reach);
        uint self = mover.ObjectId;
        for (int o = 0; o < objects.Count; o++)
        {
            var rows = objects.RowsOf(o);
            if (rows.Length == 0 || !objects.Reaches(o, sweptMin, sweptMax))
                continue;
            ref readonly var head = ref rows[0];
            var state = head.State;
            if ((head.EntityId == self && self != 0)
                || (state & (PhysicsState.Ethereal | PhysicsState.IgnoreCollisions)) == (PhysicsState.Ethereal | PhysicsState.IgnoreCollisions)
                || ((mover.State & ObjectInfoState.IsViewer) != 0 && (head.Flags & ShadowFlags.IsCreature) != 0))
                continue;
            bool ethereal = (state & PhysicsState.Ethereal) != 0 || ((state & PhysicsState.Static) == 0 && mover.Ethereal);
            bool exemption = ObjectCollisions.PvpExemption(mover.State, head.Flags);
            bool missileIgnore = ObjectCollisions.MissileIgnore(mover, head.EntityId, state, head.Flags);
            ShadowShapeKind rung;
            if (ObjectCollisions.BspOnlyDispatch(state, missileIgnore, exemption))
                rung = ShadowShapeKind.Bsp;
            else if (missileIgnore || exemption)
                continue;
            else
                rung = head.CylSphereCount > 0 ? ShadowShapeKind.Cylinder : ShadowShapeKind.Sphere;
            foreach (ref readonly var row in rows)
            {
                if (row.Kind != rung)
                    continue;
                Vector3 min, max;
                if (rung == ShadowShapeKind.Bsp && !ethereal)
                {
                    var shift = LandDefs.BlockOffset(cellId, row.PartPosition.CellId);
                    (min, max) = (row.PolygonsMin + shift, row.PolygonsMax + shift);
                }
                else
                {
                    var shift = LandDefs.BlockOffset(cellId, row.Position.CellId);
                    var margin = ShadowEntry.Margin(row.Scale);
                    if (rung == ShadowShapeKind.Cylinder)
                    {
                        var cyl = row.Shape.Cylinder;
                        var low = row.PlacedPoint + shift;
                        min = low - new Vector3(cyl.Radius, cyl.Radius, 0) - margin;
                        max = low + new Vector3(cyl.Radius, cyl.Radius, cyl.Height) + margin;
                    }
                    else
                    {
                        var bounds = row.Shape.Bounds;
                        var centre = row.Position.LocalToGlobal(bounds.Center) + shift;
                        min = centre - new Vector3(bounds.Radius) - margin;
                        max = centre + new Vector3(bounds.Radius) + margin;
                    }
                }
                float enter = 0f, exit = 1f;
                Within(a.X, b.X, min.X - reach, max.X + reach, ref enter, ref exit);
                Within(a.Y, b.Y, min.Y - reach, max.Y + reach, ref enter, ref exit);
                Within(a.Z, b.Z, min.Z - reach, max.Z + reach, ref enter, ref exit);
                if (enter <= exit)
                    first = MathF.Min(first, enter);
            }
        }
        return first;
    }

    /// <summary>The first fraction of [0, 1] at which v0 + t (v1 − v0) lies within [lo, hi]; infinity when none does.</summary>
    private static float FirstWithin(float v0, float v1, float lo, float hi)
    {
        float enter = 0f, exit = 1f;
        Within(v0, v1, lo, hi, ref enter, ref exit);
        return enter <= exit ? enter : float.PositiveInfinity;
    }

    /// <summary>Narrows [enter, exit] to the fractions t at which v0 + t (v1 − v0) lies within [lo, hi] (empty: enter &gt; exit).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Within(float v0, float v1, float lo, float hi, ref float enter, ref float exit)
    {
        float dv = v1 - v0;
        if (dv == 0f)
        {
            if (!(v0 >= lo && v0 <= hi))
                (enter, exit) = (1f, 0f);
            return;
        }
        float t0 = (lo - v0) / dv, t1 = (hi - v0) / dv;
        enter = MathF.Max(enter, MathF.Min(t0, t1));
        exit = MathF.Min(exit, MathF.Max(t0, t1));
    }
}
