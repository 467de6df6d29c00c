using System;
using System.Buffers;
using System.Buffers.Binary;
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
