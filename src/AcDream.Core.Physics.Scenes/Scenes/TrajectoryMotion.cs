using System.Numerics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// What a motion mover's frame records beyond a body frame: the heading (the frame's rotation) and the command in
/// effect (the interpreted motion state) after the step.
/// </summary>
/// <param name="Rotation">The mover's rotation after the step.</param>
/// <param name="Interpreted">The interpreted motion state after the step.</param>
public readonly record struct TrajectoryMotion(Quaternion Rotation, InterpretedMotionState Interpreted);
