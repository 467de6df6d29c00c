namespace AcDream.Core.Physics;

/// <summary>Where a MoveTo stands.</summary>
public enum MoveToStatus
{
    /// <summary>No MoveTo or turn has been started on this object yet (once one has, the status never returns here).</summary>
    Idle,
    /// <summary>Waiting for the first position of the sought object (MoveToObject / TurnToObject before the first target update).</summary>
    WaitingForTarget,
    /// <summary>Turning or moving.</summary>
    Moving,
    /// <summary>Ended: <see cref="ObjectMotion.MoveToResult"/> says how.</summary>
    Ended,
}
