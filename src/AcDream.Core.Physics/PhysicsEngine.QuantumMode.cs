using System.Numerics;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// How a body step moves its body each quantum: the parts of retail's UpdateObjectInternal that differ between
    /// the engine's three kinds of body (<see cref="VelocityMode"/>: a desired velocity the caller gives;
    /// <see cref="MotionMode"/>: the motion layer; <see cref="MissileMode"/>: a missile's flight and hit). The one
    /// quantum loop (<see cref="Advance"/>) is generic over it and each mode is a readonly struct, so every call is
    /// resolved when the loop is compiled for that mode: no allocation and no virtual call per quantum.
    /// </summary>
    private interface IQuantumMode
    {
        /// <summary>The description this quantum moves: the step's, or what it has become (a missile loses its flight states at the hit).</summary>
        MoverDescription QuantumMover(MoverDescription mover);

        /// <summary>
        /// UpdatePositionInternal for a body that is not Hidden: moves <paramref name="frame"/> (the quantum's start,
        /// landblock space) by the mode's motion and the physics displacement, and advances <paramref name="velocity"/>
        /// (UpdatePhysicsInternal). The spin is applied after it by the loop.
        /// </summary>
        void Move(MoverDescription mover, in MoverState state, in BodyState body, float quantum, ref Frame frame, ref Vector3 velocity);

        /// <summary>
        /// SetPositionInternal's set_on_walkable: the velocity after an accepted transition left the body
        /// <paramref name="next"/> (LeaveGround / HitGround), from <paramref name="velocity"/>.
        /// </summary>
        Vector3 OnWalkable(MoverDescription mover, in BodyState body, bool prevOnWalkable, in MoverState next, Vector3 velocity);

        /// <summary>
        /// UpdateObjectInternal's tail, after the position is set: the managers' time and the motions completed, or
        /// a missile's report of what it hit. <paramref name="transitionAccepted"/>: this quantum's transition ran and was accepted.
        /// </summary>
        void AfterQuantum(PhysicsEngine engine, MoverDescription mover, ref MoverState state, ref BodyState body, float quantum,
            bool transitionAccepted, bool prevOnWalkable);
    }
}
