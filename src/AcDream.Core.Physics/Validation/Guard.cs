using System;
using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;
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

    /// <summary>Whether <see cref="Finite(Vector3, string, string?)"/> accepts the value: callers that name the field
    /// with a built string test this first and build the name only for the message.</summary>
    public static bool IsCoordinate(Vector3 value) =>
        MathF.Abs(value.X) <= InputLimits.MaxCoordinate && MathF.Abs(value.Y) <= InputLimits.MaxCoordinate
        && MathF.Abs(value.Z) <= InputLimits.MaxCoordinate;

    /// <summary>A point or vector: every component finite and within ±<see cref="InputLimits.MaxCoordinate"/>.</summary>
    public static void Finite(Vector3 value, string field, string? suffix = null)
    {
        if (!(MathF.Abs(value.X) <= InputLimits.MaxCoordinate) || !(MathF.Abs(value.Y) <= InputLimits.MaxCoordinate)
            || !(MathF.Abs(value.Z) <= InputLimits.MaxCoordinate))
            ThrowNotCoordinate(value, field, suffix);
    }

    // The message is built out of line so that the checks inline into the per-frame callers.
    [DoesNotReturn, MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowNotCoordinate<T>(T value, string field, string? suffix) =>
        throw new ArgumentException($"{Name(field, suffix)}: must be finite and within ±{InputLimits.MaxCoordinate} m, got {value}.", Name(field, suffix));

    /// <summary>Whether <see cref="Coordinate"/> accepts the value (for callers that build the field's name only for the message).</summary>
    public static bool IsCoordinate(float value) => MathF.Abs(value) <= InputLimits.MaxCoordinate;

    /// <summary>A coordinate: finite and within ±<see cref="InputLimits.MaxCoordinate"/>.</summary>
    public static void Coordinate(float value, string field, string? suffix = null)
    {
        if (!(MathF.Abs(value) <= InputLimits.MaxCoordinate))
            ThrowNotCoordinate(value, field, suffix);
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
        // A squared length within 2e-3 of one implies every component is finite and at most ~1 in size,
        // so the common case is one test; otherwise the finiteness check runs first, for its message.
        if (!(MathF.Abs(VectorMath.Dot(value, value) - 1f) <= 2e-3f))
            NotUnit(value, field, suffix);
    }

    [DoesNotReturn, MethodImpl(MethodImplOptions.NoInlining)]
    private static void NotUnit(Vector3 value, string field, string? suffix)
    {
        Finite(value, field, suffix);
        ThrowNotUnit(value, field, suffix);
    }

    [DoesNotReturn, MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowNotUnit(Vector3 value, string field, string? suffix) =>
        throw new ArgumentException($"{Name(field, suffix)}: must be a unit vector, got {value} (length {value.Length()}).", Name(field, suffix));

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
        // The common case (a rotation retail accepts as it is) inlines; the rest is out of line. A rotation
        // IsValidRotation accepts is finite: an infinite component makes the squared length infinite, a
        // NaN makes it NaN, and both are refused.
        if (SurelyValidRotation(q) || Physics.Frame.IsValidRotation(q))
            return q;
        return CheckedRotation(q, field, suffix);
    }

    /// <summary>
    /// A quick, sufficient test for <see cref="Physics.Frame.IsValidRotation"/>: that accepts a squared
    /// length within 5 × EPSILON (0.001) of one, summed in double and rounded to float; a float sum of the
    /// four squares, in any order, is within 3e-7 of that value, so one within 0.0009 of one is accepted
    /// there too. Anything else (NaN included) takes the exact test.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool SurelyValidRotation(Quaternion q) => MathF.Abs((q.X * q.X + q.Y * q.Y) + (q.Z * q.Z + q.W * q.W) - 1f) <= 0.0009f;

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static Quaternion CheckedRotation(Quaternion q, string field, string? suffix)
    {
        if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W))
            throw new ArgumentException($"{Name(field, suffix)}: quaternion must be finite, got {q}.", Name(field, suffix));
        if (Physics.Frame.IsValidRotation(q))
            return q;
        // Retail's set_rotate normalizes any length by its reciprocal in double (x87), where the squares of
        // tiny float components do not underflow: a finite rotation of length 1.4e-19 is a valid rotation
        // there, normalized the same way here (Frame.SetRotate). Only a length of exactly zero has no
        // direction (retail's reciprocal is then infinite and set_rotate keeps the old rotation).
        if ((double)q.X * q.X + (double)q.Y * q.Y + (double)q.Z * q.Z + (double)q.W * q.W == 0.0)
            throw new ArgumentException($"{Name(field, suffix)}: quaternion has zero length.", Name(field, suffix));
        // A length that overflows float (components near 1e19 or more) is refused rather than normalized:
        // a client that sends such a rotation has a bug, and the error says so.
        if (!float.IsFinite(q.Length()))
            throw new ArgumentException($"{Name(field, suffix)}: quaternion is too long to normalize (its length overflows), got {q}.", Name(field, suffix));
        var frame = new Frame(Vector3.Zero, new Quaternion(float.NaN, float.NaN, float.NaN, float.NaN));
        frame.SetRotate(q.W, q.X, q.Y, q.Z);
        if (!Physics.Frame.IsValidRotation(frame.Orientation))
            throw new ArgumentException($"{Name(field, suffix)}: quaternion {q} does not normalize to a valid rotation.", Name(field, suffix));
        return frame.Orientation;
    }

    /// <summary>
    /// A cell id in retail's world naming a cell (<see cref="LandDefs.IsValidCellOfWorld"/>: retail's inbound_valid_cellid
    /// without the landblock's own id 0xFFFF): the landblock's x and y bytes are both at most 0xFE (the world is
    /// 255 × 255 landblocks), the cell part 1..0x40 (outdoor) or 0x100..0xFFFD (indoor).
    /// </summary>
    public static void CellInWorld(uint cellId, string field)
    {
        if (!LandDefs.IsValidCellOfWorld(cellId))
            throw new ArgumentException($"{field}: cell 0x{cellId:X8} is outside the retail world (landblock x and y must be 0x00..0xFE, the cell part 0x0001..0x0040 or 0x0100..0xFFFD).", field);
    }

    /// <summary>A landblock id (high 16 bits of a cell id) in retail's world: x and y bytes both at most 0xFE.</summary>
    public static void LandblockInWorld(uint landblock, string field)
    {
        if (landblock > 0xFFFF || !LandDefs.IsValidLandblock(landblock))
            throw new ArgumentException($"{field}: landblock 0x{landblock:X4} is outside the retail world (x and y bytes must be 0x00..0xFE).", field);
    }

    /// <summary>
    /// A position's origin lies near the cell it names: at most <see cref="InputLimits.MaxDistanceFromCell"/>
    /// plus <paramref name="reach"/> outside it (<paramref name="distance"/> is measured by the cell). The one
    /// rule for movers (reach: their spheres') and registered objects (reach: their shapes').
    /// </summary>
    public static void NearCell(float distance, float reach, uint cellId, Vector3 origin, string field)
    {
        if (!(distance <= InputLimits.MaxDistanceFromCell + reach))
            ThrowFarFromCell(distance, reach, cellId, origin, field);
    }

    [DoesNotReturn, MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowFarFromCell(float distance, float reach, uint cellId, Vector3 origin, string field)
    {
        throw new ArgumentException($"{field}: {origin} is {distance:0.#} m outside its cell 0x{cellId:X8}; a position must lie within {InputLimits.MaxDistanceFromCell} m plus the reach of its shapes ({reach:0.###} m) of the cell it names.", field);
    }

    /// <summary>
    /// A polygon's vertices against its plane (computed by the caller): at most
    /// <see cref="InputLimits.MaxPolygonVertices"/>; no vertex off the plane or on the outer side of an edge
    /// by more than the tolerance (<see cref="InputLimits.PolygonTolerance"/>), and no two consecutive
    /// vertices closer than it (a duplicate). Errors name the vertex.
    /// </summary>
    public static void ConvexPolygon(ReadOnlySpan<Vector3> v, in Plane plane, string name)
    {
        float largest = 0f;
        foreach (var p in v)
            largest = MathF.Max(largest, VectorMath.MaxAbs(p));
        float tolerance = InputLimits.PolygonTolerance + InputLimits.PolygonRelativeTolerance * largest;
        int worst = 0;
        float worstOff = 0f;
        for (int i = 0; i < v.Length; i++)
        {
            float off = MathF.Abs(Vector3.Dot(plane.Normal, v[i]) + plane.D);
            if (!(off <= worstOff))
            {
                worst = i;
                worstOff = off;
            }
        }
        if (!(worstOff <= tolerance))
            throw new ArgumentException($"{name}.vertices[{worst}]: lies {worstOff:G3} m off the polygon's plane (non-planar polygon; tolerance {tolerance:G3} m).", name);
        for (int i = 1; i < v.Length; i++)
            for (int k = 0; k < i; k++)
            {
                float apart = Vector3.Distance(v[i], v[k]);
                if (!(apart > tolerance))
                    throw new ArgumentException($"{name}.vertices[{i}]: repeats vertex {k} (duplicate vertex, {apart:G3} m apart; tolerance {tolerance:G3} m).", name);
            }
        for (int i = 0; i < v.Length; i++)
        {
            var a = v[i == 0 ? v.Length - 1 : i - 1];
            var edge = v[i] - a;
            float length = edge.Length();
            var inward = Vector3.Cross(plane.Normal, edge) / length;
            var next = v[i == v.Length - 1 ? 0 : i + 1];
            float turn = Vector3.Dot(next - a, inward);
            if (!(turn >= -tolerance))
                throw new ArgumentException($"{name}.vertices[{i}]: is a concave corner (the next vertex lies {-turn:G3} m outside the edge into it; vertices must be convex and counter-clockwise seen from the front; tolerance {tolerance:G3} m).", name);
            for (int k = 0; k < v.Length; k++)
            {
                float side = Vector3.Dot(v[k] - a, inward);
                if (!(side >= -tolerance))
                    throw new ArgumentException($"{name}.vertices[{k}]: lies {-side:G3} m outside the edge ending at vertex {i} (concave or self-intersecting polygon; vertices must be convex and counter-clockwise seen from the front; tolerance {tolerance:G3} m).", name);
            }
        }
    }

    /// <summary>True when <see cref="Frame(in Physics.Frame, string)"/> and <see cref="Rotation"/> would accept the frame (no allocation).</summary>
    public static bool IsValidFrame(in Frame frame)
    {
        var o = frame.Origin;
        var q = frame.Orientation;
        if (!(MathF.Abs(o.X) <= InputLimits.MaxCoordinate) || !(MathF.Abs(o.Y) <= InputLimits.MaxCoordinate)
            || !(MathF.Abs(o.Z) <= InputLimits.MaxCoordinate))
            return false;
        float length = q.Length();
        return length >= 1e-6f && float.IsFinite(length);
    }

    /// <summary>
    /// Checks a placement and normalizes its rotation in place: the origin as <see cref="Finite(Vector3, string, string?)"/>
    /// (field + ".origin"), then the rotation as <see cref="Rotation"/> (field + ".orientation"). One
    /// normalization per rotation: the per-frame entry points call this instead of <see cref="Frame"/> and
    /// <see cref="Rotation"/> in turn.
    /// </summary>
    public static void Pose(ref Frame frame, string field)
    {
        if (!PoseAsGiven(frame, field))
            frame.Orientation = CheckedRotation(frame.Orientation, field, ".orientation");
    }

    /// <summary>
    /// <see cref="Pose"/> without writing: checks the origin and returns whether the rotation is used as
    /// given; false when it must be normalized (or refused) by <see cref="Pose"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool PoseAsGiven(in Frame frame, string field)
    {
        Finite(frame.Origin, field, ".origin");
        var q = frame.Orientation;
        return SurelyValidRotation(q) || Physics.Frame.IsValidRotation(q);
    }

    /// <summary>
    /// Whether <see cref="Pose"/> would neither write nor throw: the origin a coordinate and the rotation used as
    /// given (for callers that build the field's name only when it would be used).
    /// </summary>
    public static bool IsPoseAsGiven(in Frame frame)
    {
        var q = frame.Orientation;
        return IsCoordinate(frame.Origin) && (SurelyValidRotation(q) || Physics.Frame.IsValidRotation(q));
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
