using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>One part of a setup: a physics model (or none) placed by a frame in the setup's space.</summary>
public sealed class SetupPart
{
    /// <summary>Creates a part.</summary>
    /// <param name="model">The part's physics model, or null.</param>
    /// <param name="frame">The part's placement in the setup's space.</param>
    /// <param name="defaultScale">The setup's default scale for this part (retail Setup default_scale, Z component).</param>
    public SetupPart(PhysicsModel? model, Frame frame, float defaultScale = 1f)
    {
        Model = model;
        Frame = frame;
        DefaultScale = defaultScale;
    }

    /// <summary>The part's physics model, or null for a part without a physics BSP.</summary>
    public PhysicsModel? Model { get; }
    /// <summary>The part's placement in the setup's space.</summary>
    public Frame Frame { get; }
    /// <summary>
    /// The setup's default scale for this part. Retail scales a part's BSP by default_scale × the object's
    /// scale and collides with the Z component (CPartArray, acclient CPartArray.c:1172-1213).
    /// </summary>
    public float DefaultScale { get; }
}
