namespace AcDream.Core.Physics.Tool;

/// <summary>What happened to a mover in one frame, as the plot colours it.</summary>
internal enum FrameOutcome
{
    /// <summary>Moved where it asked to go.</summary>
    Free,
    /// <summary>Moved, but not where it asked: deflected along something (slid).</summary>
    Slid,
    /// <summary>Moved up or down a step (height changed by more than <see cref="FrameOutcomes.StepHeight"/> while grounded).</summary>
    Stepped,
    /// <summary>Refused: retail left the mover where it was.</summary>
    Refused,
    /// <summary>Ended the frame without ground contact.</summary>
    Airborne,
}
