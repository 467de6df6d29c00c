using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The root offset of one animation frame (the DAT's per-frame "pos frame"): how far the object's origin moves
/// and turns while the frame is crossed, in the object's own axes.
/// </summary>
/// <param name="Origin">The move, metres, body axes.</param>
/// <param name="Orientation">The turn, a unit quaternion.</param>
public readonly record struct RootFrame(Vector3 Origin, Quaternion Orientation);
