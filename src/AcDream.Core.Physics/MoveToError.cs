namespace AcDream.Core.Physics;

/// <summary>
/// How a MoveTo or turn ended: retail's WeenieError codes the MoveToManager passes to CancelMoveTo and
/// CleanUpAndCallWeenie (acclient-src PORTAL/canim/CMoveToManager.c), plus <see cref="CantGetThere"/> for the opt-in
/// server give-up rule (<see cref="MoveToProgressRule.GiveUp"/>).
/// </summary>
public enum MoveToError : uint
{
    /// <summary>Arrived (or turned) as asked.</summary>
    None = 0x00,
    /// <summary>NoPhysicsObject (8): retail's answer when the manager has no object; not produced here (a MoveTo always has one).</summary>
    NoPhysicsObject = 0x08,
    /// <summary>ActionCancelled (0x36): cancelled by the caller, replaced by a new MoveTo (PerformMovement), or ended with a stick (cancel_moveto: the stick's timeout, a lost target, UnStick or a new StickTo).</summary>
    ActionCancelled = 0x36,
    /// <summary>ObjectGone (0x37): the sought object went away after the move had started (HandleUpdateTarget).</summary>
    ObjectGone = 0x37,
    /// <summary>NoObject (0x38): the sought object was not there when the move started (HandleUpdateTarget).</summary>
    NoObject = 0x38,
    /// <summary>
    /// CantGetThere (0x39, "Unable to move to object!"): the move made too little progress (CheckProgressMade failed:
    /// less than 0.25 m/s over more than 1 s) under the opt-in server rule <see cref="MoveToProgressRule.GiveUp"/> (retail's
    /// client, <see cref="MoveToProgressRule.CountOnly"/>, never ends a move so).
    /// </summary>
    CantGetThere = 0x39,
    /// <summary>YouChargedTooFar (0x3D): farther than the fail distance from where the move started.</summary>
    YouChargedTooFar = 0x3D,
    /// <summary>NoMtableData (0x43): the motion table has no walk, run or turn for the command the move gave (a motion command's error ends the move with its code).</summary>
    NoMotionTableData = 0x43,
}
