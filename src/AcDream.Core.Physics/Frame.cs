using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics;

/// <summary>
/// A placement: an origin and a unit orientation (retail Frame). Local↔global transforms rotate
/// first, then translate, through the rotation matrix retail caches on each frame (see
/// <see cref="RotationMatrix"/>). <c>default(Frame)</c> and <c>new Frame { Origin = p }</c> have the
/// identity rotation.
/// </summary>
public struct Frame
{
    /// <summary>The origin in the parent space.</summary>
    public Vector3 Origin;

    // The orientation's X, Y, Z and W. W is kept as its bits xor 1f's bits, so that the all-zero
    // frame (default, or an object initializer that sets only Origin) is the identity rotation
    // instead of a zero quaternion; the xor round-trips every value exactly.
    private float _qx, _qy, _qz;
    private uint _qwXorOne;

    private const uint OneBits = 0x3F80_0000;

    /// <summary>Creates a frame.</summary>
    public Frame(Vector3 origin, Quaternion orientation)
    {
        Origin = origin;
        _qx = orientation.X;
        _qy = orientation.Y;
        _qz = orientation.Z;
        _qwXorOne = BitConverter.SingleToUInt32Bits(orientation.W) ^ OneBits;
    }

    /// <summary>A frame at <paramref name="origin"/> with no rotation.</summary>
    public Frame(Vector3 origin) : this(origin, Quaternion.Identity) { }

    /// <summary>The identity frame.</summary>
    public static Frame Identity => default;

    /// <summary>The orientation, a unit quaternion (the identity in a default frame).</summary>
    public Quaternion Orientation
    {
        readonly get => new(_qx, _qy, _qz, Qw);
        set
        {
            _qx = value.X;
            _qy = value.Y;
            _qz = value.Z;
            _qwXorOne = BitConverter.SingleToUInt32Bits(value.W) ^ OneBits;
        }
    }

    private readonly float Qw => BitConverter.UInt32BitsToSingle(_qwXorOne ^ OneBits);

    /// <summary>
    /// The orientation's stored bits as they lie in the frame (W still xor-ed with 1f's bits): equal keys
    /// mean bit-identical orientations, so the memos compare these without rebuilding the quaternion.
    /// </summary>
    internal readonly Vector128<int> OrientationKey =>
        Unsafe.ReadUnaligned<Vector128<int>>(ref Unsafe.As<float, byte>(ref Unsafe.AsRef(in _qx)));

    /// <summary>The rotation matrix retail caches for this frame (Frame::cache).</summary>
    internal readonly RotationMatrix Matrix => new(Qw, _qx, _qy, _qz);

    /// <summary>Maps a point from this frame's space into the parent space (retail Frame::localtoglobal).</summary>
    public readonly Vector3 LocalToGlobal(Vector3 point) => Matrix.FrameToGlobal(point, Origin);

    /// <summary>Maps a point from the parent space into this frame's space (retail Frame::globaltolocal: the transpose).</summary>
    public readonly Vector3 GlobalToLocal(Vector3 point) => Matrix.FrameToLocal(point, Origin);

    /// <summary>Rotates a direction from this frame's space into the parent space (retail Frame::localtoglobalvec).</summary>
    public readonly Vector3 LocalToGlobalVec(Vector3 vector) => Matrix.FrameToGlobal(vector);

    /// <summary>Rotates a direction from the parent space into this frame's space (retail Frame::globaltolocalvec: the transpose).</summary>
    public readonly Vector3 GlobalToLocalVec(Vector3 vector) => Matrix.FrameToLocal(vector);

    /// <summary>
    /// Composes: a child frame given in this frame's space, expressed in the parent space (retail
    /// Frame::combine as used for an object's parts, acclient.c:326562: the origin through the matrix,
    /// the quaternion product in retail's order, then normalized as set_rotate does; in double, as
    /// retail's x87 code runs, see <see cref="RotationMatrix"/>).
    /// </summary>
    public readonly Frame Combine(in Frame child)
    {
        double w1 = Qw, x1 = _qx, y1 = _qy, z1 = _qz;
        double w2 = child.Qw, x2 = child._qx, y2 = child._qy, z2 = child._qz;
        float qz = (float)(w1 * z2 + x1 * y2 - x2 * y1 + w2 * z1);
        float qy = (float)(w1 * y2 - x1 * z2 + x2 * z1 + w2 * y1);
        float qx = (float)(x2 * w1 + w2 * x1 + z2 * y1 - y2 * z1);
        float qw = (float)(w2 * w1 - x2 * x1 - y2 * y1 - z2 * z1);
        var result = new Frame(Matrix.FrameToGlobal(child.Origin, Origin));
        result.SetRotate(qw, qx, qy, qz);
        return result;
    }

    /// <summary>
    /// Takes a child frame back off (retail Frame::subtract1, CFrame.c at acclient.c:357321, the exact inverse of
    /// <see cref="Combine"/>): the rotation this × child⁻¹ in retail's order, normalized as set_rotate does,
    /// then the child's origin rotated by that new rotation and taken away, the rotated x and y rounded to float
    /// before the origin is added (<see cref="RotationMatrix.SubtractToGlobal"/>). (ACE's AFrame.Subtract rotates
    /// the child's origin by the child's own rotation instead.)
    /// </summary>
    internal readonly Frame Subtract(in Frame child)
    {
        double w1 = Qw, x1 = _qx, y1 = _qy, z1 = _qz;
        double w2 = child.Qw, x2 = child._qx, y2 = child._qy, z2 = child._qz;
        float qz = (float)(z1 * w2 - (w1 * z2 + y2 * x1) + y1 * x2);
        float qy = (float)(y1 * w2 - w1 * y2 + z2 * x1 - x2 * z1);
        float qx = (float)(x1 * w2 - x2 * w1 - y1 * z2 + z1 * y2);
        float qw = (float)(y1 * y2 + x2 * x1 + w1 * w2 + z2 * z1);
        var result = new Frame(Origin, Orientation);
        result.SetRotate(qw, qx, qy, qz);
        result.Origin = result.Matrix.SubtractToGlobal(-child.Origin, Origin);
        return result;
    }

    /// <summary>
    /// Sets the orientation between two frames' orientations at <paramref name="t"/> (retail
    /// Frame::interpolate_rotation, acclient.c:357257): spherical, falling back to the linear blend when
    /// the two are within EPSILON or the spherical weights leave [0, 1]; normalized as set_rotate does.
    /// </summary>
    public void InterpolateRotation(in Frame from, in Frame to, float t) => SetRotation(InterpolatedRotation(from, to, t));

    /// <summary>The rotation <see cref="InterpolateRotation"/> sets (when it is valid): normalized, not yet checked.</summary>
    internal static Quaternion InterpolatedRotation(in Frame from, in Frame to, float t)
    {
        double fw = from.Qw, fx = from._qx, fy = from._qy, fz = from._qz;
        double tw = to.Qw, tx = to._qx, ty = to._qy, tz = to._qz;
        double cosom = fy * ty + fw * tw + fx * tx + fz * tz;
        if (cosom < 0.0)
        {
            cosom = -cosom;
            tw = -tw; tx = -tx; ty = -ty; tz = -tz;
        }
        double wFrom = 1.0 - t, wTo = t;
        if (1.0 - cosom > PhysicsConstants.Epsilon)
        {
            double omega = Geometry.PortableMath.Acos(cosom);
            double invSin = 1.0 / Geometry.PortableMath.Sin(omega);
            double a = invSin * Geometry.PortableMath.Sin(omega * (1.0 - t));
            double b = Geometry.PortableMath.Sin(t * omega) * invSin;
            if (a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0)
            {
                wFrom = a;
                wTo = b;
            }
        }
        return Normalized(
            (float)(wFrom * fw + tw * wTo),
            (float)(fx * wFrom + tx * wTo),
            (float)(fy * wFrom + ty * wTo),
            (float)(tz * wTo + fz * wFrom));
    }

    /// <summary>
    /// Retail Frame::set_rotate (acclient.c:357062): normalizes by multiplying by the reciprocal length
    /// (in double), and keeps the old orientation when the result is not a valid rotation (Frame::IsValid).
    /// </summary>
    internal void SetRotate(float qw, float qx, float qy, float qz) => SetRotation(Normalized(qw, qx, qy, qz));

    /// <summary>Set_rotate's normalization: times the reciprocal length, in double.</summary>
    private static Quaternion Normalized(float qw, float qx, float qy, float qz)
    {
        double inv = 1.0 / Math.Sqrt((double)qw * qw + (double)qx * qx + (double)qy * qy + (double)qz * qz);
        return new Quaternion((float)(qx * inv), (float)(qy * inv), (float)(inv * qz), (float)(qw * inv));
    }

    /// <summary>Set_rotate's last step: a normalized rotation is taken only when it is valid (Frame::IsValid).</summary>
    internal void SetRotation(Quaternion normalized)
    {
        if (IsValidRotation(normalized))
            Orientation = normalized;
    }

    /// <summary>
    /// Retail Frame::IsValid's rotation test (acclient.c:357024): finite, with a squared length within
    /// 5 × EPSILON of one. Such a rotation is used as given; retail does not normalize it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool IsValidRotation(Quaternion q)
    {
        float norm = (float)((double)q.Z * q.Z + (double)q.Y * q.Y + (double)q.X * q.X + (double)q.W * q.W);
        return !float.IsNaN(norm) && !(PhysicsConstants.Epsilon * 5.0 < Math.Abs(norm - 1.0));
    }

    /// <inheritdoc />
    public override readonly string ToString() => $"{Origin} {Orientation}";
}
