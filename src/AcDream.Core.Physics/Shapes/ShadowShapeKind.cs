namespace AcDream.Core.Physics.Shapes;

/// <summary>The kind of a collision shape.</summary>
public enum ShadowShapeKind : byte
{
    /// <summary>A part's physics BSP.</summary>
    Bsp = 0,
    /// <summary>A cylsphere.</summary>
    Cylinder = 1,
    /// <summary>A sphere.</summary>
    Sphere = 2,
}
