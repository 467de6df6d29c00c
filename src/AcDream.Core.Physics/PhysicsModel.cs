using System;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// The physics half of a retail GfxObj: a physics BSP and the bounding sphere tested before it.
/// Shared, immutable; one model can be placed many times.
/// </summary>
public sealed class PhysicsModel
{
    /// <summary>
    /// Creates a model; the bounding sphere defaults to the tree's root bounds. Its radius must be greater
    /// than zero and at most <see cref="InputLimits.MaxExtent"/> (as the scene loader requires).
    /// </summary>
    public PhysicsModel(BspTree bsp, Sphere? boundingSphere = null, string name = "model")
    {
        Bsp = bsp ?? throw new ArgumentNullException(nameof(bsp), $"{name}.bsp: is required.");
        var bounds = boundingSphere ?? bsp.Bounds;
        Guard.Finite(bounds.Center, $"{name}.boundingSphere.center");
        // A radius of zero is refused as the scene loader refuses it: such a model could never be touched.
        Guard.Extent(bounds.Radius, false, $"{name}.boundingSphere.radius");
        BoundingSphere = bounds;
        Name = name;
    }

    /// <summary>The physics BSP, in model space.</summary>
    public BspTree Bsp { get; }
    /// <summary>The sphere (model space) that must touch a mover sphere before the BSP is tested.</summary>
    public Sphere BoundingSphere { get; }
    /// <summary>A name for diagnostics.</summary>
    public string Name { get; }
}
