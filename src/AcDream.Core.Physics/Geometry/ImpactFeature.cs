namespace AcDream.Core.Physics.Geometry;

/// <summary>Which feature of a shape a swept sphere touched first.</summary>
internal enum ImpactFeature : byte
{
    /// <summary>No contact.</summary>
    None = 0,
    /// <summary>The sphere already touched the shape and was moving into it (time 0).</summary>
    Resting,
    /// <summary>A polygon's face (its interior).</summary>
    Face,
    /// <summary>A polygon's edge.</summary>
    Edge,
    /// <summary>A polygon's vertex.</summary>
    Vertex,
    /// <summary>A cylinder's curved side.</summary>
    CylinderSide,
    /// <summary>A cylinder's top or bottom disc.</summary>
    CylinderCap,
    /// <summary>A cylinder's top or bottom rim (found by conservative advancement).</summary>
    CylinderRim,
    /// <summary>A sphere.</summary>
    Sphere,
}
