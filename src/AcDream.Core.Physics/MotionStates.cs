namespace AcDream.Core.Physics;

/// <summary>
/// The interpreted motion state (retail InterpretedMotionState): what the object is doing after
/// adjust_motion — the style, the forward command (Ready, WalkForward, RunForward, Falling…) with its speed,
/// the sidestep (SideStepRight or 0) and turn (TurnRight or 0) with theirs. Left and backwards commands
/// appear as their right and forward forms at negative speed.
/// </summary>
public struct InterpretedMotionState
{
    /// <summary>The style (stance).</summary>
    public uint Style;
    /// <summary>The forward command.</summary>
    public uint ForwardCommand;
    /// <summary>Its speed.</summary>
    public float ForwardSpeed;
    /// <summary>The sidestep command, 0 for none.</summary>
    public uint SideStepCommand;
    /// <summary>Its speed.</summary>
    public float SideStepSpeed;
    /// <summary>The turn command, 0 for none.</summary>
    public uint TurnCommand;
    /// <summary>Its speed.</summary>
    public float TurnSpeed;

    /// <summary>The state an object starts in: NonCombat, Ready, no sidestep, no turn, speeds 1.</summary>
    public static InterpretedMotionState Default => new()
    {
        Style = MotionCommand.NonCombat, ForwardCommand = MotionCommand.Ready, ForwardSpeed = 1f, SideStepSpeed = 1f, TurnSpeed = 1f,
    };

    // InterpretedMotionState::ApplyMotion.
    internal void Apply(uint motion, float speed)
    {
        switch (motion)
        {
            case MotionCommand.TurnRight:
                TurnCommand = motion;
                TurnSpeed = speed;
                break;
            case MotionCommand.SideStepRight:
                SideStepCommand = motion;
                SideStepSpeed = speed;
                break;
            default:
                if ((motion & MotionCommandMask.Substate) != 0)
                {
                    ForwardCommand = motion;
                    ForwardSpeed = speed;
                }
                else if ((motion & MotionCommandMask.Style) != 0)
                {
                    ForwardCommand = MotionCommand.Ready;
                    Style = motion;
                }
                break;
        }
    }

    // InterpretedMotionState::RemoveMotion.
    internal void Remove(uint motion)
    {
        switch (motion)
        {
            case MotionCommand.TurnRight:
                TurnCommand = 0;
                break;
            case MotionCommand.SideStepRight:
                SideStepCommand = 0;
                break;
            default:
                RemoveMotionRule.ForwardOrStyle(motion, ref ForwardCommand, ref ForwardSpeed, ref Style);
                break;
        }
    }
}

/// <summary>The part both states' RemoveMotion share (InterpretedMotionState::RemoveMotion, RawMotionState::RemoveMotion).</summary>
internal static class RemoveMotionRule
{
    /// <summary>A substate stops only when it is the forward command (back to Ready at speed 1); a style only when it is the current one (back to NonCombat).</summary>
    public static void ForwardOrStyle(uint motion, ref uint forward, ref float forwardSpeed, ref uint style)
    {
        if ((motion & MotionCommandMask.Substate) != 0)
        {
            if (forward == motion)
            {
                forward = MotionCommand.Ready;
                forwardSpeed = 1f;
            }
        }
        else if ((motion & MotionCommandMask.Style) != 0 && style == motion)
        {
            style = MotionCommand.NonCombat;
        }
    }
}

/// <summary>
/// The raw motion state (retail RawMotionState): the commands as given, before adjust_motion, each with the
/// hold key it was given with (<see cref="HoldKey.Invalid"/>: the current hold key applies).
/// </summary>
public struct RawMotionState
{
    /// <summary>The hold key in effect (None or Run).</summary>
    public HoldKey CurrentHoldKey;
    /// <summary>The style.</summary>
    public uint Style;
    /// <summary>The forward command as given (Ready, WalkForward, WalkBackwards…).</summary>
    public uint ForwardCommand;
    /// <summary>Its hold key.</summary>
    public HoldKey ForwardHoldKey;
    /// <summary>Its speed.</summary>
    public float ForwardSpeed;
    /// <summary>The sidestep command as given (SideStepRight, SideStepLeft or 0).</summary>
    public uint SideStepCommand;
    /// <summary>Its hold key.</summary>
    public HoldKey SideStepHoldKey;
    /// <summary>Its speed.</summary>
    public float SideStepSpeed;
    /// <summary>The turn command as given (TurnRight, TurnLeft or 0).</summary>
    public uint TurnCommand;
    /// <summary>Its hold key.</summary>
    public HoldKey TurnHoldKey;
    /// <summary>Its speed.</summary>
    public float TurnSpeed;

    /// <summary>The state an object starts in: hold key None, NonCombat, Ready, speeds 1.</summary>
    public static RawMotionState Default => new()
    {
        CurrentHoldKey = HoldKey.None, Style = MotionCommand.NonCombat, ForwardCommand = MotionCommand.Ready, ForwardSpeed = 1f,
        SideStepSpeed = 1f, TurnSpeed = 1f,
    };

    // RawMotionState::ApplyMotion: a command given with SetHoldKey takes the current hold key later (Invalid).
    internal void Apply(uint motion, in MotionParameters p)
    {
        var key = p.SetHoldKey ? HoldKey.Invalid : p.HoldKey;
        switch (motion)
        {
            case MotionCommand.TurnRight:
            case MotionCommand.TurnLeft:
                TurnCommand = motion;
                TurnHoldKey = key;
                TurnSpeed = p.Speed;
                break;
            case MotionCommand.SideStepRight:
            case MotionCommand.SideStepLeft:
                SideStepCommand = motion;
                SideStepHoldKey = key;
                SideStepSpeed = p.Speed;
                break;
            default:
                if ((motion & MotionCommandMask.Substate) != 0)
                {
                    if (motion != MotionCommand.RunForward)
                    {
                        ForwardCommand = motion;
                        ForwardHoldKey = key;
                        ForwardSpeed = p.Speed;
                    }
                }
                else if ((motion & MotionCommandMask.Style) != 0 && Style != motion)
                {
                    ForwardCommand = MotionCommand.Ready;
                    Style = motion;
                }
                break;
        }
    }

    // RawMotionState::RemoveMotion.
    internal void Remove(uint motion)
    {
        switch (motion)
        {
            case MotionCommand.TurnRight:
            case MotionCommand.TurnLeft:
                TurnCommand = 0;
                break;
            case MotionCommand.SideStepRight:
            case MotionCommand.SideStepLeft:
                SideStepCommand = 0;
                break;
            default:
                RemoveMotionRule.ForwardOrStyle(motion, ref ForwardCommand, ref ForwardSpeed, ref Style);
                break;
        }
    }
}

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
