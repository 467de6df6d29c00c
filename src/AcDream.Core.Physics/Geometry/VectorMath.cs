using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Geometry;

/// <summary>Small vector helpers with retail's tolerances.</summary>
internal static class VectorMath
{
    /// <summary>
    /// Retail normalize_check_small: normalizes in place unless the vector is too short to have a
    /// direction; returns true when it was too short (and leaves it unchanged).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool NormalizeCheckSmall(ref Vector3 v)
    {
        // Retail (AC1Legacy::Vector3::normalize_check_small, acclient.c:143621) takes the length and its
        // reciprocal on the x87 stack at double precision and rounds each scaled component once.
        double length = Math.Sqrt(LengthSquaredWide(v));
        if (length < PhysicsConstants.Epsilon)
            return true;
        v = Scale(v, 1.0 / length);
        return false;
    }

    /// <summary>x·x + y·y + z·z in double, summed in that order: a length as retail takes it on the x87 stack.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double LengthSquaredWide(Vector3 v) => (double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z;

    /// <summary>Each component times a double factor, rounded to float once (retail's scaling on the x87 stack).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3 Scale(Vector3 v, double factor) => new((float)(factor * v.X), (float)(factor * v.Y), (float)(factor * v.Z));

    /// <summary>
    /// <see cref="Vector3.Dot"/> as scalar arithmetic: (x·x' + y·y') + z·z', the very sum the vector dot
    /// product rounds to (its lanes add pairwise, the fourth being zero), without the vector instruction's
    /// long latency on the chains of tests the BSP walks make.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Dot(Vector3 a, Vector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    /// <summary>True when two vectors are the same bits (so -0 differs from 0, and a NaN equals its own bits).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool SameBits(Vector3 a, Vector3 b) =>
        BitConverter.SingleToUInt32Bits(a.X) == BitConverter.SingleToUInt32Bits(b.X)
        && BitConverter.SingleToUInt32Bits(a.Y) == BitConverter.SingleToUInt32Bits(b.Y)
        && BitConverter.SingleToUInt32Bits(a.Z) == BitConverter.SingleToUInt32Bits(b.Z);

    /// <summary>
    /// The D of the plane with normal <paramref name="normal"/> through <paramref name="point"/>, −(N·P), as
    /// retail computes it (Plane::Plane, acclient.c:358518; Plane::localtoglobal, :467672): summed z, y, x
    /// in double on the x87 stack, rounded to float once.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float PlaneDThrough(Vector3 normal, Vector3 point) =>
        (float)-((double)normal.Z * point.Z + (double)normal.Y * point.Y + (double)normal.X * point.X);

    /// <summary>Signed distance of a point from a plane (normal assumed unit).</summary>
    public static float Distance(in Plane plane, Vector3 point) => Dot(plane.Normal, point) + plane.D;

    /// <summary>The largest magnitude of a vector's components (a bound for its rounding).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float MaxAbs(Vector3 v) => MathF.Max(MathF.Max(MathF.Abs(v.X), MathF.Abs(v.Y)), MathF.Abs(v.Z));

    /// <summary>Whether the boxes from <paramref name="minA"/> to <paramref name="maxA"/> and from <paramref name="minB"/> to <paramref name="maxB"/> meet (touching counts).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool BoxesMeet(Vector3 minA, Vector3 maxA, Vector3 minB, Vector3 maxB) =>
        minA.X <= maxB.X && maxA.X >= minB.X
        && minA.Y <= maxB.Y && maxA.Y >= minB.Y
        && minA.Z <= maxB.Z && maxA.Z >= minB.Z;

    /// <summary>
    /// Retail snap_to_plane: moves a vector within the plane by changing only its Z, so that its
    /// horizontal part is kept (used to make motion follow a slope). Retail computes the Z as
    /// -(n·xy + d)/nz + d/nz rather than -(n·xy)/nz; the same value in exact arithmetic, kept in retail's
    /// form so the float rounding matches.
    /// </summary>
    public static Vector3 SnapToPlane(in Plane plane, Vector3 offset)
    {
        if (System.MathF.Abs(plane.Normal.Z) <= PhysicsConstants.Epsilon)
            return offset;
        float inv = 1.0f / plane.Normal.Z;
        float dot2 = offset.X * plane.Normal.X + offset.Y * plane.Normal.Y;
        offset.Z = -(dot2 + plane.D) * inv - inv * -plane.D;
        return offset;
    }
}
