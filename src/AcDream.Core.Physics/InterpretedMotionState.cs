using AcDream.Core.Physics.Motion;

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
