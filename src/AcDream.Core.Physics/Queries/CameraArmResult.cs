using System.Numerics;

namespace AcDream.Core.Physics.Queries;

/// <summary>Where the camera ends up, and what stopped it.</summary>
public readonly struct CameraArmResult
{
    internal CameraArmResult(Position camera, CameraPlacement placement, bool blocked, Vector3 normal)
    {
        Camera = camera;
        Placement = placement;
        Blocked = blocked;
        Normal = normal;
    }

    /// <summary>The camera's position (cell and landblock-local frame).</summary>
    public Position Camera { get; }
    /// <summary>How it was placed.</summary>
    public CameraPlacement Placement { get; }
    /// <summary>Something stopped the camera short of the desired point.</summary>
    public bool Blocked { get; }
    /// <summary>The normal of what stopped it (when <see cref="Blocked"/>).</summary>
    public Vector3 Normal { get; }
}
