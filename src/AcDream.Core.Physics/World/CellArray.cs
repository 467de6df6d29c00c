using System;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.World;

/// <summary>The cells a sphere path touches (retail CELLARRAY): unique, in discovery order, reused without allocation.</summary>
internal sealed class CellArray
{
    // Cells are kept inside a struct: storing a reference into a Cell[] pays the runtime's covariant array
    // store check on every write, storing into a struct element does not.
    private struct Entry
    {
        public Cell Cell;
    }

    private Entry[] _entries = new Entry[16];
    private int _count;

    /// <summary>How many cells.</summary>
    public int Count => _count;

    /// <summary>The i-th cell.</summary>
    public Cell this[int index]
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get
        {
            if ((uint)index >= (uint)_count)
                ThrowIndex(index);
            return _entries[index].Cell;
        }
    }

    /// <summary>
    /// Empties the array. The references stay in the slots until overwritten: they are cells of the world,
    /// which outlives every transition, so nothing is kept alive that would otherwise be collected.
    /// </summary>
    public void Clear() => _count = 0;

    /// <summary>Adds a cell unless present.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Add(Cell cell)
    {
        var entries = _entries;
        int count = _count;
        foreach (ref readonly var entry in new ReadOnlySpan<Entry>(entries, 0, count))
            if (ReferenceEquals(entry.Cell, cell))
                return;
        if (count < entries.Length)
        {
            // The slot often holds this cell already from the previous search (Clear leaves it): then the
            // store, and its GC write barrier, is skipped.
            if (!ReferenceEquals(entries[count].Cell, cell))
                entries[count].Cell = cell;
            _count = count + 1;
            return;
        }
        Grow(cell);
    }

    private void Grow(Cell cell)
    {
        Array.Resize(ref _entries, _entries.Length * 2);
        _entries[_count++].Cell = cell;
    }

    private static void ThrowIndex(int index) =>
        throw new ArgumentOutOfRangeException(nameof(index), $"cell array index {index} is out of range.");
}
