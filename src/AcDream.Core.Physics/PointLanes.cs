using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace AcDream.Core.Physics;

/// <summary>
/// Up to four points side by side: lane i of <see cref="X"/>, <see cref="Y"/> and <see cref="Z"/> is point i.
/// The sphere path keeps a mover's two sphere centres and its low point this way, so that one pass of
/// <see cref="RotationMatrixLanes"/> transforms them all (each lane doing the scalar form's operations).
/// </summary>
internal struct PointLanes
{
    /// <summary>The points' X coordinates, one lane each.</summary>
    public Vector128<float> X;
    /// <summary>The points' Y coordinates.</summary>
    public Vector128<float> Y;
    /// <summary>The points' Z coordinates.</summary>
    public Vector128<float> Z;

    public PointLanes(Vector128<float> x, Vector128<float> y, Vector128<float> z)
    {
        X = x;
        Y = y;
        Z = z;
    }

    /// <summary>Four points in lanes 0 to 3.</summary>
    public static PointLanes Of(Vector3 p0, Vector3 p1, Vector3 p2, Vector3 p3) => new(
        Vector128.Create(p0.X, p1.X, p2.X, p3.X),
        Vector128.Create(p0.Y, p1.Y, p2.Y, p3.Y),
        Vector128.Create(p0.Z, p1.Z, p2.Z, p3.Z));

    /// <summary><paramref name="first"/> in lanes 0 and 1, <paramref name="second"/> in lanes 2 and 3.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static PointLanes Pairs(Vector3 first, Vector3 second)
    {
        if (Sse.IsSupported)
        {
            // shufps: lanes 0, 1 from the first operand's element k, lanes 2, 3 from the second one's.
            Vector128<float> a = first.AsVector128Unsafe(), b = second.AsVector128Unsafe();
            return new(Sse.Shuffle(a, b, 0b00_00_00_00), Sse.Shuffle(a, b, 0b01_01_01_01), Sse.Shuffle(a, b, 0b10_10_10_10));
        }
        return PairsByLane(first, second);
    }

    /// <summary><see cref="Pairs"/> one element at a time (where SSE is missing; tests call it directly).</summary>
    internal static PointLanes PairsByLane(Vector3 first, Vector3 second) => Of(first, first, second, second);

    /// <summary>Point <paramref name="lane"/>.</summary>
    public readonly Vector3 this[int lane] => new(X.GetElement(lane), Y.GetElement(lane), Z.GetElement(lane));

    /// <summary>
    /// Lanes 0 and 1 of these points and lane 0 of <paramref name="other"/> in lane 2 (lane 3 is lane 0 of
    /// <paramref name="other"/> too, or whatever the fallback leaves: unused).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly PointLanes WithLane2From(in PointLanes other)
    {
        if (Sse.IsSupported)
        {
            // shufps: lanes 0, 1 from the first operand, lanes 2, 3 from the second one's lane 0.
            const byte pick = 0b00_00_01_00;
            return new(Sse.Shuffle(X, other.X, pick), Sse.Shuffle(Y, other.Y, pick), Sse.Shuffle(Z, other.Z, pick));
        }
        return WithLane2FromByLane(other);
    }

    /// <summary><see cref="WithLane2From"/> one element at a time (where SSE is missing; tests call it directly).</summary>
    internal readonly PointLanes WithLane2FromByLane(in PointLanes other) => new(
        X.WithElement(2, other.X.GetElement(0)).WithElement(3, other.X.GetElement(0)),
        Y.WithElement(2, other.Y.GetElement(0)).WithElement(3, other.Y.GetElement(0)),
        Z.WithElement(2, other.Z.GetElement(0)).WithElement(3, other.Z.GetElement(0)));

    /// <summary>
    /// Points 0, 1 and 2 as rows (x, y, z, w) with w from the same lane of <paramref name="w"/>: the layout of
    /// a <see cref="Sphere"/> (centre, radius), stored with one write each.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Rows(Vector128<float> w, out Vector128<float> row0, out Vector128<float> row1, out Vector128<float> row2)
    {
        if (Sse.IsSupported)
        {
            var xy01 = Sse.UnpackLow(X, Y);   // x0 y0 x1 y1
            var zw01 = Sse.UnpackLow(Z, w);   // z0 w0 z1 w1
            var xy23 = Sse.UnpackHigh(X, Y);  // x2 y2 x3 y3
            var zw23 = Sse.UnpackHigh(Z, w);  // z2 w2 z3 w3
            row0 = Sse.MoveLowToHigh(xy01, zw01);
            row1 = Sse.MoveHighToLow(zw01, xy01);
            row2 = Sse.MoveLowToHigh(xy23, zw23);
            return;
        }
        RowsByLane(w, out row0, out row1, out row2);
    }

    /// <summary><see cref="Rows"/> one element at a time (where SSE is missing; tests call it directly).</summary>
    internal readonly void RowsByLane(Vector128<float> w, out Vector128<float> row0, out Vector128<float> row1, out Vector128<float> row2)
    {
        row0 = Vector128.Create(X.GetElement(0), Y.GetElement(0), Z.GetElement(0), w.GetElement(0));
        row1 = Vector128.Create(X.GetElement(1), Y.GetElement(1), Z.GetElement(1), w.GetElement(1));
        row2 = Vector128.Create(X.GetElement(2), Y.GetElement(2), Z.GetElement(2), w.GetElement(2));
    }
}
