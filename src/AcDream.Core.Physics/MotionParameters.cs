namespace AcDream.Core.Physics;

/// <summary>
/// How a motion command is applied (the parts of retail MovementParameters the motion layer reads). The
/// default is a player's key press: speed 1, the current hold key, and both states changed.
/// </summary>
/// <param name="Speed">The speed, finite.</param>
/// <param name="HoldKey">The hold key given with the command (<see cref="HoldKey.Invalid"/>: the current one).</param>
/// <param name="SetHoldKey">Make <paramref name="HoldKey"/> the current hold key first (SetHoldKey).</param>
/// <param name="ModifyRawState">Record the command in the raw state.</param>
/// <param name="ModifyInterpretedState">Record it in the interpreted state.</param>
/// <param name="DisableJumpDuringLink">Refuse jumps until the motion's links are done.</param>
public readonly record struct MotionParameters(float Speed = 1f, HoldKey HoldKey = HoldKey.Invalid, bool SetHoldKey = true,
    bool ModifyRawState = true, bool ModifyInterpretedState = true, bool DisableJumpDuringLink = false)
{
    /// <summary>Speed 1, the current hold key, both states changed.</summary>
    public MotionParameters() : this(1f) { }
}
