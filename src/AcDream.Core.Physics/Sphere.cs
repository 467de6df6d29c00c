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
