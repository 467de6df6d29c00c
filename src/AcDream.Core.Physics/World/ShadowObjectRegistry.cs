using System;
using System.Collections.Generic;
using System.Numerics;
using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Threading;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The objects of the world, as per-cell lists of objects (retail CObjCell's shadow list), each object
/// carrying its <see cref="ShadowEntry"/> rows: one row per collision shape, an object present once in every
/// cell it overlaps.
/// Single writer: register, move and unregister from one thread while no query runs; queries may run in
/// parallel when nothing is being modified. A second thread writing while one is (a caller's bug) is
/// detected, as .NET's collections detect a modification during enumeration: its call throws
/// <see cref="InvalidOperationException"/> before changing anything, the other completes, and the
/// registry stays usable. Queries running during a write are not detected.
/// </summary>
public sealed class ShadowObjectRegistry
{
    internal sealed class Record
    {
        public required uint Id;
        public required ShadowShape[] Shapes;
        public required ShadowEntry[] Rows;
        /// <summary>The setup the object was registered from (null when registered from shapes alone), for snapshots.</summary>
        public PhysicsSetup? Setup;
        public Position Position;
        public float Scale;
        public PhysicsState State;
        public ShadowFlags Flags;
        public int CylCount;
        public int SphereCount;
        public Sphere LocalBounds;
        /// <summary>The object's reach box in its own landblock's space (see <see cref="ReachBox"/>).</summary>
        public Vector3 ReachMin, ReachMax;
        /// <summary>The cells the object is listed in.</summary>
        public readonly List<uint> Cells = new(4);
        /// <summary>For each entry of <see cref="Cells"/>, the object's index in that cell's list.</summary>
        public readonly List<int> Slots = new(4);
    }

    /// <summary>
    /// One object in a cell's list, which of the object's cells that list is (its index in
    /// <see cref="Record.Cells"/>), and the object's reach box in that cell's landblock space (see
    /// <see cref="ReachBox"/>), kept beside the record so a cull reads the list alone.
    /// </summary>
    internal readonly record struct Slot(Record Record, int CellIndex, Vector3 ReachMin, Vector3 ReachMax);

    private readonly CellGraph _graph;
    // Each cell's list, by cell id: looked up once per cell per insert, so land cells are found by array.
    private readonly CellTable<List<Slot>> _byCell = new();
    private readonly Dictionary<uint, Record> _objects = new();
    private readonly CellArray _scratch = new();
    private readonly List<uint> _newCells = new(4);
    // 1 while a thread is registering, moving or removing: a second writer meets it and throws.
    private int _writing;

    /// <summary>Creates an empty registry over a world's cells.</summary>
    public ShadowObjectRegistry(CellGraph graph) => _graph = graph ?? throw new ArgumentNullException(nameof(graph));

    /// <summary>Changes with every registration, move and removal (a transition's object cull starts over).</summary>
    internal int Version { get; private set; }

    /// <summary>How many objects are registered.</summary>
    public int Count => _objects.Count;

    /// <summary>True when an object with this id is registered.</summary>
    public bool Contains(uint entityId) => _objects.ContainsKey(entityId);

    /// <summary>The registered objects in the registry's order (see <see cref="ListInLandblock"/>), for snapshots.</summary>
    internal Dictionary<uint, Record>.ValueCollection Records => _objects.Values;

    /// <summary>
    /// Puts the given objects of a cell's list back in a saved order (a snapshot restored): the places the
    /// given objects hold in the list are handed out again to them sorted by their saved rank; other
    /// objects keep their places. Unknown ids and objects not listed in the cell are ignored.
    /// </summary>
    internal void RestoreOrder(uint cellId, IReadOnlyList<(uint Id, uint Rank)> ranks)
    {
        if (_byCell.Get(cellId) is not { Count: > 1 } slots)
            return;
        var places = new List<int>();
        var entries = new List<(uint Rank, Slot Slot)>();
        foreach (var (id, rank) in ranks)
        {
            if (!_objects.TryGetValue(id, out var record))
                continue;
            int k = record.Cells.IndexOf(cellId);
            if (k < 0)
                continue;
            places.Add(record.Slots[k]);
            entries.Add((rank, slots[record.Slots[k]]));
        }
        places.Sort();
        entries.Sort((a, b) => a.Rank.CompareTo(b.Rank));
        for (int i = 0; i < places.Count; i++)
        {
            var slot = entries[i].Slot;
            slots[places[i]] = slot;
            slot.Record.Slots[slot.CellIndex] = places[i];
        }
        Version++;
    }

    /// <summary>The state an object is registered with, or false when it is not registered.</summary>
    internal bool TryGetState(uint entityId, out PhysicsState state)
    {
        bool found = _objects.TryGetValue(entityId, out var record);
        state = found ? record!.State : PhysicsState.None;
        return found;
    }

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
        Register(entityId, shapes, position, scale, state, flags, setup);
    }

    /// <summary>Registers an object from shapes already built by <see cref="ShadowShapeBuilder.FromSetup"/>.</summary>
    internal void Register(uint entityId, ShadowShape[] shapes, Position position, float scale, PhysicsState state, ShadowFlags flags = ShadowFlags.None,
        PhysicsSetup? setup = null)
    {
        BeginWrite(nameof(Register));
        try
        {
            RegisterCore(entityId, shapes, position, scale, state, flags, setup);
        }
        finally
        {
            EndWrite();
        }
    }

    private void RegisterCore(uint entityId, ShadowShape[] shapes, Position position, float scale, PhysicsState state, ShadowFlags flags,
        PhysicsSetup? setup)
    {
        ArgumentNullException.ThrowIfNull(shapes);
        string name = $"object 0x{entityId:X8}";
        if (_objects.ContainsKey(entityId))
            throw new ArgumentException($"{name}: is already registered.", nameof(entityId));
        for (int i = 0; i < shapes.Length; i++)
            if (shapes[i] is null)
                throw new ArgumentException($"{name}.shapes[{i}]: is null.", nameof(shapes));
        Guard.Extent(scale, false, $"{name}.scale");
        var localBounds = Enclose(shapes);
        position = CheckPosition(position, entityId, Reach(localBounds));

        var record = new Record
        {
            Id = entityId, Shapes = (ShadowShape[])shapes.Clone(), Rows = new ShadowEntry[shapes.Length],
            Position = position, Scale = scale, State = state, Flags = flags, Setup = setup,
        };
        foreach (var shape in shapes)
        {
            if (shape.Kind == ShadowShapeKind.Cylinder) record.CylCount++;
            if (shape.Kind == ShadowShapeKind.Sphere) record.SphereCount++;
        }
        record.LocalBounds = localBounds;
        FindCells(record, _newCells);
        _objects.Add(entityId, record);
        WriteRows(record);
        AddToCells(record, _newCells);
    }

    /// <summary>
    /// Moves a registered object; it leaves its old cells (as <see cref="Unregister"/> does) and is appended
    /// to its new cells' lists. Unknown ids and cells throw, leaving everything unchanged. Allocates nothing
    /// once the cells involved have been seen before.
    /// </summary>
    public void Move(uint entityId, Position position)
    {
        BeginWrite(nameof(Move));
        try
        {
            MoveCore(entityId, position);
        }
        finally
        {
            EndWrite();
        }
    }

    private void MoveCore(uint entityId, Position position)
    {
        if (!_objects.TryGetValue(entityId, out var record))
            throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));
        position = CheckPosition(position, entityId, Reach(record.LocalBounds));
        var old = record.Position;
        record.Position = position;
        try
        {
            FindCells(record, _newCells);
        }
        catch
        {
            record.Position = old;
            throw;
        }
        RemoveFromCells(record);
        WriteRows(record);
        AddToCells(record, _newCells);
    }

    /// <summary>
    /// Registers an object again with its shapes, scale and flags at another position and state
    /// (HasPhysicsBsp stays when it was derived from the setup). Used to place a scene's object the way
    /// a parity file says; on failure the object stays as it was.
    /// </summary>
    internal void Replace(uint entityId, Position position, PhysicsState state)
    {
        BeginWrite(nameof(Replace));
        try
        {
            if (!_objects.TryGetValue(entityId, out var old))
                throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));
            UnregisterCore(entityId);
            try
            {
                RegisterCore(entityId, old.Shapes, position, old.Scale, state | (old.State & PhysicsState.HasPhysicsBsp), old.Flags, old.Setup);
            }
            catch
            {
                RegisterCore(entityId, old.Shapes, old.Position, old.Scale, old.State, old.Flags, old.Setup);
                throw;
            }
        }
        finally
        {
            EndWrite();
        }
    }

    /// <summary>
    /// Removes an object; false when it was not registered. In each of its cells the cell's last object
    /// takes its place (retail order, see <see cref="RemoveFromCells"/>); the cost is constant per cell.
    /// </summary>
    public bool Unregister(uint entityId)
    {
        BeginWrite(nameof(Unregister));
        try
        {
            return UnregisterCore(entityId);
        }
        finally
        {
            EndWrite();
        }
    }

    private bool UnregisterCore(uint entityId)
    {
        if (!_objects.Remove(entityId, out var record))
            return false;
        RemoveFromCells(record);
        return true;
    }

    /// <summary>Takes the writer's flag; a thread that finds it taken throws before changing anything.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void BeginWrite(string operation)
    {
        if (Interlocked.CompareExchange(ref _writing, 1, 0) != 0)
            ThrowConcurrentWrite(operation);
    }

    private void EndWrite() => Volatile.Write(ref _writing, 0);

    /// <summary>
    /// Streaming (<see cref="PhysicsWorld.LoadLandblock"/>, <see cref="PhysicsWorld.UnloadLandblock"/>) changes the cell
    /// graph the registry's writers read, so it takes the same writer's flag for the whole load or unload: a second
    /// streaming thread, or a registry writer meanwhile, is refused before it changes anything.
    /// </summary>
    internal void BeginStreaming(string operation)
    {
        if (Interlocked.CompareExchange(ref _writing, 1, 0) != 0)
            throw new InvalidOperationException($"PhysicsWorld.{operation}: another thread is loading or unloading a landblock or modifying the registry; the world takes one writer at a time. This call changed nothing.");
    }

    internal void EndStreaming() => EndWrite();

    [DoesNotReturn, MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowConcurrentWrite(string operation) =>
        throw new InvalidOperationException($"ShadowObjectRegistry.{operation}: another thread is modifying the registry; it takes one writer at a time. This call changed nothing.");

    /// <summary>
    /// Takes every row listed in a landblock's cells (land and env cells) out of the registry, before the
    /// landblock's cells leave the graph (<see cref="PhysicsWorld.UnloadLandblock"/>). An object listed in
    /// other cells too (it straddles a landblock border) keeps those rows and stays registered, at its
    /// position; an object left with no row is unregistered. The cells' emptied lists are kept for the
    /// next load. Allocates nothing.
    /// </summary>
    internal void DropLandblock(uint landblock)
    {
        // The caller holds the writer's flag (BeginStreaming).
        Version++;
        for (uint i = 1; i <= 64; i++)
            DropCell((landblock << 16) | i);
        foreach (var env in _graph.EnvCellsOf(landblock))
            DropCell(env.Id);
    }

    private void DropCell(uint cellId)
    {
        if (_byCell.Get(cellId) is not { Count: > 0 } slots)
            return;
        for (int s = 0; s < slots.Count; s++)
        {
            // Read from the list each time: dropping an earlier cell of the same object renumbered it.
            var record = slots[s].Record;
            int k = slots[s].CellIndex;
            record.Cells.RemoveAt(k);
            record.Slots.RemoveAt(k);
            // The object's later cells moved down one place: their lists' slots say so.
            for (int j = k; j < record.Cells.Count; j++)
            {
                var list = _byCell.Get(record.Cells[j])!;
                list[record.Slots[j]] = list[record.Slots[j]] with { CellIndex = j };
            }
            if (record.Cells.Count == 0)
                _objects.Remove(record.Id);
        }
        slots.Clear();
    }

    /// <summary>
    /// Lists the objects already registered in the cells of a landblock just added
    /// (<see cref="PhysicsWorld.LoadLandblock"/>): every object standing in that landblock or one beside it
    /// gets the rows its shapes would have had there had the landblock been loaded when it was registered,
    /// appended to those cells' lists (the objects' other rows are left as they are). The objects are visited
    /// in the registry's order, which depends only on the order of registrations and removals.
    /// </summary>
    internal void ListInLandblock(uint landblock) => ListInLandblockCore(landblock); // the caller holds the writer's flag (BeginStreaming)

    private void ListInLandblockCore(uint landblock)
    {
        Version++;
        int bx = (int)(landblock >> 8), by = (int)(landblock & 0xFF);
        foreach (var record in _objects.Values)
        {
            uint home = record.Position.CellId >> 16;
            if (Math.Abs((int)(home >> 8) - bx) > 1 || Math.Abs((int)(home & 0xFF) - by) > 1)
                continue;
            FindCells(record, _newCells);
            foreach (uint cellId in _newCells)
            {
                if (cellId >> 16 != landblock || record.Cells.Contains(cellId) || _graph.Get(cellId) is null)
                    continue;
                Append(record, cellId);
            }
        }
    }

    /// <summary>
    /// The rows of a cell's objects, in the order they are tested (empty for a cell with no objects): rows of
    /// one object are contiguous. Builds a new array: for inspection and tests, not for the per-frame path.
    /// </summary>
    internal ReadOnlySpan<ShadowEntry> RowsInCell(uint cellId)
    {
        if (_byCell.Get(cellId) is not { Count: > 0 } slots)
            return ReadOnlySpan<ShadowEntry>.Empty;
        var rows = new List<ShadowEntry>();
        foreach (var slot in slots)
            rows.AddRange(slot.Record.Rows);
        return rows.ToArray();
    }

    /// <summary>The objects listed in a cell, in the order they are tested; allocates nothing (the per-frame path).</summary>
    internal CellObjects ObjectsInCell(uint cellId) => new(_byCell.Get(cellId));

    /// <summary>A cell's objects: how many, and each one's rows. Valid until the registry is next modified.</summary>
    internal readonly struct CellObjects
    {
        private readonly List<Slot>? _slots;

        internal CellObjects(List<Slot>? slots) => _slots = slots;

        /// <summary>How many objects the cell lists.</summary>
        public int Count => _slots?.Count ?? 0;

        /// <summary>The cell's list itself, in order (the object cull scans it).</summary>
        public ReadOnlySpan<Slot> Slots => CollectionsMarshal.AsSpan(_slots);

        /// <summary>The rows (one per shape) of the cell's <paramref name="index"/>-th object.</summary>
        public ReadOnlySpan<ShadowEntry> RowsOf(int index) => RowArrayOf(index);

        /// <summary>
        /// The array holding the <paramref name="index"/>-th object's rows. The object keeps this array while
        /// it is registered (moves rewrite it in place), so a holder may keep it until <see cref="Version"/> changes.
        /// </summary>
        public ShadowEntry[] RowArrayOf(int index) => _slots![index].Record.Rows;

        /// <summary>
        /// True when the <paramref name="index"/>-th object's reach box (this cell's landblock space) meets
        /// the box <paramref name="min"/>..<paramref name="max"/>.
        /// </summary>
        public bool Reaches(int index, Vector3 min, Vector3 max)
        {
            var slot = _slots![index];
            return slot.ReachMin.X <= max.X && slot.ReachMax.X >= min.X
                && slot.ReachMin.Y <= max.Y && slot.ReachMax.Y >= min.Y
                && slot.ReachMin.Z <= max.Z && slot.ReachMax.Z >= min.Z;
        }
    }

    /// <summary>The cells an object is listed in.</summary>
    public IReadOnlyList<uint> CellsOf(uint entityId) =>
        _objects.TryGetValue(entityId, out var record) ? record.Cells : throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));

    /// <summary>The position an object is registered at.</summary>
    public Position PositionOf(uint entityId) =>
        _objects.TryGetValue(entityId, out var record) ? record.Position : throw new ArgumentException($"object 0x{entityId:X8}: is not registered.", nameof(entityId));

    /// <summary>
    /// Validates a position: a valid frame, a cell in the world, and an origin near that cell (the movers'
    /// rule, <see cref="Guard.NearCell"/>: the cell an object names decides which cells list it, so a wrong
    /// label changed the physics). The field names (which hold the id) are built only when a check fails.
    /// </summary>
    private Position CheckPosition(Position position, uint entityId, float reach)
    {
        var cell = _graph.Get(position.CellId);
        if (!Guard.IsValidFrame(position.Frame) || cell is null)
        {
            string name = $"object 0x{entityId:X8}";
            Guard.Frame(position.Frame, $"{name}.position");
            cell = _graph.GetRequired(position.CellId, $"{name}.position.cell");
        }
        float outside = cell.DistanceOutside(position.Frame.Origin);
        if (!(outside <= InputLimits.MaxDistanceFromCell + reach))
            Guard.NearCell(outside, reach, position.CellId, position.Frame.Origin, $"object 0x{entityId:X8}.position.origin");
        position.Frame.Orientation = Guard.Rotation(position.Frame.Orientation, "position.orientation");
        return position;
    }

    /// <summary>How far an object's shapes reach from its origin (its shapes are scaled already).</summary>
    private static float Reach(in Sphere localBounds) => localBounds.Center.Length() + localBounds.Radius;

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
        _graph.FindCellList(record.Position, spheres, _scratch, findContaining: false, out _);
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

    /// <summary>Writes the object's rows (one per shape) from its current position and state.</summary>
    private static void WriteRows(Record record)
    {
        for (int i = 0; i < record.Shapes.Length; i++)
            record.Rows[i] = new ShadowEntry(record.Id, record.Shapes[i], record.Position, record.Scale, record.State, record.Flags, record.CylCount, record.SphereCount);
        ReachBox(record, out record.ReachMin, out record.ReachMax);
    }

    /// <summary>
    /// The box (landblock space of the object's cell) outside which a mover sphere's centre, less its
    /// radius, cannot touch any of the object's shapes in any of retail's shape tests: a BSP part's
    /// bounding sphere, a sphere, or a cylinder's upright slab (its XY circle and Z span, the slab test of
    /// CCylSphere::collides_with_sphere, whose corners a sphere around it would miss). Widened by a margin
    /// far above float rounding (and the BSP test's EPSILON slack), so a cull by it never skips a shape
    /// that the exact test would touch.
    /// </summary>
    private static void ReachBox(Record record, out Vector3 min, out Vector3 max)
    {
        min = new Vector3(float.MaxValue);
        max = new Vector3(float.MinValue);
        foreach (var shape in record.Shapes)
        {
            if (shape.Kind == ShadowShapeKind.Cylinder)
            {
                var cyl = shape.Cylinder;
                var low = record.Position.LocalToGlobal(cyl.LowPoint);
                min = Vector3.Min(min, low - new Vector3(cyl.Radius, cyl.Radius, 0));
                max = Vector3.Max(max, low + new Vector3(cyl.Radius, cyl.Radius, cyl.Height));
            }
            else
            {
                var centre = record.Position.LocalToGlobal(shape.Bounds.Center);
                var r = new Vector3(shape.Bounds.Radius);
                min = Vector3.Min(min, centre - r);
                max = Vector3.Max(max, centre + r);
            }
        }
        var margin = ShadowEntry.Margin(record.Scale);
        min -= margin;
        max += margin;
    }

    /// <summary>Appends the object to the lists of <paramref name="cells"/> and records them as its cells.</summary>
    private void AddToCells(Record record, List<uint> cells)
    {
        Version++;
        record.Cells.Clear();
        record.Slots.Clear();
        for (int k = 0; k < cells.Count; k++)
            Append(record, cells[k]);
    }

    /// <summary>Appends the object to one cell's list and records that cell as its next one.</summary>
    private void Append(Record record, uint cellId)
    {
        var slots = _byCell.Get(cellId);
        if (slots is null)
            _byCell.Set(cellId, slots = new List<Slot>());
        record.Cells.Add(cellId);
        record.Slots.Add(slots.Count);
        var offset = LandDefs.BlockOffset(cellId, record.Position.CellId);
        slots.Add(new Slot(record, record.Cells.Count - 1, record.ReachMin + offset, record.ReachMax + offset));
    }

    /// <summary>
    /// Takes the object out of its cells' lists the retail way: the cell's last object moves into the hole
    /// (CObjCell::remove_shadow_object, acclient CObjCell.c:491), so the order objects are tested in changes
    /// as retail's does. Each object knows its index in each of its cells, so no list is searched. Emptied
    /// lists are kept for reuse.
    /// </summary>
    private void RemoveFromCells(Record record)
    {
        Version++;
        for (int k = 0; k < record.Cells.Count; k++)
        {
            var slots = _byCell.Get(record.Cells[k])!;
            int hole = record.Slots[k];
            int last = slots.Count - 1;
            if (hole != last)
            {
                var moved = slots[last];
                slots[hole] = moved;
                moved.Record.Slots[moved.CellIndex] = hole;
            }
            slots.RemoveAt(last);
        }
        record.Cells.Clear();
        record.Slots.Clear();
    }
}
