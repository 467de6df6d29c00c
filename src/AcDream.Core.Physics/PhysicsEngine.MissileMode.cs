using System.Numerics;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// A missile: moved as an object without a motion table (<see cref="VelocityMode"/> with no desired velocity),
    /// by its current description (the flight states go at the hit), and after each quantum counted and, when its
    /// transition was accepted, checked for what it hit (handle_all_collisions).
    /// </summary>
    private readonly struct MissileMode(Missile missile) : IQuantumMode
    {
        private readonly VelocityMode _flight = new(Vector3.Zero);

        public MoverDescription QuantumMover(MoverDescription mover) => missile.Description;

        public void Move(MoverDescription mover, in MoverState state, in BodyState body, float quantum, ref Frame frame, ref Vector3 velocity) =>
            _flight.Move(mover, state, body, quantum, ref frame, ref velocity);

        public Vector3 OnWalkable(MoverDescription mover, in BodyState body, bool prevOnWalkable, in MoverState next, Vector3 velocity) =>
            _flight.OnWalkable(mover, body, prevOnWalkable, next, velocity);

        public void AfterQuantum(PhysicsEngine engine, MoverDescription mover, ref MoverState state, ref BodyState body, float quantum,
            bool transitionAccepted, bool prevOnWalkable)
        {
            missile.CountQuantum();
            if (transitionAccepted)
                missile.AfterTransition(engine._transition.CollisionInfo, engine._transition.World.Objects, prevOnWalkable, state);
        }
    }
}
