using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics;

/// <summary>
/// A <see cref="RotationMatrix"/> widened to double once and laid out by columns and by rows, so that the
/// two transforms the sphere path repeats most compute the three components side by side. Each lane
/// performs the same IEEE double operations in the same order as the scalar form, so the results are the
/// same bits; no fused multiply-add is used. Where 256-bit vectors are not accelerated the scalar form runs.
/// </summary>
internal readonly struct RotationMatrixLanes
{
    private readonly RotationMatrix _scalar;
    private readonly Vector256<double> _c0, _c1, _c2, _r0, _r1, _r2;

    public RotationMatrixLanes(in RotationMatrix m)
    {
        _scalar = m;
        m.Elements(out float m0, out float m1, out float m2, out float m3, out float m4, out float m5, out float m6, out float m7, out float m8);
        _c0 = Vector256.Create(m0, m1, m2, 0.0);
        _c1 = Vector256.Create(m3, m4, m5, 0.0);
        _c2 = Vector256.Create(m6, m7, m8, 0.0);
        _r0 = Vector256.Create(m0, m3, m6, 0.0);
        _r1 = Vector256.Create(m1, m4, m7, 0.0);
        _r2 = Vector256.Create(m2, m5, m8, 0.0);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 PositionToGlobal(Vector3 v, Vector3 origin)
    {
        if (!Vector256.IsHardwareAccelerated)
            return _scalar.PositionToGlobal(v, origin);
        var sum = _c1 * Vector256.Create((double)v.Y) + _c0 * Vector256.Create((double)v.X);
        sum += _c2 * Vector256.Create((double)v.Z);
        sum += Vector256.Create(origin.X, origin.Y, origin.Z, 0.0);
        return Vector256.Narrow(sum, sum).GetLower().AsVector3();
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 FrameToLocal(Vector3 point, Vector3 origin)
    {
        if (!Vector256.IsHardwareAccelerated)
            return _scalar.FrameToLocal(point, origin);
        float dx = point.X - origin.X, dy = point.Y - origin.Y;
        double dzExact = (double)point.Z - origin.Z;
        double dz = (float)dzExact;
        var sum = _r2 * Vector256.Create(dz, dz, dzExact, 0.0) + _r0 * Vector256.Create((double)dx);
        sum += _r1 * Vector256.Create((double)dy);
        return Vector256.Narrow(sum, sum).GetLower().AsVector3();
    }
}
