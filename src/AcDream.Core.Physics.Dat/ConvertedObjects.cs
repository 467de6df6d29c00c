using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Threading;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// The objects converted from a pair of DAT files (models, setups, cell structures, motion tables), by their type
/// and DAT id: each is converted once and shared by every world loaded from those files, since the runtime's
/// models are immutable. Safe for any number of threads: two asking at once for the same id get the same object,
/// converted once; a conversion that throws is not kept (the next request tries again and throws the same way).
/// </summary>
public sealed class ConvertedObjects
{
    private readonly ConcurrentDictionary<(Type Kind, uint Id), Entry> _objects = new();

    // One id's object: converted under the entry's lock by the first thread to ask, waited for by the others. A
    // landblock's load makes one per object it converts, so an entry is one small object (no Lazy, closure or
    // delegate per conversion).
    private sealed class Entry
    {
        private object? _value;
        private volatile bool _done;   // written after _value: a reader that sees it set sees the value
        private int _converter;   // the managed id of the thread converting, 0 when none
        public bool Removed;      // set, under the lock, when a conversion failed and the entry left the cache

        public bool TryGetValue(out object? value)
        {
            bool done = _done;
            value = done ? _value : null;
            return done;
        }

        // The value, converting it on the first call (it may be null); false when the entry was removed meanwhile
        // (ask the cache again).
        public bool TryGetOrConvert<TState, T>(ConvertedObjects cache, (Type, uint) key, TState state, Func<uint, TState, T> convert, out object? result) where T : class
        {
            lock (this)
            {
                result = _value;
                if (_done)
                    return true;
                if (Removed)
                    return false;
                if (_converter == Environment.CurrentManagedThreadId)
                    throw new InvalidOperationException($"converting {key.Item1.Name} 0x{key.Item2:X8} asked for itself.");
                _converter = Environment.CurrentManagedThreadId;
                try
                {
                    result = _value = convert(key.Item2, state);
                    _done = true;
                    return true;
                }
                catch
                {
                    // The cache keeps no failure: remove exactly this entry so a later request converts again.
                    Removed = true;
                    cache._objects.TryRemove(new KeyValuePair<(Type, uint), Entry>(key, this));
                    throw;
                }
                finally
                {
                    _converter = 0;
                }
            }
        }
    }

    /// <summary>How many objects are held.</summary>
    public int Count => _objects.Count;

    /// <summary>The <typeparamref name="T"/> converted from DAT object <paramref name="id"/>, converting it on the first request.</summary>
    /// <param name="id">The DAT id.</param>
    /// <param name="convert">Reads and converts the object (called at most once per id at a time).</param>
    public T GetOrAdd<T>(uint id, Func<uint, T> convert) where T : class
    {
        ArgumentNullException.ThrowIfNull(convert);
        return GetOrAdd(id, convert, static (i, c) => c(i));
    }

    /// <summary>As <see cref="GetOrAdd{T}(uint, Func{uint, T})"/>, the conversion given what it needs: no closure is made unless it runs.</summary>
    internal T GetOrAdd<T, TState>(uint id, TState state, Func<uint, TState, T> convert) where T : class
    {
        var key = (typeof(T), id);
        while (true)
        {
            if (_objects.TryGetValue(key, out var entry) && entry.TryGetValue(out var held))
                return (T)held!;
            entry = _objects.GetOrAdd(key, static _ => new Entry());
            if (entry.TryGetOrConvert(this, key, state, convert, out var value))
                return (T)value!;
            // The entry's conversion failed in another thread and was removed: ask again.
        }
    }

    /// <summary>The <typeparamref name="T"/> of this id when it is held and converted, without converting anything.</summary>
    internal bool TryGet<T>(uint id, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out T? value) where T : class
    {
        if (_objects.TryGetValue((typeof(T), id), out var entry) && entry.TryGetValue(out var held) && held is not null)
        {
            value = (T)held;
            return true;
        }
        value = null;
        return false;
    }

    /// <summary>Whether a <typeparamref name="T"/> of this id is held.</summary>
    public bool Contains<T>(uint id) where T : class => _objects.TryGetValue((typeof(T), id), out var e) && e.TryGetValue(out _);

    /// <summary>Forgets every object (worlds keep those they hold).</summary>
    public void Clear() => _objects.Clear();
}
