namespace AcDream.Core.Physics.Motion;

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
