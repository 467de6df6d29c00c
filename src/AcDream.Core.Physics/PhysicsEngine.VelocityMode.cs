using System.Numerics;
using AcDream.Core.Physics.Body;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// A body moved by a desired velocity the caller gives (not retail: it stands for the animation's root
    /// motion), plus its own velocity and acceleration; with a zero desired velocity, an object without a motion
    /// table (a thrown item, a falling body).
    /// </summary>
    private readonly struct VelocityMode(Vector3 desiredVelocity) : IQuantumMode
    {
        public MoverDescription QuantumMover(MoverDescription mover) => mover;

        public void Move(MoverDescription mover, in MoverState state, in BodyState body, float quantum, ref Frame frame, ref Vector3 velocity)
        {
            // UpdatePositionInternal: the animation's root motion counts only on walkable ground (scaled by 0 off it).
            var offset = state.OnWalkable ? desiredVelocity * quantum : Vector3.Zero;
            offset += BodyMotion.Integrate(ref velocity, body.Acceleration, quantum, state, mover.PhysicsState, body.Friction);
            frame.Origin += offset;
        }

        public Vector3 OnWalkable(MoverDescription mover, in BodyState body, bool prevOnWalkable, in MoverState next, Vector3 velocity) =>
            prevOnWalkable && !next.OnWalkable && body.HasMotionInterpreter && (mover.PhysicsState & PhysicsState.Gravity) != 0
                ? BodyMotion.LeaveGroundVelocity(velocity, desiredVelocity, 0f) // MovementManager::LeaveGround
                : velocity;

        public void AfterQuantum(PhysicsEngine engine, MoverDescription mover, ref MoverState state, ref BodyState body, float quantum,
            bool transitionAccepted, bool prevOnWalkable)
        {
        }
    }
}
