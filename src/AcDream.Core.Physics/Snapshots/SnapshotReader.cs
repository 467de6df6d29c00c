using System;
using System.Buffers.Binary;
using System.IO;
using System.Numerics;

namespace AcDream.Core.Physics.Snapshots;

/// <summary>
/// Little-endian reads from a snapshot's bytes that never read past the end: every read names its field,
/// and a short, non-finite or out-of-range value throws <see cref="InvalidDataException"/> with the field and
/// the byte offset.
/// </summary>
internal ref struct SnapshotReader
{
    private readonly ReadOnlySpan<byte> _data;
    private readonly int _base;
    private int _at;

    public SnapshotReader(ReadOnlySpan<byte> data, int baseOffset = 0)
    {
        _data = data;
        _base = baseOffset;
        _at = 0;
    }

    public readonly int Remaining => _data.Length - _at;

    private ReadOnlySpan<byte> Take(int n, string field)
    {
        if (Remaining < n)
            throw Fail(field, $"needs {n} bytes, {Remaining} left");
        var span = _data.Slice(_at, n);
        _at += n;
        return span;
    }

    public readonly InvalidDataException Fail(string field, string what) =>
        new($"snapshot {field} (byte {_base + _at}): {what}.");

    public byte U8(string field) => Take(1, field)[0];
    public ushort U16(string field) => BinaryPrimitives.ReadUInt16LittleEndian(Take(2, field));
    public uint U32(string field) => BinaryPrimitives.ReadUInt32LittleEndian(Take(4, field));

    public float F32(string field)
    {
        float v = BinaryPrimitives.ReadSingleLittleEndian(Take(4, field));
        if (!float.IsFinite(v))
            throw Fail(field, $"must be finite, got {v}");
        return v;
    }

    public double F64(string field)
    {
        double v = BinaryPrimitives.ReadDoubleLittleEndian(Take(8, field));
        if (!double.IsFinite(v))
            throw Fail(field, $"must be finite, got {v}");
        return v;
    }

    public Vector3 Vec(string field) => new(F32(field + ".x"), F32(field + ".y"), F32(field + ".z"));

    public Position Position(string field)
    {
        uint cell = U32(field + ".cell");
        var origin = Vec(field + ".origin");
        return new Position(cell, new Frame(origin, Quat(field + ".orientation")));
    }

    public Quaternion Quat(string field) => new(F32(field + ".x"), F32(field + ".y"), F32(field + ".z"), F32(field + ".w"));

    public void Skip(int n, string field) => Take(n, field);

    /// <summary>The next <paramref name="n"/> bytes as a reader of their own.</summary>
    public SnapshotReader Section(int n, string field)
    {
        int start = _base + _at;
        return new SnapshotReader(Take(n, field), start);
    }
}
