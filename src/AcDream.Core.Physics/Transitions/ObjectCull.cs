using System;
using System.Runtime.CompilerServices;
using System.Numerics;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// Which of a cell's objects a transition can touch (not retail: retail tests every object listed in
/// every cell the spheres touch). A region — a box around the check spheres, wide enough for the rest
/// of the move, its step-ups and step-downs — is chosen at the first object test; each cell's objects
/// whose reach box meets it are listed once, in the cell's order. Before every later test the check
/// spheres are checked to lie inside the region; once they have left it a new region is chosen around
/// them and the lists are made again. The region and lists carry over to the engine's next transition
/// (a mover walking on keeps its lists for a few frames) until the spheres leave the region or the
/// registry changes. An object left out therefore lies beyond reach of every check sphere of that
/// test, and retail's shape tests return OK for it without changing anything (each test first asks
/// whether a check sphere touches the shape): results are bit-identical, and the cost of a transition
/// follows the objects near its path instead of every object in its cells.
/// Reused without allocation once its buffers have grown.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.ObjectCull"/> (not retail; taken in <see cref="ObjectCollisions.FindInCell"/>).
/// Skips: the objects of a cell whose reach box misses the region. Same result: each lies beyond reach of every
/// check sphere, where retail's tests return OK and change nothing (above). Proof: ObjectCullTests,
/// CrowdObjectPassTests, and the suite with shortcuts off.
/// </remarks>
internal sealed class ObjectCull
{
    // Cells listed so far in this transition: id, and where its candidates are in _candidates.
    private uint[] _cellIds = new uint[8];
    private int[] _starts = new int[8];
    private int[] _counts = new int[8];
    private int _cells;
    private int[] _candidates = new int[64];
    // Beside each candidate index, that object's rows (the registry's array for it): the pass reads them
    // from here instead of through the cell's list, the slot and the record. Valid while the registry's
    // version is the one the lists were made at (a new version drops the lists; an object's rows array is
    // replaced only by re-registering it, which changes the version).
    private ShadowEntry[][] _rows = new ShadowEntry[64][];
    // Beside each candidate, its reach box in its cell's landblock space (the registry's), for the tight test
    // before each object (see Reach).
    private ReachBox[] _reach = new ReachBox[64];
    private int _used;

    private int _version = -1;

    // The region, in the landblock space of _regionCell.
    private bool _hasRegion;
    private uint _regionCell;
    private Vector3 _min, _max;

    /// <summary>Forgets the region and the lists (the start of a transition).</summary>
    public void Reset()
    {
        _hasRegion = false;
        _cells = 0;
        _used = 0;
    }

    /// <summary>
    /// The indices, ascending, of the objects of cell <paramref name="cellId"/> that the check spheres of
    /// <paramref name="transition"/> may touch now.
    /// </summary>
    public ReadOnlySpan<int> Candidates(Transition transition, uint cellId)
    {
        int k = ListOf(transition, cellId);
        return _candidates.AsSpan(_starts[k], _counts[k]);
    }

    /// <summary>
    /// The rows of the objects <see cref="Candidates"/> names, in the same order (one array per object): the
    /// object pass reads this one array. The registry is read only when the cell is not listed yet. Beside
    /// each, <paramref name="reach"/> holds its reach box (in its cell's landblock space, the registry's
    /// <see cref="ShadowObjectRegistry.CellObjects.Reaches"/> box).
    /// </summary>
    public ReadOnlySpan<ShadowEntry[]> CandidateRows(Transition transition, uint cellId, out ReadOnlySpan<ReachBox> reach)
    {
        int k = ListOf(transition, cellId);
        reach = _reach.AsSpan(_starts[k], _counts[k]);
        return _rows.AsSpan(_starts[k], _counts[k]);
    }

    /// <summary>An object's reach box (see <see cref="ShadowObjectRegistry.CellObjects.Reaches"/>).</summary>
    internal readonly record struct ReachBox(Vector3 Min, Vector3 Max)
    {
        /// <summary>True when the box meets <paramref name="min"/>..<paramref name="max"/> (the registry's test).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Meets(Vector3 min, Vector3 max) =>
            Min.X <= max.X && Max.X >= min.X && Min.Y <= max.Y && Max.Y >= min.Y && Min.Z <= max.Z && Max.Z >= min.Z;
    }

    /// <summary>Where the cell's list is in <see cref="_cellIds"/>, made first when it is not there.</summary>
    private int ListOf(Transition transition, uint cellId)
    {
        var objects = transition.World.Objects;
        int version = objects.Version;
        if (version != _version)
        {
            // The registry changed since the lists were made (only between transitions, or in tests): the
            // indices and rows arrays kept may name objects no longer there.
            Reset();
            Array.Clear(_rows);
            _version = version;
        }
        EnsureRegionHolds(transition);
        for (int i = 0; i < _cells; i++)
            if (_cellIds[i] == cellId)
                return i;
        return List(cellId, objects.ObjectsInCell(cellId), (transition.Shortcuts & Shortcuts.CellObjectIndex) != 0);
    }

    /// <summary>The check spheres' box, in the landblock space of the check cell.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void SpheresBox(SpherePath path, out Vector3 min, out Vector3 max)
    {
        min = new Vector3(float.MaxValue);
        max = new Vector3(float.MinValue);
        for (int i = 0; i < path.NumSphere; i++)
        {
            var s = path.GlobalSphere[i];
            min = Vector3.Min(min, s.Center - new Vector3(s.Radius));
            max = Vector3.Max(max, s.Center + new Vector3(s.Radius));
        }
    }

    /// <summary>The check spheres' box moved into the landblock space of <paramref name="cellId"/> (the space of that
    /// cell's reach boxes), for the object pass's pre-check.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void SpheresBoxIn(SpherePath path, uint cellId, out Vector3 min, out Vector3 max)
    {
        SpheresBox(path, out min, out max);
        var toCell = LandDefs.BlockOffset(cellId, path.CheckPos.CellId);
        min += toCell;
        max += toCell;
    }

    private void EnsureRegionHolds(Transition transition)
    {
        var path = transition.SpherePath;
        uint checkCell = path.CheckPos.CellId;
        if (_hasRegion && RegionHolds(path, LandDefs.BlockOffset(_regionCell, checkCell)))
            return;
        // No region yet, or the spheres left it (the mover walked on, a long slide, a deep step): a new
        // region around where they are now, and new lists.
        SpheresBox(path, out var min, out var max);
        float slack = Slack(transition);
        _min = min - new Vector3(slack, slack, slack + 1f);
        _max = max + new Vector3(slack, slack, slack);
        if (!(float.IsFinite(_min.X + _min.Y + _min.Z) && float.IsFinite(_max.X + _max.Y + _max.Z)))
        {
            // Never expected (inputs are checked), but a region that is not finite must cull nothing.
            _min = new Vector3(float.NegativeInfinity);
            _max = new Vector3(float.PositiveInfinity);
        }
        _regionCell = checkCell;
        _hasRegion = true;
        _cells = 0;
        _used = 0;
    }

    /// <summary>
    /// True when the check spheres' box, moved into the region's landblock space by <paramref name="toRegion"/>
    /// (a point's coordinates in landblock B's space are its coordinates in A's plus BlockOffset(B, A)), lies
    /// in the region. Sphere by sphere, all axes at once: adding the offset is monotone in float, so the
    /// box's least corner plus the offset is the least of the spheres' corners plus it, and the box is inside
    /// exactly when every sphere's box is (a NaN fails either way).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private bool RegionHolds(SpherePath path, Vector3 toRegion)
    {
        var offset = toRegion.AsVector128();
        // The fourth lane (centre 0 and offset 0 against -inf..+inf) passes unless the radius is NaN.
        var low = Vector128.Create(_min.X, _min.Y, _min.Z, float.NegativeInfinity);
        var high = Vector128.Create(_max.X, _max.Y, _max.Z, float.PositiveInfinity);
        for (int i = 0; i < path.NumSphere; i++)
        {
            ref readonly var s = ref path.GlobalSphere[i];
            var centre = s.Center.AsVector128();
            var radius = Vector128.Create(s.Radius);
            var inside = Vector128.GreaterThanOrEqual(centre - radius + offset, low) & Vector128.LessThanOrEqual(centre + radius + offset, high);
            if (inside.ExtractMostSignificantBits() != 0xF)
                return false;
        }
        return true;
    }

    /// <summary>
    /// How far beyond the check spheres the region reaches: the rest of the move (a placement searches
    /// rings up to 4 m), a step up or down, and half a metre. Only a guess of where the spheres go: the
    /// check in <see cref="EnsureRegionHolds"/> makes it safe.
    /// </summary>
    private static float Slack(Transition transition)
    {
        var path = transition.SpherePath;
        float move = path.HasBeginPos ? path.CheckPos.GetOffset(path.EndPos).Length() : 4.5f;
        var mover = transition.ObjectInfo;
        return MathF.Min(move, 100f) + MathF.Max(mover.StepUpHeight, mover.StepDownHeight) + 0.5f;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void AddIfReaches(ReadOnlySpan<ShadowObjectRegistry.Slot> slots, int i, Vector3 min, Vector3 max)
    {
        ref readonly var slot = ref slots[i];
        if (slot.ReachMin.X <= max.X && slot.ReachMax.X >= min.X
            && slot.ReachMin.Y <= max.Y && slot.ReachMax.Y >= min.Y
            && slot.ReachMin.Z <= max.Z && slot.ReachMax.Z >= min.Z)
            Add(slots, i);
    }

    /// <summary>Lists object <paramref name="i"/> of the cell (its reach box known to meet the region).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Add(ReadOnlySpan<ShadowObjectRegistry.Slot> slots, int i)
    {
        ref readonly var slot = ref slots[i];
        if (_used == _candidates.Length)
        {
            Array.Resize(ref _candidates, _used * 2);
            Array.Resize(ref _rows, _used * 2);
            Array.Resize(ref _reach, _used * 2);
        }
        _candidates[_used] = i;
        _rows[_used] = slot.Record.Rows;
        _reach[_used] = new ReachBox(slot.ReachMin, slot.ReachMax);
        _used++;
    }

    // The crowded cells' indexes this engine keeps (a pile spans a few cells), replaced in turn.
    private readonly CellObjectIndex?[] _indexes = new CellObjectIndex?[8];
    private int _nextIndex;
    private int[] _found = new int[64];

    /// <summary>The index of a crowded cell at the registry's current version, built when it is not kept.</summary>
    private CellObjectIndex IndexOf(uint cellId, ReadOnlySpan<ShadowObjectRegistry.Slot> slots)
    {
        CellObjectIndex? index = null;
        foreach (var kept in _indexes)
            if (kept is not null && kept.CellId == cellId)
            {
                index = kept;
                break;
            }
        if (index is null)
        {
            index = _indexes[_nextIndex] ??= new CellObjectIndex();
            _nextIndex = (_nextIndex + 1) % _indexes.Length;
        }
        else if (index.Version == _version)
            return index;
        index.Build(cellId, _version, slots);
        return index;
    }

    private int List(uint cellId, in ShadowObjectRegistry.CellObjects objects, bool indexed)
    {
        if (_cells == _cellIds.Length)
        {
            Array.Resize(ref _cellIds, _cells * 2);
            Array.Resize(ref _starts, _cells * 2);
            Array.Resize(ref _counts, _cells * 2);
        }
        var toCell = LandDefs.BlockOffset(cellId, _regionCell);
        var min = _min + toCell;
        var max = _max + toCell;
        int start = _used;
        var slots = objects.Slots;
        if (indexed && slots.Length >= CellObjectIndex.MinObjects && float.IsFinite(min.X + min.Y) && float.IsFinite(max.X + max.Y))
        {
            // A crowded cell: only the objects its index names are tested, in the cell's order (see CellObjectIndex).
            var index = IndexOf(cellId, slots);
            if (_found.Length < slots.Length)
                _found = new int[slots.Length * 2];
            int n = index.Meeting(min, max, slots, _found);
            for (int j = 0; j < n; j++)
                Add(slots, _found[j]);
        }
        else
        {
            // The cell's slots read as one span.
            for (int i = 0; i < slots.Length; i++)
                AddIfReaches(slots, i, min, max);
        }
        _cellIds[_cells] = cellId;
        _starts[_cells] = start;
        _counts[_cells] = _used - start;
        return _cells++;
    }
}
