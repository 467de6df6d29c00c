using System.Numerics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// One frame of a body mover (a scene mover moved by <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>): the elapsed time, the
/// desired motion and the jump, as a client would pass them each frame.
/// </summary>
/// <param name="Elapsed">Seconds since the previous frame.</param>
/// <param name="DesiredVelocity">The desired motion, m/s, landblock axes.</param>
/// <param name="JumpVelocity">0, or the jump's vertical speed, m/s.</param>
public readonly record struct SceneStep(double Elapsed, Vector3 DesiredVelocity, float JumpVelocity);
