using System.Numerics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics;

/// <summary>
/// A vertical cylinder with rounded contact rules (retail CCylSphere's data): a low point, a radius and
/// a height. Retail quirk: the axis is always world +Z, whatever the owner's rotation; only the low point
/// is transformed (holtburger, acclient.c:347305-347338). Collision routines live in <see cref="CylSphereCollision"/>.
/// </summary>
public struct CylSphere
{
    /// <summary>The centre of the bottom cap.</summary>
    public Vector3 LowPoint;

    /// <summary>The radius.</summary>
    public float Radius;

    /// <summary>The height above the low point.</summary>
    public float Height;

    /// <summary>Creates a cylsphere.</summary>
    public CylSphere(Vector3 lowPoint, float radius, float height)
    {
        LowPoint = lowPoint;
        Radius = radius;
        Height = height;
    }

    /// <inheritdoc />
    public override readonly string ToString() => $"(low={LowPoint}, r={Radius}, h={Height})";
}
