using System;
using System.Collections.Concurrent;
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
    private readonly ConcurrentDictionary<(Type Kind, uint Id), Lazy<object>> _objects = new();

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
        var entry = _objects.GetOrAdd(key, static (k, a) => new Lazy<object>(() => a.convert(k.Id, a.state), LazyThreadSafetyMode.ExecutionAndPublication), (convert, state));
        try
        {
            return (T)entry.Value;
        }
        catch
        {
            // Lazy keeps an exception; the cache does not: remove exactly this entry so a later request retries.
            _objects.TryRemove(new System.Collections.Generic.KeyValuePair<(Type, uint), Lazy<object>>(key, entry));
            throw;
        }
    }

    /// <summary>The <typeparamref name="T"/> of this id when it is held and converted, without converting anything.</summary>
    internal bool TryGet<T>(uint id, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out T? value) where T : class
    {
        if (_objects.TryGetValue((typeof(T), id), out var entry) && entry.IsValueCreated)
        {
            value = (T)entry.Value;
            return true;
        }
        value = null;
        return false;
    }

    /// <summary>Whether a <typeparamref name="T"/> of this id is held.</summary>
    public bool Contains<T>(uint id) where T : class => _objects.TryGetValue((typeof(T), id), out var e) && e.IsValueCreated;

    /// <summary>Forgets every object (worlds keep those they hold).</summary>
    public void Clear() => _objects.Clear();
}
