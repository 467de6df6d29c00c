using System;
using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics;

/// <summary>
/// The motion layer of one player or creature: its motion table, the interpreter's raw and interpreted
/// states (retail CMotionInterp), the motion table manager's state and the animation sequence (CPartArray's
/// MotionTableManager and CSequence). Commands (<see cref="DoMotion"/>, <see cref="StopMotion"/>,
/// <see cref="StopCompletely"/>, <see cref="ChargeJump"/>, <see cref="Jump"/>) change it between steps;
/// <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, ObjectMotion, double)"/>
/// moves the body by it. A command that leaves the ground (a jump) changes the caller's mover and body state
/// through its ref arguments. One instance per object; not thread-safe; no allocation once warm.
/// </summary>
public sealed partial class ObjectMotion
{
    private readonly Sequence _sequence = new();
    private readonly MotionTableManager _manager;
    private readonly MotionInterpreter _interp;

    /// <summary>
    /// Creates the motion layer of an object entering the world (CMotionInterp::enter_default_state): the
    /// table's default style and cycle, then LeaveGround as retail does, which leaves it Falling until
    /// <see cref="Place"/> (or a step) puts it on walkable ground.
    /// </summary>
    /// <param name="table">The motion table.</param>
    /// <param name="skills">The run rate and jump velocity (retail CWeenieObject); null for an object without one (retail: jump speed 10 m/s, run rate 1).</param>
    public ObjectMotion(MotionTable table, IMotionSkills? skills = null)
    {
        ArgumentNullException.ThrowIfNull(table);
        Table = table;
        _manager = new MotionTableManager(table, _sequence);
        _interp = new MotionInterpreter(_manager, skills);
        _interp.Body = new InterpreterBody { Gravity = true, Orientation = Quaternion.Identity };
        _interp.EnterDefaultState();
        PositionManager = new Managers.PositionManager(_interp, this);
    }

    /// <summary>
    /// The object's position managers (retail CPhysicsObj's PositionManager): smoothing towards reported positions,
    /// sticking to a target, the leash. The body step runs them each quantum.
    /// </summary>
    public Managers.PositionManager PositionManager { get; }

    /// <summary>The motion table.</summary>
    public MotionTable Table { get; }

    /// <summary>The interpreted state (after adjust_motion).</summary>
    public InterpretedMotionState Interpreted => _interp.Interpreted;

    /// <summary>The raw state (the commands as given).</summary>
    public RawMotionState Raw => _interp.Raw;

    /// <summary>The motion table manager's style.</summary>
    public uint Style => _manager.State.Style;
    /// <summary>The cycle playing (the substate).</summary>
    public uint Substate => _manager.State.Substate;
    /// <summary>Its speed.</summary>
    public float SubstateSpeed => _manager.State.SubstateMod;
    /// <summary>The number of modifiers combined with the cycle.</summary>
    public int ModifierCount => _manager.State.ModifierCount;
    /// <summary>A modifier, newest first.</summary>
    public MotionAndSpeed Modifier(int index) =>
        (uint)index < (uint)_manager.State.ModifierCount ? _manager.State.Modifier(index) : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>The sequence's velocity (body axes, m/s): the motions' velocities × their speeds.</summary>
    public Vector3 SequenceVelocity => _sequence.Velocity;
    /// <summary>The sequence's omega (body axes, rad/s).</summary>
    public Vector3 SequenceOmega => _sequence.Omega;
    /// <summary>The animation playing, 0 when none.</summary>
    public uint CurrentAnimation => _sequence.Current >= 0 ? _sequence[_sequence.Current].Animation.Id : 0;
    /// <summary>Its framerate (× the speed), frames/s.</summary>
    public float CurrentFramerate => _sequence.Current >= 0 ? _sequence[_sequence.Current].Framerate : 0f;
    /// <summary>The frame number within it.</summary>
    public double FrameNumber => _sequence.FrameNumber;
    /// <summary>The number of animations in the sequence (links, then the cycle).</summary>
    public int AnimationCount => _sequence.Count;
    /// <summary>The index of the cycle's first animation in the sequence, −1 when it is empty.</summary>
    public int FirstCyclicAnimation => _sequence.FirstCyclic;
    /// <summary>An animation of the sequence and its framerate (× the speed), in play order.</summary>
    public (uint Id, float Framerate) Animation(int index) =>
        (uint)index < (uint)_sequence.Count ? (_sequence[index].Animation.Id, _sequence[index].Framerate) : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>The run rate in effect (the skills' answer, else the last run speed seen).</summary>
    public float RunRate => _interp.RunRate();

    /// <summary>CMotionInterp::get_state_velocity: the interpreted state's speed in body axes, m/s (what a jump carries into the air).</summary>
    public Vector3 StateVelocity => _interp.StateVelocity();

    /// <summary>CMotionInterp::get_max_speed: 4 m/s × the run rate.</summary>
    public float MaxSpeed => _interp.MaxSpeed();

    /// <summary>
    /// Puts the object in the world at <paramref name="state"/> (retail: the placement's set_on_walkable):
    /// on walkable ground the interpreter's HitGround applies the current movement (Ready after creation).
    /// </summary>
    /// <exception cref="ArgumentException">A non-finite body velocity; nothing is changed.</exception>
    public void Place(MoverDescription mover, in MoverState state, ref BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckBody(body);
        Load(mover, state, body);
        bool onWalkable = _interp.Body.OnWalkable;
        _interp.Body.OnWalkable = false;
        _interp.SetOnWalkable(onWalkable);
        body.Velocity = _interp.Body.Velocity;
    }

    /// <summary>
    /// CMotionInterp::DoMotion: a raw command (e.g. <see cref="MotionCommand.WalkForward"/> with the Run key),
    /// adjusted (backwards, left, run) and given to the motion table.
    /// </summary>
    /// <exception cref="ArgumentException">An unknown command (not in the table and not a command the interpreter maps), a non-finite or out-of-range speed; nothing is changed.</exception>
    public MotionError DoMotion(uint motion, in MotionParameters parameters, MoverDescription mover, ref MoverState state, ref BodyState body) =>
        Command(stop: false, motion, parameters, mover, ref state, ref body);

    /// <summary>CMotionInterp::StopMotion: ends a raw command (the cycle goes back to the style's default, a modifier is taken off).</summary>
    /// <exception cref="ArgumentException">As <see cref="DoMotion"/>.</exception>
    public MotionError StopMotion(uint motion, in MotionParameters parameters, MoverDescription mover, ref MoverState state, ref BodyState body) =>
        Command(stop: true, motion, parameters, mover, ref state, ref body);

    // A raw command through CPhysicsObj::DoMotion / StopMotion (which mark the movement autonomous) and
    // CMotionInterp::PerformMovement (which completes the motions that need no animation).
    private MotionError Command(bool stop, uint motion, in MotionParameters parameters, MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckCommand(motion, nameof(motion));
        CheckParameters(parameters);
        CheckBody(body);
        Load(mover, state, body);
        _interp.Autonomous = true;
        var result = stop ? _interp.StopMotion(motion, parameters) : _interp.DoMotion(motion, parameters);
        _manager.CheckForCompletedMotions();
        Store(ref state, ref body);
        return result;
    }

    /// <summary>CMotionInterp::StopCompletely: Ready, no sidestep, no turn.</summary>
    public MotionError StopCompletely(MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckBody(body);
        Load(mover, state, body);
        var result = _interp.StopCompletely();
        _manager.CheckForCompletedMotions();
        Store(ref state, ref body);
        return result;
    }

    /// <summary>CMotionInterp::SetHoldKey: makes None or Run the current hold key and re-applies the movement (retail handles both; ACE only None).</summary>
    /// <exception cref="ArgumentException">A key other than None or Run.</exception>
    public void SetHoldKey(HoldKey key, MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (key is not (HoldKey.None or HoldKey.Run))
            throw new ArgumentException($"key: must be None or Run, got {key}.", nameof(key));
        CheckBody(body);
        Load(mover, state, body);
        _interp.SetHoldKey(key);
        _manager.CheckForCompletedMotions();
        Store(ref state, ref body);
    }

    /// <summary>CMotionInterp::charge_jump: starts charging a jump (refused while falling or sitting).</summary>
    public MotionError ChargeJump(MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckBody(body);
        Load(mover, state, body);
        return _interp.ChargeJump();
    }

    /// <summary>
    /// CMotionInterp::jump: when retail's jump_is_allowed holds (on walkable ground, a motion that allows it,
    /// the stamina), the body leaves the ground: <paramref name="state"/> is no longer on walkable ground and
    /// <paramref name="body"/>'s velocity is get_leave_ground_velocity (the state velocity with get_jump_v_z).
    /// </summary>
    /// <param name="extent">How far the jump was charged, 0 to 1 (more is capped at 1 by get_jump_v_z).</param>
    /// <param name="staminaOk">The owner has the stamina for it (retail's JumpStaminaCost check).</param>
    /// <param name="mover">The mover.</param>
    /// <param name="state">Its state; changed only when the jump is taken.</param>
    /// <param name="body">Its body; changed only when the jump is taken.</param>
    /// <exception cref="ArgumentException">A non-finite or negative extent; nothing is changed.</exception>
    public MotionError Jump(float extent, bool staminaOk, MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (!(extent >= 0f) || !float.IsFinite(extent))
            throw new ArgumentException($"extent: must be a finite number, 0 or more, got {extent}.", nameof(extent));
        CheckBody(body);
        Load(mover, state, body);
        var result = _interp.Jump(extent, staminaOk);
        _manager.CheckForCompletedMotions();
        if (result == MotionError.None)
            Store(ref state, ref body);
        return result;
    }

    // ---- the snapshot's view (Snapshots/MotionSection) ----

    internal MotionInterpreter Interpreter => _interp;
    internal MotionTableManager Manager => _manager;
    internal Sequence AnimationSequence => _sequence;

    // ---- the body step's hooks ----

    internal void Load(MoverDescription mover, in MoverState state, in BodyState body)
    {
        _interp.Body = new InterpreterBody
        {
            Gravity = (mover.PhysicsState & PhysicsState.Gravity) != 0,
            Contact = state.Contact,
            OnWalkable = state.OnWalkable,
            Orientation = state.Position.Frame.Orientation,
            Velocity = body.Velocity,
        };
    }

    internal void Store(ref MoverState state, ref BodyState body)
    {
        state.OnWalkable = _interp.Body.OnWalkable;
        body.Velocity = _interp.Body.Velocity;
    }

    /// <summary>CPartArray::Update then process_hooks: the sequence's offset for one quantum; ended links complete their motions.</summary>
    internal void Advance(float quantum, ref Frame offset)
    {
        int done = _sequence.Update(quantum, ref offset);
        for (int i = 0; i < done; i++)
            _manager.AnimationDone(true);
    }

    /// <summary>SetPositionInternal's set_on_walkable (and its LeaveGround when contact is lost): the velocity in and out.</summary>
    internal Vector3 SetOnWalkable(bool onWalkable, Quaternion orientation, bool contact, Vector3 velocity)
    {
        _interp.Body.Orientation = orientation;
        _interp.Body.Contact = contact;
        _interp.Body.Velocity = velocity;
        if (!_interp.Body.OnWalkable && onWalkable)
            _landed = true; // MovementManager::HitGround also tells the MoveToManager (ObjectMotion.MoveTo.cs)
        _interp.SetOnWalkable(onWalkable);
        return _interp.Body.Velocity;
    }

    /// <summary>CPartArray::HandleMovement: motions that needed no animation complete.</summary>
    internal void HandleMovement() => _manager.CheckForCompletedMotions();

    // ---- checks ----

    private void CheckCommand(uint motion, string field)
    {
        if (motion is MotionCommand.WalkBackwards or MotionCommand.TurnLeft or MotionCommand.SideStepLeft || Table.Knows(motion))
            return;
        throw new ArgumentException($"{field}: command 0x{motion:X8} is not in motion table 0x{Table.Id:X8} (no style, cycle, modifier or link for it) and is not one the interpreter maps.", field);
    }

    private static void CheckParameters(in MotionParameters p)
    {
        if (!float.IsFinite(p.Speed) || MathF.Abs(p.Speed) > 100f)
            throw new ArgumentException($"parameters.Speed: must be finite and within ±100, got {p.Speed}.", "parameters");
        if (p.HoldKey is not (HoldKey.Invalid or HoldKey.None or HoldKey.Run))
            throw new ArgumentException($"parameters.HoldKey: must be Invalid, None or Run, got {p.HoldKey}.", "parameters");
    }

    private static void CheckBody(in BodyState body) => BodyGuard.Velocity(body.Velocity, "body.velocity", nameof(body));
}
