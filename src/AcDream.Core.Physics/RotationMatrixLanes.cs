using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace AcDream.Core.Physics;

/// <summary>
/// A <see cref="RotationMatrix"/> widened to double once, each element repeated in four lanes, so that the
/// two transforms the sphere path repeats most run on up to four points at once (<see cref="PointLanes"/>:
/// a mover's sphere centres and low point, or the check spheres and the current sphere). Each lane performs
/// the same IEEE double operations in the same order as the scalar form (products of floats, exact in
/// double; the sums in the retail function's order; one rounding to float), so the results are the same
/// bits; no fused multiply-add is used. Without AVX (four double lanes, and the narrowing of four doubles
/// to floats in one instruction) each lane runs the scalar form.
/// </summary>
internal readonly struct RotationMatrixLanes
{
    private readonly RotationMatrix _scalar;
    private readonly Vector256<double> _m0, _m1, _m2, _m3, _m4, _m5, _m6, _m7, _m8;

    public RotationMatrixLanes(in RotationMatrix m)
    {
        _scalar = m;
        m.Elements(out float m0, out float m1, out float m2, out float m3, out float m4, out float m5, out float m6, out float m7, out float m8);
        _m0 = Vector256.Create((double)m0);
        _m1 = Vector256.Create((double)m1);
        _m2 = Vector256.Create((double)m2);
        _m3 = Vector256.Create((double)m3);
        _m4 = Vector256.Create((double)m4);
        _m5 = Vector256.Create((double)m5);
        _m6 = Vector256.Create((double)m6);
        _m7 = Vector256.Create((double)m7);
        _m8 = Vector256.Create((double)m8);
    }

    /// <summary><see cref="RotationMatrix.PositionToGlobal(System.Numerics.Vector3, System.Numerics.Vector3)"/> of every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public PointLanes PositionToGlobal(in PointLanes v, System.Numerics.Vector3 origin)
    {
        if (!Avx.IsSupported)
            return PositionToGlobalByLane(v, origin);
        var x = Avx.ConvertToVector256Double(v.X);
        var y = Avx.ConvertToVector256Double(v.Y);
        var z = Avx.ConvertToVector256Double(v.Z);
        // Position::localtoglobal's order per component: y, x, z, then the origin.
        var gx = _m3 * y + _m0 * x;
        var gy = _m4 * y + _m1 * x;
        var gz = _m5 * y + _m2 * x;
        gx += _m6 * z;
        gy += _m7 * z;
        gz += _m8 * z;
        gx += Vector256.Create((double)origin.X);
        gy += Vector256.Create((double)origin.Y);
        gz += Vector256.Create((double)origin.Z);
        return new(Avx.ConvertToVector128Single(gx), Avx.ConvertToVector128Single(gy), Avx.ConvertToVector128Single(gz));
    }

    /// <summary><see cref="PositionToGlobal"/> one lane at a time through the scalar form (without AVX; tests call it directly).</summary>
    internal PointLanes PositionToGlobalByLane(in PointLanes v, System.Numerics.Vector3 origin) => PointLanes.Of(
        _scalar.PositionToGlobal(v[0], origin), _scalar.PositionToGlobal(v[1], origin),
        _scalar.PositionToGlobal(v[2], origin), _scalar.PositionToGlobal(v[3], origin));

    /// <summary><see cref="RotationMatrix.FrameToLocal(System.Numerics.Vector3, System.Numerics.Vector3)"/> of every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public PointLanes FrameToLocal(in PointLanes p, System.Numerics.Vector3 origin)
    {
        if (!Avx.IsSupported)
            return FrameToLocalByLane(p, origin);
        // The x and y differences are floats; the z row uses the unrounded z difference, the others its float.
        // That float is taken by a float subtraction rather than by rounding the double difference: the same
        // number, since a double has more than 2·24 + 1 bits, so rounding a difference of floats first to
        // double and then to float gives the correctly rounded float difference (double rounding is
        // innocuous, Figueroa 1995), which is what float subtraction returns. It starts the x and y rows'
        // chain two conversions sooner.
        var dx = Avx.ConvertToVector256Double(p.X - Vector128.Create(origin.X));
        var dy = Avx.ConvertToVector256Double(p.Y - Vector128.Create(origin.Y));
        var dz = Avx.ConvertToVector256Double(p.Z - Vector128.Create(origin.Z));
        var dzExact = Avx.ConvertToVector256Double(p.Z) - Vector256.Create((double)origin.Z);
        // Frame::globaltolocal's order per component: z, x, y.
        var lx = _m2 * dz + _m0 * dx;
        var ly = _m5 * dz + _m3 * dx;
        var lz = _m8 * dzExact + _m6 * dx;
        lx += _m1 * dy;
        ly += _m4 * dy;
        lz += _m7 * dy;
        return new(Avx.ConvertToVector128Single(lx), Avx.ConvertToVector128Single(ly), Avx.ConvertToVector128Single(lz));
    }

    /// <summary><see cref="FrameToLocal"/> one lane at a time through the scalar form (without AVX; tests call it directly).</summary>
    internal PointLanes FrameToLocalByLane(in PointLanes p, System.Numerics.Vector3 origin) => PointLanes.Of(
        _scalar.FrameToLocal(p[0], origin), _scalar.FrameToLocal(p[1], origin),
        _scalar.FrameToLocal(p[2], origin), _scalar.FrameToLocal(p[3], origin));
}
