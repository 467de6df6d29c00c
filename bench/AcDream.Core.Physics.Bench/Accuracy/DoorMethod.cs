using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>The ways of resolving a frame that the door benchmark compares.</summary>
public enum DoorMethod
{
    /// <summary>The engine as retail runs it (sub-steps of one sphere radius).</summary>
    Retail,
    /// <summary>Sub-steps of a quarter radius.</summary>
    Scale0_25,
    /// <summary>Sub-steps of half a radius.</summary>
    Scale0_5,
    /// <summary>Sub-steps of two radii.</summary>
    Scale2,
    /// <summary>Sub-steps of four radii.</summary>
    Scale4,
    /// <summary>The exact continuous sweep (<see cref="ReferenceSweep"/>).</summary>
    Reference,
}
