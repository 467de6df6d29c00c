using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// The position managers of one player or creature (retail PositionManager, CPositionManager.c): smoothing
/// towards the positions a server reports (<see cref="InterpolateTo"/>, retail InterpolationManager), sticking to
/// a target in melee (<see cref="StickTo"/>, StickyManager) and a leash (<see cref="ConstrainTo"/>,
/// ConstraintManager). It belongs to the object's <see cref="ObjectMotion"/> (<see cref="ObjectMotion.PositionManager"/>);
/// each manager is created on its first use, as retail's PositionManager creates them.
/// <para>
/// Each quantum of <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, ObjectMotion, double)"/>
/// the animation's offset passes through the managers in retail's order (adjust_offset: interpolation, then
/// sticky, then the leash) before the physics and the transition, so a smoothed or stuck object moves through
/// the transition like any other and never passes through a wall; after the quantum, UseTime runs (the
/// interpolation's blip, the sticky timeout).
/// </para>
/// <para>
/// There is no object manager: where retail looks the target up (GetObjectA, TargetManager voyeur updates), the
/// caller reports the target with <see cref="UpdateTarget"/> (each frame it moves, and right after
/// <see cref="StickTo"/>, as retail's set_target sends the first update at once) and <see cref="LoseTarget"/>.
/// Not thread-safe; no allocation once each manager exists.
/// </para>
/// </summary>
public sealed class PositionManager
{
    private readonly MotionInterpreter _interp;
    private readonly ObjectMotion _owner;
    private InterpolationManager? _interpolation;
    private StickyManager? _sticky;
    private ConstraintManager? _constraint;

    internal PositionManager(MotionInterpreter interp, ObjectMotion owner)
    {
        _interp = interp;
        _owner = owner;
    }

    /// <summary>
    /// The managers' clock, seconds: the sum of the quanta stepped (retail reads Timer::cur_time; only the
    /// sticky timeout uses it).
    /// </summary>
    public double Clock { get; private set; }

    /// <summary>
    /// The object is the client's own player (retail CPhysicsObj::player_object): indoors its autonomy blip
    /// distance is 25 m instead of 20 m. False by default.
    /// </summary>
    public bool IsPlayerObject { get; set; }

    // ---- interpolation ----

    /// <summary>
    /// CPhysicsObj::InterpolateTo: queues a position reported for the object (retail InterpolationManager::InterpolateTo).
    /// A position within 0.05 m of the last one queued replaces it; with 20 queued the oldest is dropped. A position
    /// within 0.05 m of the object ends the smoothing (and turns the object to the position's heading unless
    /// <paramref name="keepHeading"/>). A position farther than the autonomy blip distance from the last one
    /// queued (100 m outdoors; indoors 25 m for the player, 20 m for others) teleports the object there at the
    /// next step. Updates are queued in the order given: retail checks the update's timestamps before this call
    /// (CPhysicsObj::MoveOrTeleport), so discarding a stale update is the caller's.
    /// </summary>
    /// <param name="position">The reported position (its cell need not be loaded until the object gets there).</param>
    /// <param name="keepHeading">Keep the object's heading (retail passes IsMovingTo: an object running a MoveTo turns by itself).</param>
    /// <param name="mover">The object.</param>
    /// <param name="state">Its state; only its heading changes, and only in the case above.</param>
    /// <exception cref="ArgumentException">A non-finite or out-of-range position, or a cell id outside the retail world, named in the message; nothing is changed.</exception>
    public void InterpolateTo(in Position position, bool keepHeading, MoverDescription mover, ref MoverState state)
    {
        ArgumentNullException.ThrowIfNull(mover);
        var p = CheckedPosition(position, nameof(position));
        _interpolation ??= new InterpolationManager();
        if (_interpolation.InterpolateTo(p, keepHeading, View(mover, state), out float heading))
            state.Position.Frame.Orientation = Headings.Facing(heading);
    }

    /// <summary>CPhysicsObj::StopInterpolating: the queue is emptied and the progress state reset.</summary>
    public void StopInterpolating() => _interpolation?.StopInterpolating();

    /// <summary>PositionManager::IsInterpolating: positions are queued.</summary>
    public bool IsInterpolating => _interpolation is { Count: > 0 };

    /// <summary>The number of positions queued (at most 20).</summary>
    public int QueuedPositions => _interpolation?.Count ?? 0;

    /// <summary>A queued position, the head (the one being approached) first.</summary>
    public Position QueuedPosition(int index) =>
        (uint)index < (uint)QueuedPositions ? _interpolation!.Node(index) : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>The nodes that failed their progress check since the smoothing started (node_fail_counter); more than 3 blip the object.</summary>
    public int FailedNodes => _interpolation?.NodeFailCounter ?? 0;

    // ---- sticky ----

    /// <summary>
    /// CPhysicsObj::stick_to_object / PositionManager::StickTo: keeps the object 0.3 m from the target's cylinder and
    /// facing it, from the target's first <see cref="UpdateTarget"/> on, for 1 s of <see cref="Clock"/>. A running
    /// stick ends first (and, as every end of a stick in retail, cancels the object's MoveTo if one is on: the 1 s
    /// timeout, <see cref="LoseTarget"/> and <see cref="UnStick"/> do too). Retail sets the timeout only here
    /// (StickyManager::StickTo): target updates do not extend it, and sticking again restarts it. A MoveTo with
    /// <see cref="MoveToFlags.Sticky"/> sticks here itself on arrival.
    /// </summary>
    /// <param name="targetId">The target's object id, not 0 and not the object's own.</param>
    /// <param name="targetRadius">The target's radius, m (retail: its part array's radius).</param>
    /// <param name="targetHeight">The target's height, m (retail passes it and does not use it).</param>
    /// <param name="mover">The object.</param>
    /// <exception cref="ArgumentException">Target 0 or the object itself, or a radius or height not finite, negative or too large; nothing is changed.</exception>
    public void StickTo(uint targetId, float targetRadius, float targetHeight, MoverDescription mover)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (targetId == 0)
            throw new ArgumentException("targetId: 0 is no object.", nameof(targetId));
        if (targetId == mover.ObjectId)
            throw new ArgumentException($"targetId: 0x{targetId:X8} is the object itself.", nameof(targetId));
        Guard.Extent(targetRadius, true, nameof(targetRadius));
        Guard.Extent(targetHeight, true, nameof(targetHeight));
        StickToChecked(targetId, targetRadius);
    }

    // PositionManager::StickTo after the checks; also MoveToManager::BeginNextNode's arrival with the Sticky flag.
    internal void StickToChecked(uint targetId, float targetRadius)
    {
        _sticky ??= new StickyManager();
        if (_sticky.StickTo(targetId, targetRadius, Clock))
            StickEnded();
    }

    /// <summary>
    /// CPhysicsObj::unstick_from_object (PositionManager::UnStick → StickyManager::HandleExitWorld): ends the stick,
    /// and a running stick's end cancels the object's MoveTo (<see cref="MoveToError.ActionCancelled"/>), as every
    /// end of a stick does in retail.
    /// </summary>
    public void UnStick()
    {
        if (_sticky is not null && _sticky.End())
            StickEnded();
    }

    // Every end of a running stick in retail (StickTo over a stick, HandleUpdateTarget with another status than Ok,
    // UseTime's timeout, HandleExitWorld) calls clear_target and then CPhysicsObj::cancel_moveto
    // (CStickyManager.c:388501-388710): the object's MoveTo, if one is on, ends with ActionCancelled (0x36).
    private void StickEnded() => _owner.CancelMoveToForStick();

    /// <summary>The target stuck to, 0 when none (PositionManager::GetStickyObjectID).</summary>
    public uint StickyTargetId => _sticky?.TargetId ?? 0;

    /// <summary>The stuck target's position is known (StickyManager's initialized): the stick moves the object.</summary>
    public bool StickyTargetKnown => _sticky is { Initialized: true };

    /// <summary>When the stick ends, on <see cref="Clock"/> (sticky_timeout_time); meaningless without a stick.</summary>
    public double StickyTimeout => _sticky?.TimeoutTime ?? 0;

    /// <summary>
    /// A target update with status Ok (retail TargetManager → CPhysicsObj::HandleUpdateTarget → StickyManager):
    /// where the target is now. Updates for another object than the one stuck to are ignored, as in retail.
    /// </summary>
    /// <exception cref="ArgumentException">A non-finite or out-of-range position or a cell outside the world; nothing is changed.</exception>
    public void UpdateTarget(uint targetId, in Position position)
    {
        var p = CheckedPosition(position, nameof(position));
        if (_sticky is not null && _sticky.HandleUpdateTarget(targetId, TargetStatus.Ok, p))
            StickEnded();
    }

    /// <summary>
    /// A target update with another status than Ok (the target left the world, teleported, timed out …): the stick to
    /// it ends, and with it the object's MoveTo if one is on (retail's cancel_moveto, <see cref="MoveToError.ActionCancelled"/>).
    /// </summary>
    /// <exception cref="ArgumentException">Status Ok (use <see cref="UpdateTarget"/>) or not a defined status.</exception>
    public void LoseTarget(uint targetId, TargetStatus status)
    {
        if (status == TargetStatus.Ok || !Enum.IsDefined(status))
            throw new ArgumentException($"status: must be a defined status other than Ok, got {status}.", nameof(status));
        if (_sticky is not null && _sticky.HandleUpdateTarget(targetId, status, default))
            StickEnded();
    }

    // ---- constraint ----

    /// <summary>
    /// CPhysicsObj::ConstrainTo: a leash from <paramref name="position"/>: past <paramref name="startDistance"/> the
    /// object's offsets shrink linearly, at <paramref name="maxDistance"/> they stop (while it touches the ground).
    /// Retail measures the distance at this call plus the length of every offset since (a path length).
    /// </summary>
    /// <exception cref="ArgumentException">A bad position, a distance not finite, negative or too large, or a max distance not above the start; nothing is changed.</exception>
    public void ConstrainTo(in Position position, float startDistance, float maxDistance, in MoverState state)
    {
        var p = CheckedPosition(position, nameof(position));
        Guard.Extent(startDistance, true, nameof(startDistance));
        Guard.Extent(maxDistance, true, nameof(maxDistance));
        if (!(maxDistance > startDistance))
            throw new ArgumentException($"maxDistance: must be greater than startDistance ({startDistance}), got {maxDistance}.", nameof(maxDistance));
        _constraint ??= new ConstraintManager();
        _constraint.ConstrainTo(p, startDistance, maxDistance, state.Position);
    }

    /// <summary>CPhysicsObj::UnConstrain: the leash is let go.</summary>
    public void UnConstrain() => _constraint?.UnConstrain();

    /// <summary>A leash is on.</summary>
    public bool IsConstrained => _constraint is { IsConstrained: true };

    /// <summary>PositionManager::IsFullyConstrained: more than 90 % of the leash's max distance is used.</summary>
    public bool IsFullyConstrained => _constraint is { } c && c.IsFullyConstrained;

    /// <summary>The leash's distance counted so far, m (constraint_pos_offset).</summary>
    public float ConstraintDistance => _constraint?.Offset ?? 0f;

    // ---- the body step's hooks ----

    internal StickyManager? Sticky => _sticky;

    /// <summary>PositionManager::adjust_offset: interpolation, then sticky, then the leash, on one offset.</summary>
    internal void AdjustOffset(ref Frame offset, float quantum, MoverDescription mover, in MoverState state)
    {
        if (_interpolation is null && _sticky is null && _constraint is null)
            return;
        var view = View(mover, state);
        _interpolation?.AdjustOffset(ref offset, quantum, view, StickyTargetId != 0);
        _sticky?.AdjustOffset(ref offset, quantum, view);
        _constraint?.AdjustOffset(ref offset, state.Contact);
    }

    /// <summary>
    /// PositionManager::UseTime: the clock advances by the quantum, the sticky timeout is checked, and the
    /// interpolation says whether the object must be blipped and where (the caller places it and then calls
    /// <see cref="StopInterpolating"/>).
    /// </summary>
    internal bool UseTime(float quantum, out Position blipTarget)
    {
        Clock += quantum;
        blipTarget = default;
        bool blip = _interpolation is not null && _interpolation.BlipTarget(out blipTarget);
        if (_sticky is not null && _sticky.UseTime(Clock))
            StickEnded();
        return blip;
    }

    internal ObjectView View(MoverDescription mover, in MoverState state) =>
        new(state.Position, state.Contact, Radius(mover), _interp.MaxSpeed(), AdjustedMaxSpeed(_interp), IsPlayerObject);

    /// <summary>
    /// CMotionInterp::get_adjusted_max_speed (CMotionInterp.c:236): 4 m/s × the run rate, or × the forward speed
    /// while running forward (current_speed_factor, which retail leaves at 1).
    /// </summary>
    internal static float AdjustedMaxSpeed(MotionInterpreter interp)
    {
        double rate = interp.RunRate();
        if (interp.Interpreted.ForwardCommand == MotionCommand.RunForward)
            rate = interp.Interpreted.ForwardSpeed;
        return (float)(rate * MotionInterpreter.RunAnimSpeed);
    }

    // CPhysicsObj::GetRadius is the setup's radius × scale; the largest sphere stands for it (the retail player's are equal).
    private static float Radius(MoverDescription mover)
    {
        float r = 0f;
        foreach (var s in mover.Spheres)
            r = MathF.Max(r, s.Radius);
        return r * mover.Scale;
    }

    // The field is always "position" (a constant: the check allocates nothing).
    private static Position CheckedPosition(in Position position, string field)
    {
        var p = position;
        Guard.CellInWorld(p.CellId, "position.cell");
        Guard.Pose(ref p.Frame, field);
        Guard.Coordinate(p.Frame.Origin.X, field, ".origin.x");
        Guard.Coordinate(p.Frame.Origin.Y, field, ".origin.y");
        Guard.Coordinate(p.Frame.Origin.Z, field, ".origin.z");
        return p;
    }
}
