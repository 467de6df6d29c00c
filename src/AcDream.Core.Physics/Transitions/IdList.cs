using System;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// Object ids in the order first added, each once (retail COLLISIONINFO::add_object's list), reused from
/// call to call without allocation once grown. Handed out as <see cref="Items"/>, valid until the next
/// <see cref="Clear"/>: a list that outgrows its buffer moves to a larger one, so ids handed out earlier
/// stay intact.
/// </summary>
internal sealed class IdList
{
    private uint[] _ids = new uint[8];
    private int _count;

    /// <summary>The ids, in order.</summary>
    public ReadOnlyMemory<uint> Items => new(_ids, 0, _count);

    /// <summary>Empties the list (keeps the buffer).</summary>
    public void Clear() => _count = 0;

    /// <summary>Adds an id unless present; true when it was added.</summary>
    public bool Add(uint id)
    {
        for (int i = 0; i < _count; i++)
            if (_ids[i] == id)
                return false;
        if (_count == _ids.Length)
            Array.Resize(ref _ids, _ids.Length * 2);
        _ids[_count++] = id;
        return true;
    }
}
