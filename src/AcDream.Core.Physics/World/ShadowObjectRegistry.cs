using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The objects of the world, as flat per-cell lists of <see cref="ShadowEntry"/> rows (retail shadow
/// objects): one row per collision shape, an object present once in every cell it overlaps.
/// Single writer: register, move and unregister from one thread while no query runs; queries may run in
/// parallel when nothing is being modified.
/// </summary>
public sealed class ShadowObjectRegistry
{
    private sealed class Record
    {
        public required ShadowShape[] Shapes;
        public Position Position;
        public float Scale;
        public PhysicsState State;
        public ShadowFlags Flags;
        public int CylCount;
        public int SphereCount;
        public Sphere LocalBounds;
        public readonly List<uint> Cells = new(4);
    }

    private readonly CellGraph _graph;
    private readonly Dictionary<uint, List<ShadowEntry>> _byCell = new();
    private readonly Dictionary<uint, Record> _objects = new();
    private readonly CellArray _scratch = new();

    /// <summary>Creates an empty registry over a world's cells.</summary>
    public ShadowObjectRegistry(CellGraph graph) => _graph = graph ?? throw new ArgumentNullException(nameof(graph));

    /// <summary>How many objects are registered.</summary>
    public int Count => _objects.Count;

    /// <summary>True when an object with this id is registered.</summary>
    public bool Contains(uint entityId) => _objects.ContainsKey(entityId);

    /// <summary>
    /// Registers an object from its setup. <see cref="PhysicsState.HasPhysicsBsp"/> is set when any part has
    /// a physics model (retail CacheHasPhysicsBSP) and is also kept when the caller's state has it.
    /// </summary>
    public void Register(uint entityId, PhysicsSetup setup, Position position, float scale = 1f,
        PhysicsState state = PhysicsState.None, ShadowFlags flags = ShadowFlags.None)
    {
        ArgumentNullException.ThrowIfNull(setup);
        var shapes = ShadowShapeBuilder.FromSetup(setup, scale, $"object 0x{entityId:X8}.setup");
        if (setup.HasPhysicsBsp)
            state |= PhysicsState.HasPhysicsBsp;
        Register(entityId, shapes, position, scale, state, flags);
    }

    /// <summary>Registers an object from shapes already built by <see cref="ShadowShapeBuilder.FromSetup"/>.</summary>
    internal void Register(uint entityId, ShadowShape[] shapes, Position position, float scale, PhysicsState state, ShadowFlags flags = ShadowFlags.None)
    {
        ArgumentNullException.ThrowIfNull(shapes);
        string name = $"object 0x{entityId:X8}";
        if (_objects.ContainsKey(entityId))
            throw new ArgumentException($"{name}: is already registered.", nameof(entityId));
        for (int i = 0; i < shapes.Length; i++)
            if (shapes[i] is null)
                throw new ArgumentException($"{name}.shapes[{i}]: is null.", nameof(shapes));
        Guard.Extent(scale, false, $"{name}.scale");
        position = CheckPosition(position, name);

        var record = new Record { Shapes = (ShadowShape[])shapes.Clone(), Position = position, Scale = scale, State = state, Flags = flags };
        foreach (var shape in shapes)
        {
            if (shape.Kind == ShadowShapeKind.Cylinder) record.CylCount++;
            if (shape.Kind == ShadowShapeKind.Sphere) record.SphereCount++;
        }
        record.LocalBounds = Enclose(shapes);
        FindCells(record, record.Cells);
        _objects.Add(entityId, record);
        AddRows(entityId, record);
    }

    /// <summary>Moves a registered object; its rows migrate between cells. Unknown ids and cells throw, leaving everything unchanged.</summary>
    public void Move(uint entityId, Position position)
    {
        if (!_objects.TryGetValue(entityId, out var record))
            throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));
        position = CheckPosition(position, $"object 0x{entityId:X8}");
        var old = record.Position;
        record.Position = position;
        var cells = new List<uint>(4);
        try
        {
            FindCells(record, cells);
        }
        catch
        {
            record.Position = old;
            throw;
        }
        RemoveRows(entityId, record);
        record.Cells.Clear();
        record.Cells.AddRange(cells);
        AddRows(entityId, record);
    }

    /// <summary>Removes an object; false when it was not registered.</summary>
    public bool Unregister(uint entityId)
    {
        if (!_objects.Remove(entityId, out var record))
            return false;
        RemoveRows(entityId, record);
        return true;
    }

    /// <summary>The rows of a cell (empty for a cell with no objects). Valid until the registry is next modified.</summary>
    internal ReadOnlySpan<ShadowEntry> RowsInCell(uint cellId) =>
        _byCell.TryGetValue(cellId, out var rows) ? CollectionsMarshal.AsSpan(rows) : ReadOnlySpan<ShadowEntry>.Empty;

    /// <summary>The cells an object is listed in.</summary>
    public IReadOnlyList<uint> CellsOf(uint entityId) =>
        _objects.TryGetValue(entityId, out var record) ? record.Cells : throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));

    /// <summary>The position an object is registered at.</summary>
    public Position PositionOf(uint entityId) =>
        _objects.TryGetValue(entityId, out var record) ? record.Position : throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));

    private Position CheckPosition(Position position, string name)
    {
        Guard.Frame(position.Frame, $"{name}.position");
        position.Frame.Orientation = Guard.Rotation(position.Frame.Orientation, $"{name}.position.orientation");
        _graph.GetRequired(position.CellId, $"{name}.position.cell");
        return position;
    }

    private static Sphere Enclose(ShadowShape[] shapes)
    {
        if (shapes.Length == 0)
            return new Sphere(System.Numerics.Vector3.Zero, 0f);
        var min = new System.Numerics.Vector3(float.MaxValue);
        var max = new System.Numerics.Vector3(float.MinValue);
        foreach (var s in shapes)
        {
            min = System.Numerics.Vector3.Min(min, s.Bounds.Center - new System.Numerics.Vector3(s.Bounds.Radius));
            max = System.Numerics.Vector3.Max(max, s.Bounds.Center + new System.Numerics.Vector3(s.Bounds.Radius));
        }
        var center = (min + max) * 0.5f;
        float radius = 0f;
        foreach (var s in shapes)
            radius = MathF.Max(radius, System.Numerics.Vector3.Distance(center, s.Bounds.Center) + s.Bounds.Radius);
        return new Sphere(center, radius);
    }

    /// <summary>
    /// The cells an object is listed in, by retail's rule per kind of object (CPhysicsObj::calc_cross_cells):
    /// an object with HasPhysicsBsp by its BSP parts' boxes (outdoors: every land cell under each box);
    /// an object with cylspheres by one sphere per cylsphere at its low point with its radius — retail
    /// quirk: both unscaled, at most ten (CObjCell::find_cell_list for cylspheres); anything else by one
    /// sphere around its shapes (retail uses the setup's sorting sphere, which we do not carry).
    /// Indoor cells are found through the cell graph's sphere search in every case.
    /// </summary>
    private void FindCells(Record record, List<uint> cells)
    {
        cells.Clear();
        var bounds = new Sphere(record.Position.LocalToGlobal(record.LocalBounds.Center), record.LocalBounds.Radius);
        bool bspObject = (record.State & PhysicsState.HasPhysicsBsp) != 0 && Array.Exists(record.Shapes, s => s.Kind == ShadowShapeKind.Bsp);
        if (!bspObject && record.CylCount > 0)
        {
            Span<Sphere> feet = stackalloc Sphere[Math.Min(record.CylCount, MaxCylSpheresForCells)];
            int n = 0;
            foreach (var shape in record.Shapes)
            {
                if (shape.Kind != ShadowShapeKind.Cylinder || n == feet.Length)
                    continue;
                var c = shape.Cylinder;
                feet[n++] = new Sphere(record.Position.LocalToGlobal(c.LowPoint / record.Scale), c.Radius / record.Scale);
            }
            AddFound(record, feet[..n], cells);
        }
        else
        {
            AddFound(record, [bounds], cells);
        }
        if (bspObject && LandDefs.IsLandCell(record.Position.CellId))
            foreach (var shape in record.Shapes)
                if (shape.Kind == ShadowShapeKind.Bsp)
                    AddLandCellsUnderBox(record, shape, cells);
        if (!cells.Contains(record.Position.CellId))
            cells.Insert(0, record.Position.CellId);
    }

    /// <summary>Retail lists a cylsphere object by at most this many of its cylspheres.</summary>
    private const int MaxCylSpheresForCells = 10;

    private void AddFound(Record record, ReadOnlySpan<Sphere> spheres, List<uint> cells)
    {
        _graph.FindCellList(record.Position, spheres, _scratch, findContaining: false, path: null);
        for (int i = 0; i < _scratch.Count; i++)
            if (!cells.Contains(_scratch[i].Id))
                cells.Add(_scratch[i].Id);
    }

    /// <summary>Every loaded land cell under the horizontal box around a BSP part's bounding sphere.</summary>
    private void AddLandCellsUnderBox(Record record, ShadowShape shape, List<uint> cells)
    {
        var centre = record.Position.LocalToGlobal(shape.Bounds.Center);
        float r = shape.Bounds.Radius;
        uint block = record.Position.CellId >> 16;
        int baseX = (int)(block >> 8) * 8, baseY = (int)(block & 0xFF) * 8;
        int x0 = baseX + (int)MathF.Floor((centre.X - r) / PhysicsConstants.LandCellLength);
        int x1 = baseX + (int)MathF.Floor((centre.X + r) / PhysicsConstants.LandCellLength);
        int y0 = baseY + (int)MathF.Floor((centre.Y - r) / PhysicsConstants.LandCellLength);
        int y1 = baseY + (int)MathF.Floor((centre.Y + r) / PhysicsConstants.LandCellLength);
        for (int gx = x0; gx <= x1; gx++)
            for (int gy = y0; gy <= y1; gy++)
            {
                uint id = LandDefs.LandCellAtGlobal(gx, gy);
                if (id != 0 && _graph.Get(id) is not null && !cells.Contains(id))
                    cells.Add(id);
            }
    }

    private void AddRows(uint entityId, Record record)
    {
        foreach (uint cellId in record.Cells)
        {
            if (!_byCell.TryGetValue(cellId, out var rows))
                _byCell.Add(cellId, rows = new List<ShadowEntry>());
            foreach (var shape in record.Shapes)
                rows.Add(new ShadowEntry(entityId, shape, record.Position, record.Scale, record.State, record.Flags, record.CylCount, record.SphereCount));
        }
    }

    /// <summary>
    /// Removes an object's rows from its cells the retail way: the cell's last object takes the removed
    /// object's place (CObjCell::remove_shadow_object moves the last entry into the hole, acclient
    /// CObjCell.c:491), so the order objects are tested in changes as retail's does.
    /// </summary>
    private void RemoveRows(uint entityId, Record record)
    {
        foreach (uint cellId in record.Cells)
        {
            if (!_byCell.TryGetValue(cellId, out var rows))
                continue;
            int start = 0;
            while (start < rows.Count && rows[start].EntityId != entityId)
                start++;
            if (start == rows.Count)
                continue;
            int end = start;
            while (end < rows.Count && rows[end].EntityId == entityId)
                end++;
            int lastStart = rows.Count;
            while (lastStart > end && rows[lastStart - 1].EntityId == rows[rows.Count - 1].EntityId)
                lastStart--;
            if (lastStart > end)
            {
                // Move the last object's rows into the hole, then drop the tail.
                var last = rows.GetRange(lastStart, rows.Count - lastStart);
                rows.RemoveRange(lastStart, rows.Count - lastStart);
                rows.RemoveRange(start, end - start);
                rows.InsertRange(start, last);
            }
            else
            {
                rows.RemoveRange(start, end - start);
            }
            if (rows.Count == 0)
                _byCell.Remove(cellId);
        }
    }
}
