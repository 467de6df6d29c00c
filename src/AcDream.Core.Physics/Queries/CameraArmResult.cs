using System.Numerics;

namespace AcDream.Core.Physics.Queries;

/// <summary>How the camera was placed by <see cref="WorldQuery.CameraArm"/> (the three outcomes of retail SmartBox::update_viewer).</summary>
public enum CameraPlacement : byte
{
    /// <summary>The viewer transition from the pivot succeeded: the camera is where the sweep ended (short of anything in the way).</summary>
    Swept,
    /// <summary>The sweep failed, but a cell holds the desired point: the camera is put there unchecked.</summary>
    AtDesired,
    /// <summary>Neither: the camera falls back to the pivot.</summary>
    AtPivot,
}

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
