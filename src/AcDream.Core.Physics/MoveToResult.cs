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

/// <summary>
/// What a MoveTo does when its progress check fails (see <see cref="ObjectMotion.MoveToProgressRule"/>). The default,
/// <see cref="CountOnly"/>, is the 2013 client's; <see cref="GiveUp"/> is an opt-in server rule.
/// </summary>
public enum MoveToProgressRule
{
    /// <summary>
    /// The default, retail's client exactly: CMoveToManager's HandleMoveToPosition and HandleTurnToHeading add one to
    /// fail_progress_count per failed check (acclient.c:345659, 345769) and nothing in the manager reads it; a blocked
    /// mover runs in place until its owner cancels the move.
    /// </summary>
    CountOnly,
    /// <summary>
    /// Not retail's client (opt-in): CMoveToManager never ends a move for lack of progress. This stands for the server's
    /// cancel of a creature whose move makes no progress (retail's monster AI reads the fail count and cancels the move
    /// after a time, outside the manager): the move ends with <see cref="MoveToError.CantGetThere"/> once its progress
    /// checks (CheckProgressMade: less than 0.25 m/s over more than 1 s) have kept failing for a further progress window
    /// (1 s) after the first failure, so no progress for more than 2 s in all; a passing dip (a creature turning about to
    /// move away) does not end it.
    /// </summary>
    GiveUp,
}
