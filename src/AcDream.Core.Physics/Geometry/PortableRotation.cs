using System.Numerics;

namespace AcDream.Core.Physics.Geometry;

/// <summary>
/// A vector turned by a unit quaternion in plain float arithmetic. <see cref="Vector3.Transform(Vector3, Quaternion)"/>
/// is built on <c>MultiplyAddEstimate</c>, which fuses the multiply and the add where the CPU has a fused
/// multiply-add and rounds twice where it has none, so its bits depend on the machine (docs/robustness.md,
/// "Determinism"). Here every product and sum rounds as written, the same on every CPU.
/// </summary>
internal static class PortableRotation
{
    /// <summary><paramref name="v"/> turned by the unit quaternion <paramref name="q"/>: the rotation matrix of q applied to v.</summary>
    public static Vector3 Apply(Vector3 v, Quaternion q)
    {
        float x2 = q.X + q.X, y2 = q.Y + q.Y, z2 = q.Z + q.Z;
        float xx = q.X * x2, yy = q.Y * y2, zz = q.Z * z2;
        float xy = q.X * y2, xz = q.X * z2, yz = q.Y * z2;
        float wx = q.W * x2, wy = q.W * y2, wz = q.W * z2;
        return new Vector3(
            v.X * (1f - yy - zz) + v.Y * (xy - wz) + v.Z * (xz + wy),
            v.X * (xy + wz) + v.Y * (1f - xx - zz) + v.Z * (yz - wx),
            v.X * (xz - wy) + v.Y * (yz + wx) + v.Z * (1f - xx - yy));
    }
}
