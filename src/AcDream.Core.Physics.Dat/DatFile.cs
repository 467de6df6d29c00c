using System;
using System.Buffers.Binary;
using System.IO;
using DatReaderWriter;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.IO;
using DatReaderWriter.Lib.IO.DatBTree;
using DatReaderWriter.Options;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// One DAT file opened read-only (other readers, the game client too, may keep it open) with typed reads by id.
/// The header is checked before DatReaderWriter walks the file: a file that is not a DAT, or the other one of the
/// two, never reaches its index. Reads are serialised (one at a time per file), so any thread may read.
/// </summary>
internal sealed class DatFile : IDisposable
{
    /// <summary>The largest object read, bytes (retail's largest physics objects are well under 1 MB).</summary>
    public const int MaxObjectBytes = 16 * 1024 * 1024;

    // The header's layout (DatHeader.Unpack): a 256-byte version string, 64 bytes of transactions, then the magic,
    // block size, file size and file type as 32-bit little-endian words.
    private const int HeaderBytes = 400, MagicOffset = 320, TypeOffset = 332;

    private readonly DatDatabase _database;
    private readonly object _gate = new();

    private DatFile(string path, string name, DatFileType type, DatDatabase database)
    {
        Type = type;
        Path = path;
        Name = name;
        _database = database;
    }

    /// <summary>Portal or cell.</summary>
    public DatFileType Type { get; }
    /// <summary>The file's path as given.</summary>
    public string Path { get; }
    /// <summary>The file's name, used in every message.</summary>
    public string Name { get; }

    /// <summary>Opens a DAT file of the expected type, read-only and shared.</summary>
    /// <exception cref="DatReadException">The file is missing, unreadable, not a DAT file, or of the other type.</exception>
    public static DatFile Open(string path, DatFileType expected)
    {
        ArgumentNullException.ThrowIfNull(path);
        string name = System.IO.Path.GetFileName(path);
        if (!File.Exists(path))
            throw new DatReadException(name, null, $"does not exist ({path}).");
        CheckHeader(path, name, expected);
        try
        {
            var database = new DatDatabase(o =>
            {
                o.FilePath = path;
                o.AccessType = DatAccessType.Read;
                // The adapter caches what it converts; DatReaderWriter's own object cache would hold every raw object too.
                o.FileCachingStrategy = FileCachingStrategy.Never;
                o.IndexCachingStrategy = IndexCachingStrategy.OnDemand;
            });
            return new DatFile(path, name, expected, database);
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            throw new DatReadException(name, null, $"cannot be opened: {ex.Message}", ex);
        }
    }

    private static void CheckHeader(string path, string name, DatFileType expected)
    {
        var header = new byte[HeaderBytes];
        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
            if (stream.Length < HeaderBytes)
                throw new DatReadException(name, null, $"is not a DAT file ({stream.Length} bytes, shorter than its {HeaderBytes}-byte header).");
            stream.ReadExactly(header);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new DatReadException(name, null, $"cannot be read: {ex.Message}", ex);
        }
        int magic = BinaryPrimitives.ReadInt32LittleEndian(header.AsSpan(MagicOffset));
        if (magic != DatHeader.RETAIL_MAGIC)
            throw new DatReadException(name, null, $"is not a DAT file (magic 0x{magic:X8}, expected 0x{DatHeader.RETAIL_MAGIC:X8}).");
        var type = (DatFileType)BinaryPrimitives.ReadUInt32LittleEndian(header.AsSpan(TypeOffset));
        if (type != expected)
            throw new DatReadException(name, null, $"is a {Describe(type)} DAT file, expected a {Describe(expected)} DAT file.");
    }

    private static string Describe(DatFileType type) => type switch
    {
        DatFileType.Portal => "portal",
        DatFileType.Cell => "cell",
        DatFileType.Local => "local (language)",
        _ => $"type {(uint)type}",
    };

    /// <summary>Told the id of every object about to be unpacked (tests count the reads a load makes through it).</summary>
    internal Action<uint>? Unpacking { get; set; }

    /// <summary>Whether the file holds an object with this id.</summary>
    public bool Contains(uint id)
    {
        lock (_gate)
            return _database.Tree.TryGetFile(id, out _);
    }

    /// <summary>Reads the object <paramref name="id"/> as a <typeparamref name="T"/>.</summary>
    /// <exception cref="DatReadException">The object is absent, its id names another type, it is larger than
    /// <see cref="MaxObjectBytes"/> (stored, or inflated when compressed), or it cannot be unpacked.</exception>
    public T Read<T>(uint id) where T : DBObj
    {
        var kind = Kind<T>.Value;
        if (kind.File != Type)
            throw new ArgumentException($"{typeof(T).Name} is a {Describe(kind.File)} DAT object; {Name} is the {Describe(Type)} DAT.", nameof(T));
        lock (_gate)
        {
            if (!_database.Tree.TryGetFile(id, out var entry))
                throw new DatReadException(Name, id, $"is absent (expected a {kind.ObjectType}).");
            var actual = DatObjectKinds.Of(Type, id) ?? _database.TypeFromId(id);
            if (actual != kind.ObjectType)
                throw new DatReadException(Name, id, $"is a {actual}, not a {kind.ObjectType}.");
            if (entry.Size > MaxObjectBytes)
                throw new DatReadException(Name, id, $"is {entry.Size} bytes, more than the {MaxObjectBytes} read.");
            if (entry.Flags.HasFlag(DatBTreeFileFlags.IsCompressed))
                CheckInflatedSize(id, entry.Offset, entry.Size);
            Unpacking?.Invoke(id);
            try
            {
                if (_database.TryGet<T>(id, out var value) && value is not null)
                    return value;
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                throw new DatReadException(Name, id, $"cannot be read as a {kind.ObjectType}: {ex.Message}", ex);
            }
            throw new DatReadException(Name, id, $"cannot be read as a {kind.ObjectType}.");
        }
    }

    // A compressed object starts with its inflated size, which DatReaderWriter allocates before inflating (up to
    // 4 GB from a damaged word): the word is read first, from the object's first block, and capped as the stored
    // size is.
    private void CheckInflatedSize(uint id, int firstBlock, uint storedSize)
    {
        if (storedSize < sizeof(uint))
            return;     // DatReaderWriter keeps so short an object as it is
        var head = new byte[sizeof(uint)];
        try
        {
            _database.BlockAllocator.ReadBlock(head, firstBlock);
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            throw new DatReadException(Name, id, $"cannot be read: {ex.Message}", ex);
        }
        uint inflated = BinaryPrimitives.ReadUInt32LittleEndian(head);
        if (inflated > MaxObjectBytes)
            throw new DatReadException(Name, id, $"inflates to {inflated} bytes, more than the {MaxObjectBytes} read.");
    }

    /// <summary>DatReaderWriter's own answer for the type of an id in this file (tests compare <see cref="DatObjectKinds"/> with it).</summary>
    internal DBObjType TypeFromIdAsReaderSays(uint id)
    {
        lock (_gate)
            return _database.TypeFromId(id);
    }

    /// <summary>Closes the file.</summary>
    public void Dispose()
    {
        lock (_gate)
            _database.Dispose();
    }

    // What DatReaderWriter's generated type says of itself (its attribute): its file and its object type.
    private static class Kind<T> where T : DBObj
    {
        public static readonly DatObjectKinds.Kind Value = DatObjectKinds.OfType(typeof(T))
            ?? throw new InvalidOperationException($"{typeof(T).Name} is not a DAT object type.");
    }
}
