using System;
using System.Numerics;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tool;

/// <summary>Classifies trajectory frames.</summary>
internal static class FrameOutcomes
{
    /// <summary>A grounded frame whose height changes by more than this (metres) stepped.</summary>
    public const float StepHeight = 0.01f;

    /// <summary>A frame ending farther than this (metres) from its target slid.</summary>
    public const float SlideDistance = 0.001f;

    /// <summary>
    /// The outcome of <paramref name="frame"/>, which started at <paramref name="previous"/> (the same
    /// landblock frame): refused, else airborne, else stepped, else slid (ended away from its target, or for a
    /// body mover, which has no target, a collision normal was recorded), else free.
    /// </summary>
    public static FrameOutcome Of(TrajectoryFrame frame, Vector3 previous)
    {
        if (!frame.Succeeded)
            return FrameOutcome.Refused;
        if (!frame.Contact)
            return FrameOutcome.Airborne;
        if (MathF.Abs(frame.Position.Z - previous.Z) > StepHeight)
            return FrameOutcome.Stepped;
        // A body mover's frame has no target (it moves by velocity): it slid when a collision deflected it.
        if (frame.Target.CellId == 0)
            return frame.CollisionNormalValid ? FrameOutcome.Slid : FrameOutcome.Free;
        var target = frame.Target.Origin + LandDefs.BlockOffset(frame.Cell, frame.Target.CellId);
        var missed = target - frame.Position;
        missed.Z = 0f;
        return missed.Length() > SlideDistance ? FrameOutcome.Slid : FrameOutcome.Free;
    }
}
