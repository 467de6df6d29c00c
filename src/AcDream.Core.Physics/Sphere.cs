using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics;

/// <summary>A sphere: a centre and a radius (retail CSphere's data). Collision routines live in <see cref="SphereCollision"/>.</summary>
public struct Sphere
{
    /// <summary>The centre.</summary>
    public Vector3 Center;

    /// <summary>The radius.</summary>
    public float Radius;

    /// <summary>Creates a sphere.</summary>
    public Sphere(Vector3 center, float radius)
    {
        Center = center;
        Radius = radius;
    }

    /// <summary>True when the two spheres overlap (touching counts), as retail CSphere::intersects.</summary>
    public readonly bool Intersects(in Sphere other)
    {
        var delta = other.Center - Center;
        float reach = Radius + other.Radius;
        return VectorMath.Dot(delta, delta) - reach * reach < PhysicsConstants.Epsilon;
    }

    /// <inheritdoc />
    public override readonly string ToString() => $"({Center}, r={Radius})";
}

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
