using System.Runtime.CompilerServices;
using System.Collections.Generic;

namespace AcDream.Core.Physics.World;

/// <summary>The cells a sphere path touches (retail CELLARRAY): unique, in discovery order, reused without allocation.</summary>
internal sealed class CellArray
{
    private readonly List<Cell> _cells = new(16);

    /// <summary>The cells.</summary>
    public IReadOnlyList<Cell> Cells => _cells;
    /// <summary>How many cells.</summary>
    public int Count => _cells.Count;
    /// <summary>The i-th cell.</summary>
    public Cell this[int index] => _cells[index];

    /// <summary>Empties the array.</summary>
    public void Clear() => _cells.Clear();

    /// <summary>Adds a cell unless present.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Add(Cell cell)
    {
        for (int i = 0; i < _cells.Count; i++)
            if (ReferenceEquals(_cells[i], cell))
                return;
        _cells.Add(cell);
    }
}
