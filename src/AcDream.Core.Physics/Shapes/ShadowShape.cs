using System.Numerics;

namespace AcDream.Core.Physics.Shapes;

/// <summary>
/// One collision shape of an object, in the object's space, already scaled (see
/// <see cref="ShadowShapeBuilder.FromSetup"/>). Immutable; shared by every row that refers to it.
/// </summary>
internal sealed class ShadowShape
{
    private ShadowShape(ShadowShapeKind kind, int index) { Kind = kind; Index = index; }

    /// <summary>The kind.</summary>
    public ShadowShapeKind Kind { get; }
    /// <summary>The index of the part, cylsphere or sphere in the setup.</summary>
    public int Index { get; }
    /// <summary>BSP shapes: the model.</summary>
    public PhysicsModel? Model { get; private init; }
    /// <summary>BSP shapes: the part's frame in object space, its origin scaled.</summary>
    public Frame PartFrame { get; private init; }
    /// <summary>BSP shapes: the model's scale.</summary>
    public float ModelScale { get; private init; } = 1f;
    /// <summary>Cylinder shapes: the scaled cylsphere in object space.</summary>
    public CylSphere Cylinder { get; private init; }
    /// <summary>Sphere shapes: the scaled sphere in object space.</summary>
    public Sphere Sphere { get; private init; }

    /// <summary>A sphere in object space (scaled) enclosing the shape, used to find the cells an object touches.</summary>
    public Sphere Bounds { get; private init; }

    internal static ShadowShape ForPart(int index, PhysicsModel model, Frame partFrame, float scale)
    {
        var bounds = model.BoundingSphere;
        return new ShadowShape(ShadowShapeKind.Bsp, index)
        {
            Model = model,
            PartFrame = partFrame,
            ModelScale = scale,
            Bounds = new Sphere(partFrame.LocalToGlobal(bounds.Center * scale), bounds.Radius * scale),
        };
    }

    internal static ShadowShape ForCylinder(int index, CylSphere cylinder)
    {
        var mid = cylinder.LowPoint + new Vector3(0, 0, cylinder.Height * 0.5f);
        float half = cylinder.Height * 0.5f;
        return new ShadowShape(ShadowShapeKind.Cylinder, index)
        {
            Cylinder = cylinder,
            // The axis stays world Z under any rotation, so the bound must hold the cylinder for every rotation of its low point.
            Bounds = new Sphere(mid, System.MathF.Sqrt(cylinder.Radius * cylinder.Radius + half * half)),
        };
    }

    internal static ShadowShape ForSphere(int index, Sphere sphere) =>
        new(ShadowShapeKind.Sphere, index) { Sphere = sphere, Bounds = sphere };
}
