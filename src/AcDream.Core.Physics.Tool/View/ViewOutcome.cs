namespace AcDream.Core.Physics.Tool.View;

/// <summary>What happened to a mover in one frame, as the viewer colours it (the plot's outcomes with the step split by direction).</summary>
internal enum ViewOutcome
{
    /// <summary>Moved where it asked to go.</summary>
    Moved,
    /// <summary>Deflected along something.</summary>
    Slid,
    /// <summary>Stepped up (grounded, height rose).</summary>
    SteppedUp,
    /// <summary>Stepped down (grounded, height fell).</summary>
    SteppedDown,
    /// <summary>Refused: left where it was.</summary>
    Refused,
    /// <summary>Ended the frame without ground contact.</summary>
    Airborne,
}
