namespace AcDream.Core.Physics;

/// <summary>The result of a motion command (retail's WeenieError codes for movement).</summary>
public enum MotionError
{
    /// <summary>Done.</summary>
    None = 0x00,
    /// <summary>The motion table has nothing for the command.</summary>
    NoMotionTableData = 0x43,
    /// <summary>Six actions are queued already.</summary>
    TooManyActions = 0x45,
    /// <summary>A jump refused for another reason (no stamina, constrained).</summary>
    GeneralMovementFailure = 0x47,
    /// <summary>A jump or action while not on walkable ground.</summary>
    CantJumpWhileInTheAir = 0x24,
    /// <summary>A jump from a position that allows none (falling, sitting…).</summary>
    CantJumpFromThisPosition = 0x48,
    /// <summary>The owner refuses the jump (CanJump).</summary>
    CantJumpLoadedDown = 0x49,
    /// <summary>Crouching in a combat style.</summary>
    CantCrouchInCombat = 0x3F,
    /// <summary>Sitting in a combat style.</summary>
    CantSitInCombat = 0x40,
    /// <summary>Lying down in a combat style.</summary>
    CantLieDownInCombat = 0x41,
    /// <summary>A chat emote in a combat style.</summary>
    CantChatEmoteInCombat = 0x42,
}
