namespace AcDream.Core.Physics;

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
