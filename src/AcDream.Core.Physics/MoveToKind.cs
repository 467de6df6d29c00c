namespace AcDream.Core.Physics;

/// <summary>Retail's MovementTypes for the MoveToManager.</summary>
public enum MoveToKind
{
    /// <summary>No move.</summary>
    Invalid = 0,
    /// <summary>Move to an object whose positions arrive as target updates.</summary>
    MoveToObject = 6,
    /// <summary>Move to a position.</summary>
    MoveToPosition = 7,
    /// <summary>Turn to face an object.</summary>
    TurnToObject = 8,
    /// <summary>Turn to a heading.</summary>
    TurnToHeading = 9,
}
