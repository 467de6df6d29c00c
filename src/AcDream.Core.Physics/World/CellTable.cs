using System;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.World;

/// <summary>
/// Values keyed by cell id, for lookups on the per-frame path: outdoor cells (index 1..64) by arrays (landblock
/// x byte, then y byte, then cell index − 1), so a lookup is three array reads instead of a hash; indoor
/// cells the same way (cell index − 0x100, the landblock's array grown to the largest index set), since a
/// camera arm or a mover indoors looks its cells up several times per sub-step. Single writer; readers may
/// run in parallel while nothing writes.
/// A struct, kept in a readonly field of its owner, so a lookup starts from the owner (one pointer fewer to
/// follow); create it with <c>new()</c>.
/// </summary>
internal readonly struct CellTable<T> where T : class
{
    private readonly T?[]?[]?[] _land;
    private readonly T?[]?[]?[] _indoor;

    // The first indoor cell index (retail's env cells are 0x100..0xFFFD).
    private const uint FirstIndoor = 0x100;

    /// <summary>Creates an empty table.</summary>
    public CellTable()
    {
        _land = new T?[]?[]?[256];
        _indoor = new T?[]?[]?[256];
    }

    /// <summary>The value for a cell, or null.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public T? Get(uint cellId)
    {
        uint index = (cellId & 0xFFFF) - 1;
        if (index < 64)
            return _land[cellId >> 24]?[(cellId >> 16) & 0xFF]?[index];
        return GetIndoor(cellId);
    }

    /// <summary>
    /// The value for the outdoor cell at global land-cell coordinates (0..2039 on each axis, see
    /// <see cref="LandDefs.LandCellAtGlobal"/>), or null (also outside the world).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public T? GetLandAtGlobal(int gx, int gy)
    {
        if ((uint)gx >= LandDefs.CellsPerSide || (uint)gy >= LandDefs.CellsPerSide)
            return null;
        return _land[gx >> 3]?[gy >> 3]?[(gx & 7) * 8 + (gy & 7)];
    }

    /// <summary>Sets the value for a cell.</summary>
    public void Set(uint cellId, T value)
    {
        uint index = (cellId & 0xFFFF) - 1;
        if (index < 64)
        {
            var column = _land[cellId >> 24] ??= new T?[]?[256];
            var block = column[(cellId >> 16) & 0xFF] ??= new T?[64];
            block[index] = value;
        }
        else
        {
            uint at = (cellId & 0xFFFF) - FirstIndoor;
            var column = _indoor[cellId >> 24] ??= new T?[]?[256];
            ref var block = ref column[(cellId >> 16) & 0xFF];
            if (block is null || at >= block.Length)
            {
                // Grown to hold the index (doubling, at least 16): built once per landblock load.
                var grown = new T?[Math.Max(Math.Max(16, (int)at + 1), block is null ? 0 : block.Length * 2)];
                block?.CopyTo(grown, 0);
                block = grown;
            }
            block[at] = value;
        }
    }

    /// <summary>
    /// Forgets the value for a cell (a landblock being unloaded). The landblock's array stays for the next
    /// load, so removing and adding again allocates nothing.
    /// </summary>
    public void Remove(uint cellId)
    {
        uint index = (cellId & 0xFFFF) - 1;
        if (index < 64)
        {
            if (_land[cellId >> 24]?[(cellId >> 16) & 0xFF] is { } block)
                block[index] = null;
        }
        else
        {
            uint at = (cellId & 0xFFFF) - FirstIndoor;
            if (_indoor[cellId >> 24]?[(cellId >> 16) & 0xFF] is { } block && at < block.Length)
                block[at] = null;
        }
    }

    // Apart so that Get inlines: the outdoor path is the array reads.
    private T? GetIndoor(uint cellId)
    {
        uint at = (cellId & 0xFFFF) - FirstIndoor;
        return _indoor[cellId >> 24]?[(cellId >> 16) & 0xFF] is { } block && at < (uint)block.Length ? block[at] : null;
    }
}
