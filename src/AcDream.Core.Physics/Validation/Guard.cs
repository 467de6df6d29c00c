using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Validation;

/// <summary>
/// Input checks at the library's boundary. Each throws an <see cref="ArgumentException"/> naming the
/// field. A field name is given as a prefix and an optional suffix so that nothing is concatenated (and
/// nothing allocated) unless the check fails: these run on every engine call.
/// </summary>
internal static class Guard
{
    private static string Name(string field, string? suffix) => suffix is null ? field : field + suffix;

    public static void Finite(float value, string field, string? suffix = null)
    {
        if (!float.IsFinite(value))
            throw new ArgumentException($"{Name(field, suffix)}: must be a finite number, got {value}.", Name(field, suffix));
    }

    /// <summary>A point or vector: every component finite and within ±<see cref="InputLimits.MaxCoordinate"/>.</summary>
    public static void Finite(Vector3 value, string field, string? suffix = null)
    {
        if (!(MathF.Abs(value.X) <= InputLimits.MaxCoordinate) || !(MathF.Abs(value.Y) <= InputLimits.MaxCoordinate)
            || !(MathF.Abs(value.Z) <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"{Name(field, suffix)}: must be finite and within ±{InputLimits.MaxCoordinate} m, got {value}.", Name(field, suffix));
    }

    /// <summary>A coordinate: finite and within ±<see cref="InputLimits.MaxCoordinate"/>.</summary>
    public static void Coordinate(float value, string field, string? suffix = null)
    {
        if (!(MathF.Abs(value) <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"{Name(field, suffix)}: must be finite and within ±{InputLimits.MaxCoordinate} m, got {value}.", Name(field, suffix));
    }

    /// <summary>As <see cref="Coordinate"/>, returning true, for use in initializers.</summary>
    public static bool CoordinateOk(float value, string field)
    {
        Coordinate(value, field);
        return true;
    }

    /// <summary>A size: finite, greater than zero (or zero when <paramref name="allowZero"/>), at most <see cref="InputLimits.MaxExtent"/>.</summary>
    public static void Extent(float value, bool allowZero, string field, string? suffix = null)
    {
        if (!(allowZero ? value >= 0f : value > 0f) || !(value <= InputLimits.MaxExtent))
            throw new ArgumentException($"{Name(field, suffix)}: must be a finite number {(allowZero ? "of zero or more" : "greater than zero")} and at most {InputLimits.MaxExtent} m, got {value}.", Name(field, suffix));
    }

    /// <summary>A plane normal: finite and of unit length (within 1e-3).</summary>
    public static void UnitNormal(Vector3 value, string field, string? suffix = null)
    {
        Finite(value, field, suffix);
        if (!(MathF.Abs(value.LengthSquared() - 1f) <= 2e-3f))
            throw new ArgumentException($"{Name(field, suffix)}: must be a unit vector, got {value} (length {value.Length()}).", Name(field, suffix));
    }

    public static void Positive(float value, string field, string? suffix = null)
    {
        if (!(value > 0f) || !float.IsFinite(value))
            throw new ArgumentException($"{Name(field, suffix)}: must be a finite number greater than zero, got {value}.", Name(field, suffix));
    }

    public static void NonNegative(float value, string field, string? suffix = null)
    {
        if (!(value >= 0f) || !float.IsFinite(value))
            throw new ArgumentException($"{Name(field, suffix)}: must be a finite number of zero or more, got {value}.", Name(field, suffix));
    }

    /// <summary>
    /// Checks a rotation. A rotation retail's Frame::IsValid accepts (squared length within 0.001 of one)
    /// is returned unchanged, as retail uses it; any other finite, non-zero one is normalized the way
    /// Frame::set_rotate normalizes (times the reciprocal length). Zero-length or non-finite is refused.
    /// </summary>
    public static Quaternion Rotation(Quaternion q, string field, string? suffix = null)
    {
        if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W))
            throw new ArgumentException($"{Name(field, suffix)}: quaternion must be finite, got {q}.", Name(field, suffix));
        if (Physics.Frame.IsValidRotation(q))
            return q;
        float length = q.Length();
        if (length < 1e-6f)
            throw new ArgumentException($"{Name(field, suffix)}: quaternion has zero length.", Name(field, suffix));
        var frame = default(Frame);
        frame.SetRotate(q.W, q.X, q.Y, q.Z);
        return frame.Orientation;
    }

    public static void Frame(in Frame frame, string field)
    {
        Finite(frame.Origin, field, ".origin");
        Rotation(frame.Orientation, field, ".orientation");
    }

    public static void Sphere(in Sphere sphere, string field)
    {
        Finite(sphere.Center, field, ".center");
        Extent(sphere.Radius, false, field, ".radius");
    }

    public static void CylSphere(in CylSphere cyl, string field)
    {
        Finite(cyl.LowPoint, field, ".lowPoint");
        Extent(cyl.Radius, false, field, ".radius");
        Extent(cyl.Height, true, field, ".height");
    }
}
