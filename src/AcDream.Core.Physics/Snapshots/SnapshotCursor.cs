using System;
using System.Buffers;
using System.Buffers.Binary;
using System.IO;
using System.Numerics;

namespace AcDream.Core.Physics.Snapshots;

/// <summary>Little-endian writes into a growing buffer (the snapshot writer).</summary>
internal sealed class SnapshotWriter
{
    private readonly ArrayBufferWriter<byte> _buffer = new(256);

    public int Length => _buffer.WrittenCount;

    private void Advance(int n) => _buffer.Advance(n);

    public void Byte(byte v) { _buffer.GetSpan(1)[0] = v; Advance(1); }
    public void U16(ushort v) { BinaryPrimitives.WriteUInt16LittleEndian(_buffer.GetSpan(2), v); Advance(2); }
    public void U32(uint v) { BinaryPrimitives.WriteUInt32LittleEndian(_buffer.GetSpan(4), v); Advance(4); }
    public void F32(float v) { BinaryPrimitives.WriteSingleLittleEndian(_buffer.GetSpan(4), v); Advance(4); }
    public void F64(double v) { BinaryPrimitives.WriteDoubleLittleEndian(_buffer.GetSpan(8), v); Advance(8); }
    public void Vec(Vector3 v) { F32(v.X); F32(v.Y); F32(v.Z); }

    public void Quat(Quaternion q) { F32(q.X); F32(q.Y); F32(q.Z); F32(q.W); }

    public void Position(in Position p)
    {
        U32(p.CellId);
        Vec(p.Frame.Origin);
        Quat(p.Frame.Orientation);
    }

    /// <summary>Writes a section length placeholder and returns where it is.</summary>
    public int BeginSection(byte tag)
    {
        Byte(tag);
        int at = Length;
        U32(0);
        return at;
    }

    /// <summary>The bytes written, with each section's length filled in.</summary>
    public byte[] Finish(ReadOnlySpan<int> sectionStarts)
    {
        var bytes = _buffer.WrittenSpan.ToArray();
        for (int i = 0; i < sectionStarts.Length; i++)
        {
            int at = sectionStarts[i];
            int end = i + 1 < sectionStarts.Length ? sectionStarts[i + 1] - 1 : bytes.Length;
            BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(at), (uint)(end - at - 4));
        }
        return bytes;
    }
}

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
