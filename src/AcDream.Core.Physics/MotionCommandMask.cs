namespace AcDream.Core.Physics;

/// <summary>The bits of a motion command id that say what kind of command it is (retail CommandMask).</summary>
public static class MotionCommandMask
{
    /// <summary>A style (stance).</summary>
    public const uint Style = 0x80000000;
    /// <summary>A substate (a cycle).</summary>
    public const uint Substate = 0x40000000;
    /// <summary>A modifier (combined with the substate: turn, sidestep).</summary>
    public const uint Modifier = 0x20000000;
    /// <summary>An action (a one-shot motion).</summary>
    public const uint Action = 0x10000000;
    /// <summary>The command number without the kind bits.</summary>
    public const uint Command = 0x00FFFFFF;
}
