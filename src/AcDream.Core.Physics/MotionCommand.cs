namespace AcDream.Core.Physics;

/// <summary>
/// Retail's motion command ids (the MotionCommand enumeration of the client, as the DAT's motion tables key
/// them). The high byte's bits say what kind of command it is (<see cref="MotionCommandMask"/>): a style
/// (stance), a substate (a cycle that replaces the forward motion), a modifier (turn and sidestep, combined
/// with the substate), or an action.
/// </summary>
public static class MotionCommand
{
    /// <summary>Standing still (the NonCombat style's default substate).</summary>
    public const uint Ready = 0x41000003;
    /// <summary>Walk forward (3.12 m/s at speed 1 in retail's get_state_velocity).</summary>
    public const uint WalkForward = 0x45000005;
    /// <summary>Walk backwards: adjust_motion turns it into <see cref="WalkForward"/> at −0.65 × the speed.</summary>
    public const uint WalkBackwards = 0x45000006;
    /// <summary>Run forward: <see cref="WalkForward"/> with the Run hold key becomes this at the run rate.</summary>
    public const uint RunForward = 0x44000007;
    /// <summary>Turn right (clockwise seen from above).</summary>
    public const uint TurnRight = 0x6500000D;
    /// <summary>Turn left: adjust_motion turns it into <see cref="TurnRight"/> at −1 × the speed.</summary>
    public const uint TurnLeft = 0x6500000E;
    /// <summary>Sidestep right.</summary>
    public const uint SideStepRight = 0x6500000F;
    /// <summary>Sidestep left: adjust_motion turns it into <see cref="SideStepRight"/> at −1 × the speed.</summary>
    public const uint SideStepLeft = 0x65000010;
    /// <summary>Falling: the substate of a body off walkable ground.</summary>
    public const uint Falling = 0x40000015;
    /// <summary>Dead.</summary>
    public const uint Dead = 0x40000011;
    /// <summary>Fallen (lying on the ground).</summary>
    public const uint Fallen = 0x40000008;
    /// <summary>Crouch (the first of the crouch, sit and sleep substates).</summary>
    public const uint Crouch = 0x41000012;
    /// <summary>Sitting.</summary>
    public const uint Sitting = 0x41000013;
    /// <summary>Sleeping (the last of the crouch, sit and sleep substates).</summary>
    public const uint Sleeping = 0x41000014;
    /// <summary>The NonCombat style (stance), the humanoid's default style.</summary>
    public const uint NonCombat = 0x8000003D;
}
