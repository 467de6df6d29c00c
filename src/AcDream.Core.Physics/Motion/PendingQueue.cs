using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The first-in, first-out list of motions waiting for their animations, as the motion interpreter
/// (CMotionInterp::pending_motions) and the motion table manager (MotionTableManager::pending_animations)
/// each keep one: appended at the end, completed from the front, read and edited in place, and replaced
/// whole by a snapshot's load. Grows by doubling and never shrinks, so a steady state allocates nothing.
/// </summary>
internal sealed class PendingQueue<T> where T : struct
{
    private T[] _items = new T[8];

    /// <summary>How many entries are queued.</summary>
    public int Count { get; private set; }

    /// <summary>The entry <paramref name="index"/> places from the front (0: the oldest), by reference.</summary>
    public ref T this[int index] => ref _items[index];

    public void Add(in T item)
    {
        if (Count == _items.Length)
            Array.Resize(ref _items, _items.Length * 2);
        _items[Count++] = item;
    }

    /// <summary>Drops the oldest entry; nothing when the queue is empty.</summary>
    public void RemoveFirst()
    {
        if (Count == 0)
            return;
        Count--;
        Array.Copy(_items, 1, _items, 0, Count);
    }

    /// <summary>Replaces the whole queue by <paramref name="items"/> (a snapshot's load).</summary>
    public void Restore(ReadOnlySpan<T> items)
    {
        if (_items.Length < items.Length)
            _items = new T[items.Length];
        items.CopyTo(_items);
        Array.Clear(_items, items.Length, _items.Length - items.Length);
        Count = items.Length;
    }
}
