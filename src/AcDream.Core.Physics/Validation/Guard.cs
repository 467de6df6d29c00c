using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>Input checks at the library's boundary. Each throws an <see cref="ArgumentException"/> naming the field.</summary>
internal static class Guard
{
    public static void Finite(float value, string field)
    {
        if (!float.IsFinite(value))
            throw new ArgumentException($"{field}: must be a finite number, got {value}.", field);
    }

    public static void Finite(Vector3 value, string field)
    {
        if (!float.IsFinite(value.X) || !float.IsFinite(value.Y) || !float.IsFinite(value.Z))
            throw new ArgumentException($"{field}: must be finite, got {value}.", field);
    }

    public static void Positive(float value, string field)
    {
        if (!(value > 0f) || !float.IsFinite(value))
            throw new ArgumentException($"{field}: must be a finite number greater than zero, got {value}.", field);
    }

    public static void NonNegative(float value, string field)
    {
        if (!(value >= 0f) || !float.IsFinite(value))
            throw new ArgumentException($"{field}: must be a finite number of zero or more, got {value}.", field);
    }

    /// <summary>Checks a rotation and returns it normalized; a zero-length or non-finite quaternion is refused.</summary>
    public static Quaternion Rotation(Quaternion q, string field)
    {
        if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W))
            throw new ArgumentException($"{field}: quaternion must be finite, got {q}.", field);
        float length = q.Length();
        if (length < 1e-6f)
            throw new ArgumentException($"{field}: quaternion has zero length.", field);
        return Quaternion.Multiply(q, 1f / length);
    }

    public static void Frame(in Frame frame, string field)
    {
        Finite(frame.Origin, field + ".origin");
        Rotation(frame.Orientation, field + ".orientation");
    }

    public static void Sphere(in Sphere sphere, string field)
    {
        Finite(sphere.Center, field + ".center");
        Positive(sphere.Radius, field + ".radius");
    }

    public static void CylSphere(in CylSphere cyl, string field)
    {
        Finite(cyl.LowPoint, field + ".lowPoint");
        Positive(cyl.Radius, field + ".radius");
        NonNegative(cyl.Height, field + ".height");
    }
}
