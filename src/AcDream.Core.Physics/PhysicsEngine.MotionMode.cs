using System.Numerics;
using AcDream.Core.Physics.Body;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// A player or creature moved by its motion layer, the retail way: the sequence's authored offset, the position
    /// managers' adjustment, then the physics displacement in retail's rounding; the interpreter's LeaveGround and
    /// HitGround; after the quantum, MoveTo, the completed motions and the interpolation's blip.
    /// </summary>
    private readonly struct MotionMode(ObjectMotion motion) : IQuantumMode
    {
        public MoverDescription QuantumMover(MoverDescription mover) => mover;

        public void Move(MoverDescription mover, in MoverState state, in BodyState body, float quantum, ref Frame frame, ref Vector3 velocity)
        {
            // UpdatePositionInternal (CPhysicsObj.c:4431): the sequence's offset (body axes), its origin scaled by the
            // object's scale on walkable ground and by 0 off it (the turn is kept), combined onto the position; then
            // the physics displacement (UpdatePhysicsInternal) and the physics omega, in world axes.
            var offset = Frame.Identity;
            motion.Advance(quantum, ref offset);
            float scale = state.OnWalkable ? mover.Scale : 0f;
            offset.Origin = new Vector3((float)(offset.Origin.X * (double)scale), (float)(offset.Origin.Y * (double)scale),
                (float)(offset.Origin.Z * (double)scale));
            motion.PositionManager.AdjustOffset(ref offset, quantum, mover, state); // interpolation, sticky, leash
            frame = frame.Combine(offset);
            BodyMotion.IntegrateInto(ref frame.Origin, ref velocity, body.Acceleration, quantum, state, mover.PhysicsState, body.Friction);
        }

        // set_on_walkable: CMotionInterp::LeaveGround / HitGround.
        public Vector3 OnWalkable(MoverDescription mover, in BodyState body, bool prevOnWalkable, in MoverState next, Vector3 velocity) =>
            motion.SetOnWalkable(next.OnWalkable, next.Position.Frame.Orientation, next.Contact, velocity);

        public void AfterQuantum(PhysicsEngine engine, MoverDescription mover, ref MoverState state, ref BodyState body, float quantum,
            bool transitionAccepted, bool prevOnWalkable)
        {
            // After SetPositionInternal: MovementManager::UseTime → MoveToManager::UseTime (Motion/ObjectMotion.MoveTo.cs).
            motion.UseMoveTo(mover, ref state, body, quantum);
            // UpdateObjectInternal's tail: CPartArray::HandleMovement completes the motions that needed no animation.
            motion.HandleMovement();
            // PositionManager::UseTime: the sticky timeout, and the interpolation's blip (SetPositionSimple).
            if (motion.PositionManager.UseTime(quantum, out var blipTarget))
                engine.Blip(mover, ref state, ref body, blipTarget, motion.PositionManager);
        }
    }
}
