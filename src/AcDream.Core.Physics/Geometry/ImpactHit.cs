using System.Numerics;

namespace AcDream.Core.Physics.Geometry;

/// <summary>The first contact of a swept sphere: when (fraction of the sweep), the contact normal (pointing from the shape to the sphere's centre), and the feature.</summary>
internal readonly struct ImpactHit
{
    /// <summary>Creates a hit.</summary>
    public ImpactHit(float time, Vector3 normal, ImpactFeature feature)
    {
        Time = time;
        Normal = normal;
        Feature = feature;
    }

    /// <summary>The fraction of the displacement travelled at first contact, in [0, 1].</summary>
    public float Time { get; }
    /// <summary>The unit contact normal, from the shape towards the sphere's centre.</summary>
    public Vector3 Normal { get; }
    /// <summary>The feature touched.</summary>
    public ImpactFeature Feature { get; }

    /// <inheritdoc />
    public override string ToString() => $"t={Time} n={Normal} {Feature}";
}
