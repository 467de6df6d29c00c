using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Queries;

/// <summary>
/// The questions a client asks the world besides "resolve this move": the floor under a point, the cell
/// that holds a point, the objects overlapping a sphere or a box, the first contact of a swept sphere or
/// a ray, and the retail camera arm. Positions are retail <see cref="Position"/>s: the cell id names the
/// landblock frame of the coordinates (the cell need not hold the point, but must be in the world), and
/// every result is given in that frame.
/// One query object per thread, like <see cref="PhysicsEngine"/>: it reuses its scratch lists and
/// allocates nothing per call once warm. Any number of query objects and engines may share a world while
/// nobody modifies it (see docs/robustness.md, thread safety). Bad input throws
/// <see cref="ArgumentException"/> naming the field.
/// </summary>
public sealed class WorldQuery
{
    /// <summary>The camera sphere's radius: 0.3 m, centred on the camera (retail viewer_sphere, set up in SmartBox's constructor, acclient.c:145543).</summary>
    public const float ViewerRadius = 0.3f;

    /// <summary>
    /// Retail's camera object-info bits (SmartBox::update_viewer calls init_object(player, 92), acclient.c:145086):
    /// IsViewer | PathClipped | FreeRotate | PerfectClip — stop at the first contact, exactly at it.
    /// </summary>
    public const ObjectInfoState ViewerFlags = ObjectInfoState.IsViewer | ObjectInfoState.PathClipped | ObjectInfoState.FreeRotate | ObjectInfoState.PerfectClip;

    private readonly List<Cell> _cells = new(32);
    private readonly CellArray _cellArray = new();
    // The objects a cast has swept (their ids, the first _sweptCount entries): an object listed in several
    // of its cells (a door across a doorway's portal) is swept once. A second sweep of the same rows could
    // only tie or trail the first, and the first found wins a tie, so skipping it changes no answer. A cast
    // sweeps a handful of objects, so a scan of a flat array beats a hash set's hashing and buckets; it
    // grows (doubling) only when a cast sweeps more objects than ever before.
    private uint[] _swept = new uint[16];
    private int _sweptCount;
    private readonly PhysicsEngine _viewer;
    private MoverDescription? _viewerMover;
    private int _landCount;

    /// <summary>Creates a query object over a world.</summary>
    public WorldQuery(PhysicsWorld world) : this(world, ShortcutSettings.Default) { }

    /// <summary>
    /// Creates a query object whose camera arm takes <paramref name="shortcuts"/> (<see cref="Shortcuts.None"/>:
    /// every sub-step walked, as retail) and reports to <paramref name="observer"/>.
    /// </summary>
    internal WorldQuery(PhysicsWorld world, Shortcuts shortcuts, Diagnostics.ITransitionObserver? observer = null)
    {
        World = world ?? throw new ArgumentNullException(nameof(world));
        _viewer = new PhysicsEngine(world, shortcuts) { Observer = observer };
    }

    /// <summary>The world asked.</summary>
    public PhysicsWorld World { get; }

    /// <summary>
    /// The first contact of a sphere of <paramref name="radius"/> swept from <paramref name="from"/> to
    /// <paramref name="to"/> (same frame) against what <paramref name="layers"/> selects: terrain, indoor
    /// cells' physics BSPs and buildings' shells (the cells along the way, through buildings' doorways and
    /// indoor portals), and the objects listed in those cells by their dispatch rung (an object with
    /// <see cref="PhysicsState.HasPhysicsBsp"/> by its parts' BSPs only, else its cylspheres, else its
    /// spheres — the shapes a mover collides with). Exact times of impact, no sub-steps. Faces count from
    /// their front only, so a cast starting inside an object passes out of it; a sphere already touching
    /// a surface hits it at fraction 0 when it moves into it. Radius 0 is a ray.
    /// </summary>
    /// <returns>True when something was hit; <paramref name="hit"/> is the earliest contact.</returns>
    public bool SphereCast(in Position from, Vector3 to, float radius, out SurfaceHit hit, QueryLayers layers = QueryLayers.Solid, uint ignoreObjectId = 0)
    {
        CheckPosition(from, "from.origin", "from.cell");
        Guard.Finite(to, "to");
        Guard.Extent(radius, true, "radius");
        return Cast(from, to - from.Origin, radius, walkableOnly: false, layers, ignoreObjectId, out hit);
    }

    /// <summary>A ray from <paramref name="from"/> to <paramref name="to"/> for picking: <see cref="SphereCast"/> with radius 0.</summary>
    public bool RayCast(in Position from, Vector3 to, out SurfaceHit hit, QueryLayers layers = QueryLayers.Solid, uint ignoreObjectId = 0)
    {
        CheckPosition(from, "from.origin", "from.cell");
        Guard.Finite(to, "to");
        return Cast(from, to - from.Origin, 0f, walkableOnly: false, layers, ignoreObjectId, out hit);
    }

    /// <summary>
    /// The highest walkable surface (normal Z at least <see cref="PhysicsConstants.FloorZ"/>) at or below
    /// <paramref name="point"/>, at most <paramref name="maxDrop"/> metres down: terrain, indoor floors and
    /// stairs, buildings' roofs, objects' tops (by their dispatch rung). Steeper surfaces are looked through.
    /// <see cref="SurfaceHit.Point"/>.Z is the floor's height.
    /// </summary>
    public bool TryFindFloor(in Position point, float maxDrop, out SurfaceHit floor, QueryLayers layers = QueryLayers.Solid, uint ignoreObjectId = 0)
    {
        CheckPosition(point, "point.origin", "point.cell");
        Guard.Extent(maxDrop, true, "maxDrop");
        return Cast(point, new Vector3(0, 0, -maxDrop), 0f, walkableOnly: true, layers, ignoreObjectId, out floor);
    }

    /// <summary>
    /// The cell that holds <paramref name="point"/>, in any loaded landblock: an indoor cell when one
    /// contains it (found through the building standing in the land cell under the point and the indoor
    /// portals from there, or from <paramref name="point"/>'s own cell when that is indoor), else the land
    /// cell under it. Retail's cell search (find_cell_list, preferring an indoor cell).
    /// </summary>
    /// <param name="point">The point; its cell id names the frame and, when indoor, is searched first.</param>
    /// <param name="found">The cell, with the point expressed in that cell's landblock frame.</param>
    /// <returns>False when no loaded cell holds the point.</returns>
    public bool TryFindCell(in Position point, out Position found)
    {
        CheckPosition(point, "point.origin", "point.cell");
        return FindCell(point, out found);
    }

    /// <summary>
    /// The objects whose collision shapes (by dispatch rung) overlap a sphere: BSP parts by retail's
    /// sphere-versus-solid test, cylspheres and spheres exactly. One entry per object, in a fixed order;
    /// stops when <paramref name="results"/> is full. <see cref="QueryLayers.Environment"/> is ignored.
    /// </summary>
    /// <returns>How many entries were written.</returns>
    public int OverlapSphere(in Position center, float radius, Span<ObjectOverlap> results, QueryLayers layers = QueryLayers.All, uint ignoreObjectId = 0)
    {
        CheckPosition(center, "center.origin", "center.cell");
        Guard.Extent(radius, true, "radius");
        return Overlap(center, new Vector3(radius), radius, isBox: false, results, layers, ignoreObjectId);
    }

    /// <summary>
    /// The objects whose collision shapes (by dispatch rung) overlap an axis-aligned box centred on
    /// <paramref name="center"/>: cylspheres and spheres exactly, BSP parts by their bounding spheres
    /// (conservative). One entry per object; stops when <paramref name="results"/> is full.
    /// </summary>
    /// <returns>How many entries were written.</returns>
    public int OverlapBox(in Position center, Vector3 halfExtents, Span<ObjectOverlap> results, QueryLayers layers = QueryLayers.All, uint ignoreObjectId = 0)
    {
        CheckPosition(center, "center.origin", "center.cell");
        Guard.Extent(halfExtents.X, true, "halfExtents.X");
        Guard.Extent(halfExtents.Y, true, "halfExtents.Y");
        Guard.Extent(halfExtents.Z, true, "halfExtents.Z");
        return Overlap(center, halfExtents, halfExtents.Length(), isBox: true, results, layers, ignoreObjectId);
    }

    /// <summary>
    /// The retail camera arm (SmartBox::update_viewer): a viewer transition — one sphere of
    /// <see cref="ViewerRadius"/>, <see cref="ViewerFlags"/>, sub-steps of one radius with a shorter last
    /// one — from <paramref name="pivot"/> towards <paramref name="desired"/> (same frame), stopping just
    /// short of the first thing in the way (terrain by the viewer's arm of validate_walkable, walls, objects;
    /// creatures are ignored). The sweep starts in the cell that holds the pivot. When the sweep fails the
    /// camera goes to the desired point if a cell holds it, else to the pivot, as retail does (also when
    /// no loaded cell holds the pivot).
    /// </summary>
    /// <param name="pivot">Where the arm starts (the player's head, say).</param>
    /// <param name="desired">Where the camera wants to be.</param>
    /// <param name="playerId">The player's object id: the camera passes through the player (a new id builds the viewer's description once; the same id allocates nothing).</param>
    public CameraArmResult CameraArm(in Position pivot, Vector3 desired, uint playerId = 0)
    {
        CheckPosition(pivot, "pivot.origin", "pivot.cell");
        Guard.Rotation(pivot.Frame.Orientation, "pivot.orientation");
        Guard.Finite(desired, "desired");
        // Retail starts an indoor pivot in the cell that holds it (CPhysicsObj::AdjustPosition) and an outdoor
        // one in the player's cell; here the pivot's cell id only names its frame, so both start in the cell
        // holding the pivot (outdoors the same cell unless the pivot lies across a cell border).
        // An indoor pivot inside its own cell is found at once: the cell search lists that cell first and
        // takes the first indoor cell holding the point (the same answer, same bits, without the search).
        Position start;
        if (World.Cells.Get(pivot.CellId) is EnvCell own && own.ContainsPoint(pivot.Origin))
            start = pivot;
        else if (!FindCell(pivot, out start))
            return new CameraArmResult(pivot, CameraPlacement.AtPivot, false, Vector3.Zero);
        var target = new Position(start.CellId, new Frame(desired - LandDefs.BlockOffset(pivot.CellId, start.CellId), start.Frame.Orientation));
        if (_viewerMover is null || _viewerMover.ObjectId != playerId)
            _viewerMover = new MoverDescription(playerId, [new Sphere(Vector3.Zero, ViewerRadius)], 0f, 0f, PhysicsState.None, ViewerFlags);
        var result = _viewer.Resolve(_viewerMover, MoverState.Airborne(start), target);
        if (result.Succeeded)
            return new CameraArmResult(result.Position, CameraPlacement.Swept, result.CollisionNormalValid, result.CollisionNormal);
        var wanted = new Position(pivot.CellId, new Frame(desired, pivot.Frame.Orientation));
        if (FindCell(wanted, out var placed))
            return new CameraArmResult(placed, CameraPlacement.AtDesired, false, Vector3.Zero);
        return new CameraArmResult(pivot, CameraPlacement.AtPivot, false, Vector3.Zero);
    }

    /// <summary>Queries read only a position's origin and cell (the camera also its rotation); the cell must be in the world.</summary>
    private void CheckPosition(in Position position, string originField, string cellField)
    {
        Guard.Finite(position.Frame.Origin, originField);
        World.Cells.GetRequired(position.CellId, cellField);
    }

    private bool FindCell(in Position point, out Position found)
    {
        var graph = World.Cells;
        Span<Sphere> probe = stackalloc Sphere[1];
        if (!LandDefs.IsLandCell(point.CellId))
        {
            probe[0] = new Sphere(point.Origin, 0f);
            if (graph.FindCellList(point, probe, _cellArray, findContaining: true, out _) is { } indoor)
            {
                found = Relabel(point, indoor.Id);
                return true;
            }
        }
        uint block = point.CellId >> 16;
        float fx = MathF.Floor(point.Origin.X / PhysicsConstants.LandCellLength);
        float fy = MathF.Floor(point.Origin.Y / PhysicsConstants.LandCellLength);
        uint landId = LandDefs.LandCellAtGlobal((int)(block >> 8) * 8 + (int)fx, (int)(block & 0xFF) * 8 + (int)fy);
        if (landId != 0 && graph.Get(landId) is LandCell)
        {
            var local = Relabel(point, landId);
            probe[0] = new Sphere(local.Origin, 0f);
            if (graph.FindCellList(local, probe, _cellArray, findContaining: true, out _) is { } cell)
            {
                found = Relabel(point, cell.Id);
                return true;
            }
        }
        found = default;
        return false;
    }

    private static Position Relabel(in Position point, uint cellId) =>
        new(cellId, new Frame(point.Origin - LandDefs.BlockOffset(point.CellId, cellId), point.Frame.Orientation));

    private bool Cast(in Position from, Vector3 d, float r, bool walkableOnly, QueryLayers layers, uint ignoreId, out SurfaceHit hit)
    {
        uint frameCell = from.CellId;
        var c = from.Origin;
        CollectCells(from, d, new Vector3(r), r);
        var best = ShapeSweep.Best.None(1f);
        var kind = SurfaceKind.None;
        bool manyCells = _cells.Count > 1;
        _sweptCount = 0;
        uint cellId = 0, objectId = 0;
        for (int n = 0; n < _cells.Count; n++)
        {
            var cell = _cells[n];
            var shift = LandDefs.BlockOffset(frameCell, cell.Id);
            if ((layers & QueryLayers.Environment) != 0)
            {
                if (cell is LandCell land)
                {
                    var (first, second) = land.Triangles;
                    if (SweepTerrain(first, frameCell, shift, c, d, r, walkableOnly, ref best)
                        | SweepTerrain(second, frameCell, shift, c, d, r, walkableOnly, ref best))
                        (kind, cellId, objectId) = (SurfaceKind.Terrain, land.Id, 0u);
                    if (land.Building is { } building
                        && ShapeSweep.Tree(building.Shell.Bsp, building.Position.Frame, shift, 1f, c, d, r, walkableOnly, ref best))
                        (kind, cellId, objectId) = (SurfaceKind.Building, land.Id, 0u);
                }
                else if (cell is EnvCell { PhysicsBsp: { } bsp } env
                    && ShapeSweep.Tree(bsp, env.Matrix, env.Position.Frame.Origin, shift, 1f, c, d, r, walkableOnly, ref best))
                {
                    (kind, cellId, objectId) = (SurfaceKind.EnvCell, env.Id, 0u);
                }
            }
            if ((layers & (QueryLayers.Objects | QueryLayers.EtherealObjects)) == 0)
                continue;
            var objects = World.Objects.ObjectsInCell(cell.Id);
            SweptBox(c - shift, d, new Vector3(r), out var boxMin, out var boxMax);
            for (int o = 0; o < objects.Count; o++)
            {
                if (!objects.Reaches(o, boxMin, boxMax))
                    continue;
                var rows = objects.RowsOf(o);
                if (rows.Length == 0 || !Selected(rows[0], layers, ignoreId, out var rung)
                    || (manyCells && !FirstSweep(rows[0].EntityId)))
                    continue;
                for (int i = 0; i < rows.Length; i++)
                    if (rows[i].Kind == rung && SweepRow(rows[i], frameCell, c, d, r, walkableOnly, ref best))
                        (kind, cellId, objectId) = (SurfaceKind.Object, rows[i].Position.CellId, rows[i].EntityId);
            }
        }
        if (!best.Found)
        {
            hit = default;
            return false;
        }
        var center = c + d * best.Fraction;
        hit = new SurfaceHit(best.Fraction, center, center - best.Normal * r, best.Normal, cellId, objectId, kind);
        return true;
    }

    /// <summary>Records that this cast sweeps object <paramref name="id"/>; false when it already has.</summary>
    private bool FirstSweep(uint id)
    {
        var swept = _swept.AsSpan(0, _sweptCount);
        if (swept.Contains(id))
            return false;
        if (_sweptCount == _swept.Length)
            Array.Resize(ref _swept, _swept.Length * 2);
        _swept[_sweptCount++] = id;
        return true;
    }

    /// <summary>
    /// A terrain triangle, except where the contact lies inside an indoor cell: there retail puts a mover in
    /// the indoor cell, which never collides with terrain (a cottage floor level with the ground is the
    /// floor, a cellar under the ground is reachable).
    /// </summary>
    private bool SweepTerrain(Polygon triangle, uint frameCell, Vector3 shift, Vector3 c, Vector3 d, float r, bool walkableOnly, ref ShapeSweep.Best best)
    {
        var trial = best;
        if (!ShapeSweep.Polygon(triangle, shift, c, d, r, walkableOnly, ref trial))
            return false;
        var contact = c + d * trial.Fraction - trial.Normal * r;
        for (int i = _landCount; i < _cells.Count; i++)
        {
            var env = (EnvCell)_cells[i];
            if (env.ContainsPoint(contact - LandDefs.BlockOffset(frameCell, env.Id)))
                return false;
        }
        best = trial;
        return true;
    }

    private static bool SweepRow(in ShadowEntry row, uint frameCell, Vector3 c, Vector3 d, float r, bool walkableOnly, ref ShapeSweep.Best best)
    {
        var shift = LandDefs.BlockOffset(frameCell, row.Position.CellId);
        var shape = row.Shape;
        var bounds = new Sphere(row.Position.LocalToGlobal(shape.Bounds.Center) + shift, shape.Bounds.Radius);
        if (!ShapeSweep.Reaches(bounds, c, c + d * best.Fraction, r))
            return false;
        switch (shape.Kind)
        {
            case ShadowShapeKind.Bsp:
                var part = row.PartPosition.Frame; // the registry's Frame::combine, same bits
                return ShapeSweep.Tree(shape.Model!.Bsp, part, shift, shape.ModelScale, c, d, r, walkableOnly, ref best);
            case ShadowShapeKind.Cylinder:
                var cyl = shape.Cylinder;
                cyl.LowPoint = row.PlacedPoint + shift; // the registry's Position::localtoglobal, same bits
                return ShapeSweep.Cylinder(cyl, c, d, r, walkableOnly, ref best);
            default:
                return ShapeSweep.Sphere(bounds, c, d, r, walkableOnly, ref best);
        }
    }

    private int Overlap(in Position center, Vector3 extent, float reach, bool isBox, Span<ObjectOverlap> results, QueryLayers layers, uint ignoreId)
    {
        uint frameCell = center.CellId;
        var c = center.Origin;
        CollectCells(center, Vector3.Zero, extent, reach);
        int count = 0;
        for (int n = 0; n < _cells.Count; n++)
        {
            var cell = _cells[n];
            var objects = World.Objects.ObjectsInCell(cell.Id);
            SweptBox(c - LandDefs.BlockOffset(frameCell, cell.Id), Vector3.Zero, extent, out var boxMin, out var boxMax);
            for (int o = 0; o < objects.Count && count < results.Length; o++)
            {
                if (!objects.Reaches(o, boxMin, boxMax))
                    continue;
                var rows = objects.RowsOf(o);
                if (rows.Length == 0)
                    continue;
                uint id = rows[0].EntityId;
                if (!Selected(rows[0], layers, ignoreId, out var rung) || Listed(results[..count], id))
                    continue;
                for (int i = 0; i < rows.Length; i++)
                {
                    ref readonly var row = ref rows[i];
                    if (row.Kind != rung || !Overlaps(row, frameCell, c, extent, isBox))
                        continue;
                    results[count++] = new ObjectOverlap(id, row.Kind, row.Shape.Index, row.Position.CellId, row.State);
                    break;
                }
            }
        }
        return count;
    }

    private static bool Overlaps(in ShadowEntry row, uint frameCell, Vector3 c, Vector3 extent, bool isBox)
    {
        var shift = LandDefs.BlockOffset(frameCell, row.Position.CellId);
        var shape = row.Shape;
        var bounds = new Sphere(row.Position.LocalToGlobal(shape.Bounds.Center) + shift, shape.Bounds.Radius);
        if (isBox)
        {
            if (shape.Kind != ShadowShapeKind.Cylinder)
                return BoxTouchesSphere(c, extent, bounds);
            var cyl = shape.Cylinder;
            var low = row.Position.LocalToGlobal(cyl.LowPoint) + shift;
            if (low.Z > c.Z + extent.Z || low.Z + cyl.Height < c.Z - extent.Z)
                return false;
            float dx = MathF.Max(MathF.Abs(low.X - c.X) - extent.X, 0f), dy = MathF.Max(MathF.Abs(low.Y - c.Y) - extent.Y, 0f);
            return dx * dx + dy * dy <= cyl.Radius * cyl.Radius;
        }
        float r = extent.X;
        switch (shape.Kind)
        {
            case ShadowShapeKind.Bsp:
                var model = shape.Model!;
                var part = row.PartPosition.Frame; // the registry's Frame::combine, same bits
                float inv = 1f / shape.ModelScale;
                var local = new Sphere(part.GlobalToLocal(c - shift) * inv, r * inv);
                return local.Intersects(model.BoundingSphere) && Bsp.BspQuery.SphereIntersectsSolid(model.Bsp, local);
            case ShadowShapeKind.Cylinder:
                var cyl = shape.Cylinder;
                cyl.LowPoint = row.PlacedPoint + shift; // the registry's Position::localtoglobal, same bits
                return Vector3.DistanceSquared(TimeOfImpact.ClosestPointOnCylinder(c, cyl), c) <= r * r;
            default:
                float reach = bounds.Radius + r;
                return Vector3.DistanceSquared(bounds.Center, c) <= reach * reach;
        }
    }

    /// <summary>
    /// The box a shape centred on the segment from <paramref name="c"/> along <paramref name="d"/>, with half-sizes
    /// <paramref name="extent"/>, sweeps (in one cell's landblock space). An object whose reach box (the registry's,
    /// which holds every shape a query tests, widened far above rounding) misses it cannot be touched, so its rows
    /// are not visited: a cast or overlap beside a crowded cell costs a box test per object there instead of a
    /// placed bounding sphere per row. Changes no result.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // its outs then stay in registers, not in the caller's zeroed frame
    private static void SweptBox(Vector3 c, Vector3 d, Vector3 extent, out Vector3 min, out Vector3 max)
    {
        min = Vector3.Min(c, c + d) - extent;
        max = Vector3.Max(c, c + d) + extent;
    }

    private static bool BoxTouchesSphere(Vector3 c, Vector3 extent, in Sphere sphere)
    {
        var nearest = Vector3.Clamp(sphere.Center, c - extent, c + extent);
        return Vector3.DistanceSquared(nearest, sphere.Center) <= sphere.Radius * sphere.Radius;
    }

    private static bool Listed(ReadOnlySpan<ObjectOverlap> found, uint id)
    {
        foreach (var o in found)
            if (o.ObjectId == id)
                return true;
        return false;
    }

    /// <summary>Whether the layers take this object, and which kind of its shapes it collides by (retail's dispatch rung).</summary>
    private static bool Selected(in ShadowEntry head, QueryLayers layers, uint ignoreId, out ShadowShapeKind rung)
    {
        rung = ObjectCollisions.PlainDispatchRung(head);
        if (head.EntityId == ignoreId && ignoreId != 0)
            return false;
        var needed = (head.State & PhysicsState.Ethereal) != 0 ? QueryLayers.EtherealObjects : QueryLayers.Objects;
        return (layers & needed) != 0;
    }

    /// <summary>
    /// The cells a query must look at: the loaded land cells under the swept footprint (column by column,
    /// so a long diagonal cast visits only the cells along it), then the indoor cells reached from the
    /// start cell (when indoor) and from the buildings standing in those land cells, through portals,
    /// as long as their physics geometry can be reached.
    /// </summary>
    private void CollectCells(in Position from, Vector3 d, Vector3 extent, float reach)
    {
        _cells.Clear();
        var graph = World.Cells;
        uint frameCell = from.CellId;
        var c = from.Origin;
        uint block = frameCell >> 16;
        int baseX = (int)(block >> 8) * 8, baseY = (int)(block & 0xFF) * 8;
        const float size = PhysicsConstants.LandCellLength;
        const int worldCells = 2040;
        // A footprint on a cell's edge takes the cells on both sides: a ray down the last loaded cell's outer
        // edge (x = 192 of the world's eastern landblock) touches that cell's terrain, not the missing one's.
        extent += new Vector3(PhysicsConstants.Epsilon);
        int gx0 = Math.Clamp(baseX + (int)MathF.Floor((MathF.Min(c.X, c.X + d.X) - extent.X) / size), 0, worldCells - 1);
        int gx1 = Math.Clamp(baseX + (int)MathF.Floor((MathF.Max(c.X, c.X + d.X) + extent.X) / size), 0, worldCells - 1);
        for (int gx = gx0; gx <= gx1; gx++)
        {
            float x0 = (gx - baseX) * size - extent.X, x1 = (gx - baseX + 1) * size + extent.X;
            float tLo = 0f, tHi = 1f;
            if (d.X != 0f)
            {
                float ta = (x0 - c.X) / d.X, tb = (x1 - c.X) / d.X;
                tLo = MathF.Max(0f, MathF.Min(ta, tb));
                tHi = MathF.Min(1f, MathF.Max(ta, tb));
                if (tLo > tHi)
                    continue;
            }
            float ya = c.Y + d.Y * tLo, yb = c.Y + d.Y * tHi;
            int gy0 = Math.Clamp(baseY + (int)MathF.Floor((MathF.Min(ya, yb) - extent.Y) / size), 0, worldCells - 1);
            int gy1 = Math.Clamp(baseY + (int)MathF.Floor((MathF.Max(ya, yb) + extent.Y) / size), 0, worldCells - 1);
            for (int gy = gy0; gy <= gy1; gy++)
                if (graph.Get(LandDefs.LandCellAtGlobal(gx, gy)) is LandCell land)
                    _cells.Add(land);
        }

        int landCount = _landCount = _cells.Count;
        if (graph.Get(frameCell) is EnvCell startCell)
            _cells.Add(startCell);
        for (int i = 0; i < landCount; i++)
            if (((LandCell)_cells[i]).Building is { } building)
                foreach (uint id in building.EntranceCells)
                    AddEnvCell(graph.Get(id) as EnvCell, frameCell, c, d, reach);
        for (int i = landCount; i < _cells.Count; i++)
            foreach (var portal in ((EnvCell)_cells[i]).Portals)
                if (!portal.LeadsOutside)
                    AddEnvCell(graph.Get(portal.OtherCellId) as EnvCell, frameCell, c, d, reach);
    }

    private void AddEnvCell(EnvCell? env, uint frameCell, Vector3 c, Vector3 d, float reach)
    {
        if (env is null || _cells.Contains(env))
            return;
        if (env.PhysicsBsp is { } bsp)
        {
            // The physics BSP's bounds placed in the cell's landblock: kept by the cell (the same bits) unless empty.
            var bounds = bsp.Bounds.Radius > 0f ? env.Bounds : new Sphere(env.Position.Frame.LocalToGlobal(bsp.Bounds.Center), bsp.Bounds.Radius);
            bounds.Center += LandDefs.BlockOffset(frameCell, env.Id);
            if (!ShapeSweep.Reaches(bounds, c, c + d, reach))
                return;
        }
        _cells.Add(env);
    }
}
