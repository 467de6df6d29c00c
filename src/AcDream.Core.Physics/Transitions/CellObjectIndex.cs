using System;
using System.Numerics;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// A crowded cell's objects sorted by the west edge of their reach boxes (not retail; changes no result), so
/// that the object cull finds the objects whose reach box meets a region without reading the whole cell. A pile
/// of creatures puts hundreds of objects in one 24 m cell, and every mover's transition makes a region of its
/// own: read in full, the cell costs each mover time in proportion to the pile, and the tick the square of it.
/// Built for one registry version (every move makes a new one) the first time an engine lists the cell in it;
/// an engine keeps a few such indexes and reuses their arrays, so nothing is allocated once they have grown.
/// The index keeps each object's reach box beside its place in the west-edge order and tests the objects of the
/// region's band there with the registry's own box test, so only the objects that meet the region are looked up
/// in the cell and put back in the cell's order: it names exactly the objects the full read would, in the same
/// order.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.CellObjectIndex"/> (not retail; taken in <see cref="ObjectCull"/>). Skips: reading
/// every object of a crowded cell to list the cull's candidates. Same result: the very list, in the very order
/// (above). Proof: CellObjectIndexTests, CrowdObjectPassTests and the crowd replays, and the suite with shortcuts off.
/// </remarks>
internal sealed class CellObjectIndex
{
    /// <summary>Cells listing fewer objects are read in full: the sort would cost more than it saves.</summary>
    public const int MinObjects = 48;

    /// <summary>Objects whose reach box is wider (west to east) than this are kept apart and always read.</summary>
    private const float WideObject = 6f;

    // The narrow objects' slot indices, sorted by their reach boxes' west edge, the edges, and beside each its
    // reach box (the slot's, copied: the band is tested here, in order, without reading the cell's list).
    private int[] _order = new int[64];
    private float[] _west = new float[64];
    private ObjectCull.ReachBox[] _box = new ObjectCull.ReachBox[64];
    private int _narrow;
    // The widest narrow object's box (west to east), and the wide objects' slot indices (ascending).
    private float _width;
    private int[] _wide = new int[8];
    private int _wideCount;

    /// <summary>The cell this index is of.</summary>
    public uint CellId { get; private set; }

    /// <summary>The registry version this index was built at.</summary>
    public int Version { get; private set; } = -1;

    /// <summary>Sorts the cell's objects (<paramref name="slots"/>, the registry's list at <paramref name="version"/>).</summary>
    public void Build(uint cellId, int version, ReadOnlySpan<ShadowObjectRegistry.Slot> slots)
    {
        CellId = cellId;
        Version = version;
        if (_order.Length < slots.Length)
        {
            _order = new int[slots.Length * 2];
            _west = new float[slots.Length * 2];
            _box = new ObjectCull.ReachBox[slots.Length * 2];
        }
        _narrow = 0;
        _wideCount = 0;
        _width = 0f;
        for (int i = 0; i < slots.Length; i++)
        {
            ref readonly var slot = ref slots[i];
            float width = slot.ReachMax.X - slot.ReachMin.X;
            // A NaN width (never expected: positions are checked) counts as wide, so it is always read.
            if (!(width <= WideObject))
            {
                if (_wideCount == _wide.Length)
                    Array.Resize(ref _wide, _wideCount * 2);
                _wide[_wideCount++] = i;
                continue;
            }
            _width = MathF.Max(_width, width);
            _order[_narrow] = i;
            _west[_narrow] = slot.ReachMin.X;
            _narrow++;
        }
        Array.Sort(_west, _order, 0, _narrow);
        for (int k = 0; k < _narrow; k++)
        {
            ref readonly var slot = ref slots[_order[k]];
            _box[k] = new ObjectCull.ReachBox(slot.ReachMin, slot.ReachMax);
        }
    }

    /// <summary>
    /// Writes to <paramref name="found"/>, in ascending slot order, every object of <paramref name="slots"/> (the
    /// list the index was built from) whose reach box meets <paramref name="min"/>..<paramref name="max"/> by the
    /// registry's box test (<see cref="ObjectCull.ReachBox.Meets"/>); returns how many. <paramref name="found"/>
    /// must hold the cell's object count.
    /// </summary>
    public int Meeting(Vector3 min, Vector3 max, ReadOnlySpan<ShadowObjectRegistry.Slot> slots, Span<int> found)
    {
        // An object meets min..max on X only if its box's west edge is at most max.X and its east edge at least
        // min.X, so its west edge is at least min.X less its width: the objects before that edge and after max.X
        // fail the box test and are not read. The margin covers the rounding of the widths (coordinates within a
        // few hundred metres: an ulp is below 1e-4 m).
        float from = min.X - _width - 0.01f;
        int lo = LowerBound(from);
        int n = 0;
        for (int k = lo; k < _narrow && _west[k] <= max.X; k++)
            if (_box[k].Meets(min, max))
                found[n++] = _order[k];
        for (int w = 0; w < _wideCount; w++)
        {
            ref readonly var slot = ref slots[_wide[w]];
            if (new ObjectCull.ReachBox(slot.ReachMin, slot.ReachMax).Meets(min, max))
                found[n++] = _wide[w];
        }
        // Not-a-number bounds (never expected: the region is checked finite) find nothing here; the caller
        // falls back to the full read for them.
        found[..n].Sort();
        return n;
    }

    private int LowerBound(float key)
    {
        int lo = 0, hi = _narrow;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            if (_west[mid] < key)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo;
    }
}
