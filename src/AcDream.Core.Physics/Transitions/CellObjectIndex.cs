using System;
using System.Numerics;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// A crowded cell's objects arranged by where their reach boxes start (not retail; changes no result), so that
/// the object cull finds the objects whose reach box meets a region without reading the whole cell. A pile of
/// creatures puts hundreds of objects in one 24 m cell, and every mover's transition makes a region of its own:
/// read in full, the cell costs each mover time in proportion to the pile, and the tick the square of it.
/// The objects are put in columns 2 m wide by the west edge of their reach boxes, and within a column sorted by
/// the south edge; a region reads only the columns and the run of each column whose boxes can reach it, tests
/// those objects with the registry's own box test on the index's copy of their boxes, and puts the ones that
/// meet it back in the cell's order: exactly the objects the full read would list, in the same order.
/// Built for one registry version (every move makes a new one) the first time an engine lists the cell in it;
/// an engine keeps a few such indexes and reuses their arrays, so nothing is allocated once they have grown.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.CellObjectIndex"/> (not retail; taken in <see cref="ObjectCull"/>). Skips: reading
/// every object of a crowded cell to list the cull's candidates. Same result: the very list, in the very order
/// (above). Proof: CellObjectIndexTests, CrowdObjectPassTests and the crowd replays, and the suite with shortcuts off.
/// </remarks>
internal sealed class CellObjectIndex
{
    /// <summary>Cells listing fewer objects are read in full: the index would cost more than it saves.</summary>
    public const int MinObjects = 48;

    /// <summary>Objects whose reach box is wider than this (west to east or south to north) are kept apart and always read.</summary>
    private const float WideObject = 6f;

    /// <summary>The width of a column (m), and the most columns (the last takes every object east of the others).</summary>
    private const float ColumnWidth = 2f;
    private const int MaxColumns = 64;

    // The narrow objects' slot indices, column by column (by the west edge of their reach boxes), within a column
    // sorted by the south edge; the south edges; and beside each its reach box (the slot's, copied).
    private int[] _order = new int[64];
    private int[] _spare = new int[64];
    private float[] _south = new float[64];
    private ObjectCull.ReachBox[] _box = new ObjectCull.ReachBox[64];
    private int _narrow;
    // Where each column starts in _order (column c is _start[c].._start[c + 1]), the west edge column 0 starts
    // at, and how many columns there are.
    private readonly int[] _start = new int[MaxColumns + 1];
    private float _west0;
    private int _columns;
    // The widest narrow object's box (west to east, south to north), and the wide objects' slot indices (ascending).
    private float _widthX, _widthY;
    private int[] _wide = new int[8];
    private int _wideCount;

    /// <summary>The cell this index is of.</summary>
    public uint CellId { get; private set; }

    /// <summary>The registry version this index was built at.</summary>
    public int Version { get; private set; } = -1;

    /// <summary>Arranges the cell's objects (<paramref name="slots"/>, the registry's list at <paramref name="version"/>).</summary>
    public void Build(uint cellId, int version, ReadOnlySpan<ShadowObjectRegistry.Slot> slots)
    {
        CellId = cellId;
        Version = version;
        if (_order.Length < slots.Length)
        {
            _order = new int[slots.Length * 2];
            _spare = new int[slots.Length * 2];
            _south = new float[slots.Length * 2];
            _box = new ObjectCull.ReachBox[slots.Length * 2];
        }
        _narrow = 0;
        _wideCount = 0;
        _widthX = _widthY = 0f;
        float westMin = float.MaxValue, westMax = float.MinValue;
        for (int i = 0; i < slots.Length; i++)
        {
            ref readonly var slot = ref slots[i];
            float widthX = slot.ReachMax.X - slot.ReachMin.X;
            float widthY = slot.ReachMax.Y - slot.ReachMin.Y;
            // A NaN or infinite box (never expected: positions are checked) counts as wide, so it is always read.
            if (!(widthX <= WideObject && widthY <= WideObject))
            {
                if (_wideCount == _wide.Length)
                    Array.Resize(ref _wide, _wideCount * 2);
                _wide[_wideCount++] = i;
                continue;
            }
            _widthX = MathF.Max(_widthX, widthX);
            _widthY = MathF.Max(_widthY, widthY);
            westMin = MathF.Min(westMin, slot.ReachMin.X);
            westMax = MathF.Max(westMax, slot.ReachMin.X);
            _spare[_narrow++] = i;
        }
        _west0 = westMin;
        _columns = _narrow == 0 ? 1 : (int)MathF.Min((westMax - westMin) / ColumnWidth, MaxColumns - 1) + 1;
        // A counting sort into the columns, then each column by south edge.
        Array.Clear(_start);
        for (int k = 0; k < _narrow; k++)
            _start[Column(slots[_spare[k]].ReachMin.X) + 1]++;
        for (int c = 0; c < _columns; c++)
            _start[c + 1] += _start[c];
        for (int k = 0; k < _narrow; k++)
        {
            int i = _spare[k];
            int at = _start[Column(slots[i].ReachMin.X)]++;
            _order[at] = i;
            _south[at] = slots[i].ReachMin.Y;
        }
        // Each column's counter now stands at the next column's start: shift them back.
        for (int c = _columns; c > 0; c--)
            _start[c] = _start[c - 1];
        _start[0] = 0;
        for (int c = 0; c < _columns; c++)
            Array.Sort(_south, _order, _start[c], _start[c + 1] - _start[c]);
        for (int k = 0; k < _narrow; k++)
        {
            ref readonly var slot = ref slots[_order[k]];
            _box[k] = new ObjectCull.ReachBox(slot.ReachMin, slot.ReachMax);
        }
    }

    /// <summary>
    /// The column of a west edge <paramref name="x"/>, clamped to the columns there are: never decreasing in
    /// <paramref name="x"/> (a difference, a quotient by a positive constant, a clamp and a truncation each keep
    /// the order), so the objects whose west edge lies in from..to are in the columns of from to that of to.
    /// </summary>
    private int Column(float x) => (int)MathF.Max(0f, MathF.Min((x - _west0) / ColumnWidth, _columns - 1));

    /// <summary>
    /// Writes to <paramref name="found"/>, in ascending slot order, every object of <paramref name="slots"/> (the
    /// list the index was built from) whose reach box meets <paramref name="min"/>..<paramref name="max"/> by the
    /// registry's box test (<see cref="ObjectCull.ReachBox.Meets"/>); returns how many. <paramref name="found"/>
    /// must hold the cell's object count. The bounds must be finite (the caller reads the cell in full otherwise).
    /// </summary>
    public int Meeting(Vector3 min, Vector3 max, ReadOnlySpan<ShadowObjectRegistry.Slot> slots, Span<int> found)
    {
        // An object meets min..max on X only if its box's west edge is at most max.X and its east edge at least
        // min.X, so its west edge is at least min.X less its width; the same on Y with the south edge. The other
        // objects fail the box test and are not read. The margins cover the rounding of the widths (coordinates
        // within a few hundred metres: an ulp is below 1e-4 m).
        float fromX = min.X - _widthX - 0.01f;
        float fromY = min.Y - _widthY - 0.01f;
        int n = 0;
        if (_narrow > 0)
        {
            int last = Column(max.X);
            for (int c = Column(fromX); c <= last; c++)
            {
                int end = _start[c + 1];
                for (int k = LowerBound(_start[c], end, fromY); k < end && _south[k] <= max.Y; k++)
                    if (_box[k].Meets(min, max))
                        found[n++] = _order[k];
            }
        }
        for (int w = 0; w < _wideCount; w++)
        {
            ref readonly var slot = ref slots[_wide[w]];
            if (new ObjectCull.ReachBox(slot.ReachMin, slot.ReachMax).Meets(min, max))
                found[n++] = _wide[w];
        }
        found[..n].Sort();
        return n;
    }

    /// <summary>The first place in _south[lo..hi) whose edge is at least <paramref name="key"/> (hi when none).</summary>
    private int LowerBound(int lo, int hi, float key)
    {
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            if (_south[mid] < key)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    }
}
