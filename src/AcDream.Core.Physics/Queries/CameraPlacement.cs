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
