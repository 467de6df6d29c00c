using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// A frame's rotation as the 3×3 matrix retail caches on every frame (Frame::m_fl2gv, filled by
/// Frame::cache, acclient.c:356983): column j (elements 3j..3j+2) is the frame's local axis j in the
/// parent space. Local→global multiplies by the matrix, global→local by its transpose, as retail does
/// (never the conjugate quaternion, which rounds differently).
/// </summary>
/// <remarks>
/// <para>Precision: the retail client sets the x87 unit to 53-bit precision at start-up
/// (ClientMain::ConfigureFPU, acclient.c:60884: <c>_control87(_PC_53, _MCW_PC)</c>, and Direct3D is
/// created with FPU_PRESERVE), so these expressions are evaluated in double and rounded to float where
/// retail stores a float: the matrix elements, and each transformed component. The products of two
/// floats are exact in double; only the sums round. Fused multiply-add is never used.</para>
/// <para>Order: each transform adds its three products in the order of the retail function it stands
/// for (the Frame:: and the Position:: functions were compiled with different orders).</para>
/// <para>Computed on demand from the quaternion rather than stored in <see cref="Frame"/>, which keeps
/// the frame small for the many copies on the per-frame path; the values are the ones retail's cache
/// holds.</para>
/// </remarks>
internal readonly struct RotationMatrix
{
    private readonly float _m0, _m1, _m2, _m3, _m4, _m5, _m6, _m7, _m8;

    /// <summary>Retail Frame::cache (acclient.c:356983), operation for operation, in double.</summary>
    public RotationMatrix(float qw, float qx, float qy, float qz)
    {
        double w = qw, x = qx, y = qy, z = qz;
        double x2 = x + x, y2 = y + y, z2 = z + z;
        double wx2 = w * x2, wy2 = w * y2, wz2 = w * z2;
        double xx2 = x * x2, xy2 = x * y2, xz2 = x * z2;
        double yy2 = y * y2, yz2 = y * z2, zz2 = z * z2;
        _m0 = (float)(1.0 - yy2 - zz2);
        _m1 = (float)(xy2 + wz2);
        _m2 = (float)(xz2 - wy2);
        _m3 = (float)(xy2 - wz2);
        double oneMinusXx2 = 1.0 - xx2;
        _m4 = (float)(oneMinusXx2 - zz2);
        _m5 = (float)(yz2 + wx2);
        _m6 = (float)(xz2 + wy2);
        _m7 = (float)(yz2 - wx2);
        _m8 = (float)(oneMinusXx2 - yy2);
    }

    /// <summary>The nine elements, column by column (for <see cref="RotationMatrixLanes"/>).</summary>
    internal void Elements(out float m0, out float m1, out float m2, out float m3, out float m4, out float m5, out float m6, out float m7, out float m8)
    {
        m0 = _m0; m1 = _m1; m2 = _m2; m3 = _m3; m4 = _m4; m5 = _m5; m6 = _m6; m7 = _m7; m8 = _m8;
    }

    /// <summary>Frame::localtoglobalvec (acclient.c:143658): M·v, summed z, x, y.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 FrameToGlobal(Vector3 v) => new(
        (float)((double)_m6 * v.Z + (double)_m0 * v.X + (double)_m3 * v.Y),
        (float)((double)_m7 * v.Z + (double)_m1 * v.X + (double)_m4 * v.Y),
        (float)((double)_m8 * v.Z + (double)_m2 * v.X + (double)_m5 * v.Y));

    /// <summary>
    /// Frame::localtoglobal (acclient.c:143701) and the origin of Frame::combine (acclient.c:326562):
    /// M·v + origin, summed z, x, y, then the origin, rounded once.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 FrameToGlobal(Vector3 v, Vector3 origin) => new(
        (float)((double)_m6 * v.Z + (double)_m0 * v.X + (double)_m3 * v.Y + origin.X),
        (float)((double)_m7 * v.Z + (double)_m1 * v.X + (double)_m4 * v.Y + origin.Y),
        (float)((double)_m8 * v.Z + (double)_m2 * v.X + (double)_m5 * v.Y + origin.Z));

    /// <summary>
    /// The origin of Frame::subtract1 (acclient.c:357321): M·v + origin, summed z, x, y like
    /// <see cref="FrameToGlobal(Vector3, Vector3)"/>, but retail stores the rotated x and y to float before adding
    /// the origin's (two roundings each), while the rotated z is added unrounded (one rounding).
    /// </summary>
    public Vector3 SubtractToGlobal(Vector3 v, Vector3 origin)
    {
        float x = (float)((double)_m6 * v.Z + (double)_m0 * v.X + (double)_m3 * v.Y);
        float y = (float)((double)_m7 * v.Z + (double)_m1 * v.X + (double)_m4 * v.Y);
        double z = (double)_m8 * v.Z + (double)_m2 * v.X + (double)_m5 * v.Y;
        return new((float)((double)x + origin.X), (float)((double)y + origin.Y), (float)(z + origin.Z));
    }

    /// <summary>Frame::globaltolocalvec (acclient.c:143674): Mᵀ·v, summed z, x, y.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 FrameToLocal(Vector3 v) => new(
        (float)((double)_m2 * v.Z + (double)_m0 * v.X + (double)_m1 * v.Y),
        (float)((double)_m5 * v.Z + (double)_m3 * v.X + (double)_m4 * v.Y),
        (float)((double)_m8 * v.Z + (double)_m6 * v.X + (double)_m7 * v.Y));

    /// <summary>
    /// Frame::globaltolocal (acclient.c:143717): Mᵀ·(p − origin), summed z, x, y. Retail stores the
    /// differences as floats, except that the z row uses the unrounded z difference.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 FrameToLocal(Vector3 point, Vector3 origin)
    {
        float dx = point.X - origin.X, dy = point.Y - origin.Y;
        double dzExact = (double)point.Z - origin.Z;
        float dz = (float)dzExact;
        return new Vector3(
            (float)((double)dz * _m2 + (double)dx * _m0 + (double)dy * _m1),
            (float)((double)dz * _m5 + (double)dx * _m3 + (double)dy * _m4),
            (float)(dzExact * _m8 + (double)dx * _m6 + (double)dy * _m7));
    }

    /// <summary>Position::localtoglobalvec (acclient.c:147164): M·v, summed y, x, z.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 PositionToGlobal(Vector3 v) => new(
        (float)((double)_m3 * v.Y + (double)_m0 * v.X + (double)_m6 * v.Z),
        (float)((double)_m4 * v.Y + (double)_m1 * v.X + (double)_m7 * v.Z),
        (float)((double)_m5 * v.Y + (double)_m2 * v.X + (double)_m8 * v.Z));

    /// <summary>Position::localtoglobal / localtolocal (acclient.c:147140, :143794): M·v + origin, summed y, x, z, then the origin.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 PositionToGlobal(Vector3 v, Vector3 origin) => new(
        (float)((double)_m3 * v.Y + (double)_m0 * v.X + (double)_m6 * v.Z + origin.X),
        (float)((double)_m4 * v.Y + (double)_m1 * v.X + (double)_m7 * v.Z + origin.Y),
        (float)((double)_m5 * v.Y + (double)_m2 * v.X + (double)_m8 * v.Z + origin.Z));

    /// <summary>Position::globaltolocalvec (acclient.c:313494): Mᵀ·v, summed y, x, z.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 PositionToLocal(Vector3 v) => new(
        (float)((double)_m1 * v.Y + (double)_m0 * v.X + (double)_m2 * v.Z),
        (float)((double)_m4 * v.Y + (double)_m3 * v.X + (double)_m5 * v.Z),
        (float)((double)_m7 * v.Y + (double)_m6 * v.X + (double)_m8 * v.Z));

    /// <summary>Plane::localtoglobal's normal (acclient.c:467672): M·v, summed z, y, x.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 PlaneNormalToGlobal(Vector3 v) => new(
        (float)((double)_m6 * v.Z + (double)_m3 * v.Y + (double)_m0 * v.X),
        (float)((double)_m7 * v.Z + (double)_m4 * v.Y + (double)_m1 * v.X),
        (float)((double)_m8 * v.Z + (double)_m5 * v.Y + (double)_m2 * v.X));
}
