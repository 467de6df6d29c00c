namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail TargetStatus: what a target update says about the tracked object (TargetInfo.status). Only
/// <see cref="Ok"/> carries a position; any other status ends a stick (StickyManager::HandleUpdateTarget).
/// </summary>
public enum TargetStatus
{
    /// <summary>No update yet (Undef_TargetStatus).</summary>
    Undefined = 0,
    /// <summary>The target is where the update says (Ok_TargetStatus).</summary>
    Ok = 1,
    /// <summary>The target left the world.</summary>
    ExitWorld = 2,
    /// <summary>The target teleported.</summary>
    Teleported = 3,
    /// <summary>The target went into a container.</summary>
    Contained = 4,
    /// <summary>The target was attached to a parent.</summary>
    Parented = 5,
    /// <summary>No update came for 10 s (TargetManager::HandleTargetting).</summary>
    TimedOut = 6,
}
