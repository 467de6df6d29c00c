using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics;

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
