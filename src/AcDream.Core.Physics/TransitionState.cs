namespace AcDream.Core.Physics;

/// <summary>The result of one collision query or insertion step (retail TransitionState).</summary>
public enum TransitionState
{
    /// <summary>No valid result (retail's 0).</summary>
    Invalid = 0,
    /// <summary>No collision: the check position stands.</summary>
    OK = 1,
    /// <summary>Blocked: the check position must be abandoned.</summary>
    Collided = 2,
    /// <summary>The check position was moved to resolve contact; test again.</summary>
    Adjusted = 3,
    /// <summary>The check position slid along a surface; test again.</summary>
    Slid = 4,
}
