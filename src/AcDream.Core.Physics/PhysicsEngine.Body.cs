using System;
using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    private readonly Transitions.IdList _stepCollided = new();

    /// <summary>
    /// Advances a body by <paramref name="elapsed"/> seconds the retail way (CPhysicsObj::update_object): the
    /// time is gathered until 1/30 s has passed (<see cref="PhysicsConstants.MinQuantum"/>), dropped when longer
    /// than <see cref="PhysicsConstants.HugeQuantum"/>, else stepped whole or in quanta of at most
    /// <see cref="PhysicsConstants.MaxQuantum"/>. Each quantum moves the body by the desired motion (while it
    /// stands on walkable ground) plus its velocity and acceleration (gravity when not standing on walkable
    /// ground; friction on it), through the same transition as <see cref="Resolve"/>; the outcome lands or
    /// lifts the body, reflects its velocity off what it hit by its elasticity, or zeroes it.
    /// A mover with <see cref="PhysicsState.EdgeSlide"/> (the retail player, <see cref="MoverDescription.Player"/>)
    /// standing on walkable ground does not run off a drop deeper than its step-down height: it slides along
    /// the edge or stops at it, as in <see cref="Resolve"/>; without the flag it leaves the ground there and
    /// falls (<see cref="MoverDescription.With"/> makes the copy without it).
    /// Not retail: the desired velocity stands for the animation's root motion, which retail applies per
    /// animation frame from the object's motion table; a player or creature with a motion table steps with
    /// <see cref="Step(MoverDescription, in MoverState, in BodyState, ObjectMotion, double)"/> instead.
    /// </summary>
    /// <param name="mover">What the mover is (its PhysicsState decides Gravity, EdgeSlide, Sledding, Inelastic, Hidden, Frozen).</param>
    /// <param name="state">Where it is and how it stands.</param>
    /// <param name="body">Its velocity, spin, friction, elasticity and carried time.</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <param name="desiredVelocity">
    /// The motion the client's input asks for, world axes, m/s (retail's animation root motion): it moves the
    /// body only while it stands on walkable ground, and becomes its velocity when it leaves the ground (for a
    /// body with a <see cref="BodyState.HasMotionInterpreter"/>).
    /// </param>
    /// <param name="jumpVelocity">
    /// 0 for no jump, else the jump's vertical speed, m/s (retail get_jump_v_z): taken when the body has a
    /// motion interpreter and stands on walkable ground (jump_is_allowed); it leaves the ground with the desired
    /// motion's horizontal part and this vertical speed.
    /// </param>
    /// <exception cref="ArgumentException">A non-finite, negative or out-of-range argument, named in the message; nothing is changed.</exception>
    public BodyStepResult Step(MoverDescription mover, in MoverState state, in BodyState body, double elapsed, Vector3 desiredVelocity,
        float jumpVelocity = 0f)
    {
        ArgumentNullException.ThrowIfNull(mover);
        bool jumped = BeginVelocityStep(mover, state, body, elapsed, desiredVelocity, jumpVelocity, out var s, out var b);
        return Advance(mover, s, b, elapsed, jumped, new VelocityMode(desiredVelocity));
    }

    /// <summary>
    /// The checks and the jump before a step without a motion layer (a desired velocity or a missile): the state
    /// and body to step, with the acceleration of their contact; true when the jump was taken. Throws before
    /// anything is changed.
    /// </summary>
    private bool BeginVelocityStep(MoverDescription mover, in MoverState state, in BodyState body, double elapsed, Vector3 desiredVelocity,
        float jumpVelocity, out MoverState s, out BodyState b)
    {
        var begin = state.Position;
        Guard.Pose(ref begin.Frame, "state.position");
        ValidateState(mover, state, begin, begin.CellId);
        BodyGuard.Check(body, elapsed, desiredVelocity, jumpVelocity);

        s = state;
        b = body;
        var ps = mover.PhysicsState;
        bool gravity = (ps & PhysicsState.Gravity) != 0;

        // CMotionInterp::jump: allowed from walkable ground (or without gravity); set_on_walkable(0) then calls
        // LeaveGround, which sets the leave-ground velocity, only when the body was on walkable ground.
        bool jumped = false;
        if (jumpVelocity > 0f && b.HasMotionInterpreter && (!gravity || (s.Contact && s.OnWalkable)))
        {
            jumped = true;
            if (s.OnWalkable && gravity)
                b.Velocity = BodyMotion.LeaveGroundVelocity(b.Velocity, desiredVelocity, jumpVelocity);
            s.OnWalkable = false;
        }
        // Retail recomputes the acceleration whenever the contact state or the Gravity state changes.
        b.Acceleration = BodyMotion.Acceleration(ps, s.Contact, s.OnWalkable);
        return jumped;
    }

    /// <summary>
    /// Advances a player or creature by <paramref name="elapsed"/> seconds the retail way, moved by its motion
    /// layer (CPhysicsObj::update_object with its CPartArray and CMotionInterp): the quanta as in the other
    /// <c>Step</c>; each quantum the sequence advances (CSequence::update) and its authored offset (the frames'
    /// root offsets plus the motions' velocity and omega per frame crossed, body axes) moves and turns the body
    /// while it stands on walkable ground (only the turn counts off it: UpdatePositionInternal scales the origin
    /// by 0), then the physics velocity and gravity are added (UpdatePhysicsInternal, in retail's rounding),
    /// through the same transition as <see cref="Resolve"/>. Leaving walkable ground sets the velocity to
    /// get_leave_ground_velocity (CMotionInterp::LeaveGround); landing re-applies the held movement
    /// (CMotionInterp::HitGround) and keeps the velocity, which ground friction then decays. The same call
    /// steps a creature on a server and the player on a client.
    /// </summary>
    /// <param name="mover">What the mover is.</param>
    /// <param name="state">Where it is and how it stands.</param>
    /// <param name="body">Its velocity, spin, friction, elasticity and carried time.</param>
    /// <param name="motion">Its motion layer (commands are given to it between steps).</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <exception cref="ArgumentException">A non-finite, negative or out-of-range argument, named in the message; nothing is changed.</exception>
    public BodyStepResult Step(MoverDescription mover, in MoverState state, in BodyState body, ObjectMotion motion, double elapsed)
    {
        ArgumentNullException.ThrowIfNull(mover);
        ArgumentNullException.ThrowIfNull(motion);
        var begin = state.Position;
        Guard.Pose(ref begin.Frame, "state.position");
        ValidateState(mover, state, begin, begin.CellId);
        BodyGuard.Check(body, elapsed, Vector3.Zero, 0f);
        var s = state;
        var b = body;
        b.Acceleration = BodyMotion.Acceleration(mover.PhysicsState, s.Contact, s.OnWalkable);
        motion.Load(mover, s, b);
        return Advance(mover, s, b, elapsed, false, new MotionMode(motion));
    }

    /// <summary>
    /// CPhysicsObj::update_object's quantum loop, the one every body step runs; <paramref name="mode"/> is what differs
    /// between the kinds of body (<see cref="IQuantumMode"/>).
    /// </summary>
    private BodyStepResult Advance<TMode>(MoverDescription mover, MoverState s, BodyState b, double elapsed, bool jumped, in TMode mode)
        where TMode : struct, IQuantumMode
    {
        var ps = mover.PhysicsState;
        _stepCollided.Clear();
        _acceptedTransitions = 0;
        var last = new QuantumOutcome();
        int quanta = 0;
        var start = s.Position;
        double stepped = 0; // the quanta's seconds
        if ((ps & PhysicsState.Frozen) != 0)
        {
            b.PendingTime = 0;
            return Unmoved(s, b, jumped);
        }
        double pending = b.PendingTime + elapsed;
        if (pending < PhysicsConstants.MinQuantum)
        {
            // CPhysics::UseTime: no object is updated before 1/30 s has passed.
            b.PendingTime = pending;
            return Unmoved(s, b, jumped);
        }
        if (pending > PhysicsConstants.HugeQuantum)
        {
            b.PendingTime = 0;
            return Unmoved(s, b, jumped);
        }
        if (pending <= PhysicsConstants.MaxQuantum)
        {
            Quantum(mover, ref s, ref b, (float)pending, mode, ref last);
            stepped = (float)pending;
            quanta = 1;
            pending = 0;
        }
        else
        {
            do
            {
                Quantum(mover, ref s, ref b, (float)PhysicsConstants.MaxQuantum, mode, ref last);
                stepped += (float)PhysicsConstants.MaxQuantum;
                quanta++;
                pending -= PhysicsConstants.MaxQuantum;
            }
            while (pending > PhysicsConstants.MaxQuantum);
            if (pending > PhysicsConstants.MinQuantum)
            {
                Quantum(mover, ref s, ref b, (float)pending, mode, ref last);
                stepped += (float)pending;
                quanta++;
                pending = 0;
            }
        }
        b.PendingTime = pending;
        var move = new MoveResult(!last.Refused, s, last.Refused ? TransitionState.Collided : TransitionState.OK, last.CollisionNormalValid,
            last.CollisionNormal, last.Environment, _stepCollided.Items, last.LastCollided, last.VelocityKilled);
        return new BodyStepResult(move, b, quanta, jumped)
        {
            Transitions = _acceptedTransitions,
            Displacement = start.GetOffset(s.Position),
            SteppedTime = stepped,
        };
    }

    private static BodyStepResult Unmoved(in MoverState s, in BodyState b, bool jumped) =>
        new(new MoveResult(true, s, TransitionState.OK, false, default, false, ReadOnlyMemory<uint>.Empty, 0), b, 0, jumped);

    /// <summary>What the quanta of one step touched, gathered for the step's <see cref="MoveResult"/>.</summary>
    private struct QuantumOutcome
    {
        public bool Refused, CollisionNormalValid, Environment, VelocityKilled;
        public Vector3 CollisionNormal;
        public uint LastCollided;
    }

    /// <summary>One quantum: retail UpdateObjectInternal → UpdatePositionInternal → transition → SetPositionInternal.</summary>
    private void Quantum<TMode>(MoverDescription mover, ref MoverState s, ref BodyState b, float quantum, in TMode mode, ref QuantumOutcome outcome)
        where TMode : struct, IQuantumMode
    {
        b.QuantumStart = s.Position; // the pose a renderer blends from (SmoothFrames)
        bool prevOnWalkable = s.OnWalkable;
        int accepted = _acceptedTransitions;
        QuantumCore(mode.QuantumMover(mover), ref s, ref b, quantum, mode, ref outcome);
        mode.AfterQuantum(this, mover, ref s, ref b, quantum, _acceptedTransitions != accepted, prevOnWalkable);
    }

    private void QuantumCore<TMode>(MoverDescription mover, ref MoverState s, ref BodyState b, float quantum, in TMode mode,
        ref QuantumOutcome outcome) where TMode : struct, IQuantumMode
    {
        var ps = mover.PhysicsState;
        var begin = s.Position;
        var frame = begin.Frame;
        if ((ps & PhysicsState.Hidden) == 0)
        {
            var velocity = b.Velocity;
            mode.Move(mover, s, b, quantum, ref frame, ref velocity);
            b.Velocity = velocity;
            frame.Orientation = BodyMotion.Rotate(frame.Orientation, b.Omega * quantum);
        }
        // UpdateObjectInternal: an origin unchanged within EPSILON on every axis runs no transition (only the turn is kept).
        var d = frame.Origin - begin.Frame.Origin;
        const float e = PhysicsConstants.Epsilon;
        if (MathF.Abs(d.X) <= e && MathF.Abs(d.Y) <= e && MathF.Abs(d.Z) <= e)
        {
            s.Position.Frame.Orientation = frame.Orientation;
            return;
        }
        if ((ps & PhysicsState.AlignPath) != 0)
            frame.Orientation = AlignPath.Heading(d, frame.Orientation); // UpdateObjectInternal: a missile points along its path

        // get_object_info: a body moving away from its contact plane faster than EPSILON is not in contact (check_contact).
        var seeded = s;
        if (s.Contact && Vector3.Dot(b.Velocity, s.ContactPlane.Normal) > PhysicsConstants.Epsilon)
        {
            seeded.Contact = false;
            seeded.OnWalkable = false;
        }
        var result = ResolveCore(mover, seeded, new Position(begin.CellId, frame), b.StationaryFall, trusted: true);
        var span = result.CollidedObjects.Span;
        for (int i = 0; i < span.Length; i++)
            _stepCollided.Add(span[i]);
        if (result.CollidedWithEnvironment) outcome.Environment = true;
        if (result.VelocityKilled) outcome.VelocityKilled = true;
        if (result.LastCollidedObject != 0) outcome.LastCollided = result.LastCollidedObject;
        if (result.CollisionNormalValid)
        {
            outcome.CollisionNormalValid = true;
            outcome.CollisionNormal = result.CollisionNormal;
        }
        if (!result.Succeeded)
        {
            // The transition failed: retail keeps the old origin with the new turn, and the velocity.
            outcome.Refused = true;
            s.Position.Frame.Orientation = frame.Orientation;
            return;
        }

        // SetPositionInternal.
        bool prevOnWalkable = s.OnWalkable;
        var next = result.Next;
        var v = b.Velocity;
        if (result.VelocityKilled)
            v = Vector3.Zero; // OBJECTINFO::kill_velocity, called inside the transition
        v = mode.OnWalkable(mover, b, prevOnWalkable, next, v); // set_on_walkable: LeaveGround / HitGround
        b.Acceleration = BodyMotion.Acceleration(ps, next.Contact, next.OnWalkable);
        if (BodyMotion.StopsSpin(ps, next.Contact, next.OnWalkable))
            b.Omega = Vector3.Zero;
        b.StationaryFall = BodyMotion.HandleCollisions(ref v, ps, b.Elasticity, prevOnWalkable, next.OnWalkable,
            result.CollisionNormalValid, result.CollisionNormal, _transition.CollisionInfo.FramesStationaryFall, b.StationaryFall);
        b.Velocity = v;
        s = next;
    }
}
