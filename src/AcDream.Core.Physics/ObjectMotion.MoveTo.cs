using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

// The MoveTo side of the motion layer (retail MovementManager's MoveToManager): start, target updates, cancel, status.
public sealed partial class ObjectMotion
{
    private MoveToManager? _moveTo;

    /// <summary>The manager itself (null before the first MoveTo), for tests that read retail's fields.</summary>
    internal MoveToManager? MoveToManagerState => _moveTo;
    private bool _landed;
    private float _radius, _height;

    private MoveToManager MoveTo => _moveTo ??= new MoveToManager(_interp, _manager); // MovementManager::MakeMoveToManager

    /// <summary>
    /// The object's cylinder for the MoveTo distances (retail CPhysicsObj::GetRadius / GetHeight: the setup's radius and
    /// height × scale; the retail player's are 0.48 and 1.835 m). 0 until set.
    /// </summary>
    /// <exception cref="ArgumentException">A negative or non-finite value, named.</exception>
    public void SetCylinder(float radius, float height)
    {
        if (!(radius >= 0f && radius <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"radius: must be finite, 0 to {InputLimits.MaxCoordinate}, got {radius}.", nameof(radius));
        if (!(height >= 0f && height <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"height: must be finite, 0 to {InputLimits.MaxCoordinate}, got {height}.", nameof(height));
        _radius = radius;
        _height = height;
    }

    /// <summary>
    /// What a move does when its progress check fails: the 2013 client's <see cref="MoveToProgressRule.CountOnly"/>
    /// (default: count the failures, keep moving) or the opt-in server rule <see cref="MoveToProgressRule.GiveUp"/>
    /// (end with CantGetThere after a further second of failed checks). Kept for every later move of this object.
    /// </summary>
    public MoveToProgressRule MoveToProgressRule
    {
        get => _moveTo?.ProgressRule ?? MoveToProgressRule.CountOnly;
        set
        {
            if (value is not (MoveToProgressRule.GiveUp or MoveToProgressRule.CountOnly))
                throw new ArgumentException($"value: unknown progress rule {value}.", nameof(value));
            MoveTo.ProgressRule = value;
        }
    }

    /// <summary>Where the last MoveTo or turn stands.</summary>
    public MoveToStatus MoveToStatus => _moveTo?.Status ?? MoveToStatus.Idle;

    /// <summary>How the last MoveTo or turn ended (<see cref="MoveToError.None"/> while one is in progress or none ended).</summary>
    public MoveToError MoveToResult => _moveTo is { Status: MoveToStatus.Ended } m ? m.Result : MoveToError.None;

    /// <summary>The kind of move in progress (<see cref="MoveToKind.Invalid"/> when none).</summary>
    public MoveToKind MoveToKind => _moveTo?.MovementType ?? MoveToKind.Invalid;

    /// <summary>Retail's fail_progress_count: failed progress checks in a row (counted, never read, by the 2013 client).</summary>
    public int MoveToFailProgressCount => _moveTo?.FailProgressCount ?? 0;

    /// <summary>The turn and move nodes left (0 when none).</summary>
    public int MoveToNodeCount => _moveTo?.NodeCount ?? 0;

    /// <summary>The motion command the move is giving (WalkForward, WalkBackwards, TurnRight, TurnLeft; 0 when none).</summary>
    public uint MoveToCommand => _moveTo?.CurrentCommand ?? 0;

    /// <summary>The aim correction turn while moving (TurnRight or TurnLeft, 0 when none).</summary>
    public uint MoveToAuxCommand => _moveTo?.AuxCommand ?? 0;

    /// <summary>
    /// The object a move with <see cref="MoveToFlags.Sticky"/> asked to stick to on arrival, 0 when none; cleared by the
    /// next MoveTo. The arrival sticks the object to it at once (<see cref="PositionManager"/>'s StickTo, as retail's
    /// BeginNextNode does); the caller then reports the target's positions there.
    /// </summary>
    public uint StickOnArrival => _moveTo?.StickTarget ?? 0;

    /// <summary>
    /// MoveToManager::MoveToPosition (through PerformMovement, which cancels a move in progress with
    /// <see cref="MoveToError.ActionCancelled"/>): stop, turn towards <paramref name="target"/>, then walk or run to
    /// it; the body step works the nodes (<see cref="MoveToStatus"/>, <see cref="MoveToResult"/>).
    /// </summary>
    /// <exception cref="ArgumentException">A target outside the world or not finite, or parameters out of range, named; nothing is changed.</exception>
    public void MoveToPosition(in Position target, in MoveToParameters parameters, MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckTarget(target, nameof(target));
        parameters.Check(nameof(parameters));
        var view = Prepare(mover, state, body);
        PositionManager.UnStick(); // PerformMovement: CancelMoveTo, then unstick_from_object
        MoveTo.MoveToPosition(ref view, target, parameters);
        HandOffStick();
    }

    /// <summary>
    /// MoveToManager::MoveToObject: move to the object <paramref name="objectId"/> (a cylinder of
    /// <paramref name="radius"/> and <paramref name="height"/>), whose positions arrive through
    /// <see cref="UpdateMoveToTarget(uint, in Position, MoverDescription, in MoverState, in BodyState)"/> (retail's TargetManager voyeur updates); nothing moves before the first.
    /// The object itself as target ends the move at once with <see cref="MoveToError.None"/> (retail cleans up).
    /// </summary>
    /// <exception cref="ArgumentException">A negative or non-finite radius or height, or parameters out of range, named.</exception>
    public void MoveToObject(uint objectId, float radius, float height, in MoveToParameters parameters, MoverDescription mover, in MoverState state,
        in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (!(radius >= 0f && radius <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"radius: must be finite, 0 to {InputLimits.MaxCoordinate}, got {radius}.", nameof(radius));
        if (!(height >= 0f && height <= InputLimits.MaxCoordinate))
            throw new ArgumentException($"height: must be finite, 0 to {InputLimits.MaxCoordinate}, got {height}.", nameof(height));
        parameters.Check(nameof(parameters));
        var view = Prepare(mover, state, body);
        PositionManager.UnStick(); // PerformMovement: CancelMoveTo, then unstick_from_object
        MoveTo.MoveToObject(ref view, objectId, objectId, radius, height, parameters);
        HandOffStick();
    }

    /// <summary>MoveToManager::TurnToHeading: turn the short way to <see cref="MoveToParameters.DesiredHeading"/>, then snap to it exactly.</summary>
    /// <exception cref="ArgumentException">Parameters out of range, named.</exception>
    public void TurnToHeading(in MoveToParameters parameters, MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        parameters.Check(nameof(parameters));
        var view = Prepare(mover, state, body);
        PositionManager.UnStick(); // PerformMovement: CancelMoveTo, then unstick_from_object
        MoveTo.TurnToHeading(ref view, parameters);
        HandOffStick();
    }

    /// <summary>
    /// MoveToManager::TurnToObject: turn to face <paramref name="objectId"/> once its position arrives through
    /// <see cref="UpdateMoveToTarget(uint, in Position, MoverDescription, in MoverState, in BodyState)"/>. Retail quirk kept: the turn faces the object exactly; the parameters'
    /// desired heading is stored where TurnToObject_Internal does not read it.
    /// </summary>
    /// <exception cref="ArgumentException">Parameters out of range, named.</exception>
    public void TurnToObject(uint objectId, in MoveToParameters parameters, MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        parameters.Check(nameof(parameters));
        var view = Prepare(mover, state, body);
        PositionManager.UnStick(); // PerformMovement: CancelMoveTo, then unstick_from_object
        MoveTo.TurnToObject(ref view, objectId, objectId, parameters);
        HandOffStick();
    }

    /// <summary>
    /// MoveToManager::HandleUpdateTarget: the sought object's newest position. The first starts the move; later ones
    /// re-aim it and restart the progress samples (as retail). Each update replaces the last (no queue: a flood costs
    /// nothing more); the order is the caller's, as retail's TargetManager delivers them. One position serves as both of
    /// retail's (the target's own and the interpolated one; see the overload that takes both).
    /// </summary>
    /// <returns>False when no move is waiting on <paramref name="objectId"/> (ignored, as retail).</returns>
    /// <exception cref="ArgumentException">A position outside the world or not finite, named; nothing is changed.</exception>
    public bool UpdateMoveToTarget(uint objectId, in Position position, MoverDescription mover, in MoverState state, in BodyState body) =>
        UpdateMoveToTarget(objectId, position, position, mover, state, body);

    /// <summary>
    /// MoveToManager::HandleUpdateTarget with both positions of retail's TargetInfo: <paramref name="position"/> (the
    /// target's own, which the move steers at and measures its distance to) and <paramref name="interpolatedPosition"/>
    /// (where the target manager expects it a quantum later: the move's sought position, towards which the first
    /// update's turn is aimed).
    /// </summary>
    /// <returns>False when no move is waiting on <paramref name="objectId"/> (ignored, as retail).</returns>
    /// <exception cref="ArgumentException">A position outside the world or not finite, named; nothing is changed.</exception>
    public bool UpdateMoveToTarget(uint objectId, in Position position, in Position interpolatedPosition, MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        CheckTarget(position, nameof(position));
        CheckTarget(interpolatedPosition, nameof(interpolatedPosition));
        if (_moveTo is null)
            return false;
        var view = Prepare(mover, state, body);
        bool waiting = _moveTo.UpdateTarget(ref view, objectId, position, interpolatedPosition, present: true, out _);
        HandOffStick();
        return waiting;
    }

    /// <summary>
    /// HandleUpdateTarget with the object gone (unknown, unloaded or destroyed): the move ends with
    /// <see cref="MoveToError.NoObject"/> before it started, <see cref="MoveToError.ObjectGone"/> after.
    /// </summary>
    /// <returns>False when no move is waiting on <paramref name="objectId"/>.</returns>
    public bool MoveToTargetGone(uint objectId, MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (_moveTo is null)
            return false;
        var view = Prepare(mover, state, body);
        return _moveTo.UpdateTarget(ref view, objectId, default, default, present: false, out _);
    }

    /// <summary>MoveToManager::CancelMoveTo: ends a move in progress with <see cref="MoveToError.ActionCancelled"/> and stops the object; nothing when none.</summary>
    public void CancelMoveTo(MoverDescription mover, in MoverState state, in BodyState body)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if (_moveTo is null)
            return;
        var view = Prepare(mover, state, body);
        _moveTo.Cancel(ref view, MoveToError.ActionCancelled);
    }

    private MoveToBody Prepare(MoverDescription mover, in MoverState state, in BodyState body)
    {
        CheckBody(body);
        Load(mover, state, body);
        return View(mover, state);
    }

    private MoveToBody View(MoverDescription mover, in MoverState state) => new()
    {
        Position = state.Position,
        Contact = state.Contact,
        Interpolating = PositionManager.IsInterpolating,
        Id = mover.ObjectId,
        Radius = _radius,
        Height = _height,
    };

    // The origin first: a NaN or far-off origin has no cell of its own (a caller's LandCellAt gives 0), and the
    // message must name what is wrong, not the cell that follows from it.
    private static void CheckTarget(in Position p, string field)
    {
        Guard.Finite(p.Frame.Origin, field, ".origin");
        Guard.CellInWorld(p.CellId, field);
    }

    /// <summary>
    /// The body step's hook after a quantum's transition (MovementManager::UseTime → MoveToManager::UseTime; a landing
    /// first restarts the head node, MovementManager::HitGround): the clock advances by the quantum; a move's handler
    /// may give motion commands and snap the heading (copied into <paramref name="state"/>).
    /// </summary>
    internal void UseMoveTo(MoverDescription mover, ref MoverState state, in BodyState body, float quantum)
    {
        bool landed = _landed;
        _landed = false;
        if (_moveTo is null)
            return;
        _moveTo.Now += quantum;
        if (!_moveTo.Active)
            return;
        Load(mover, state, body);
        var view = View(mover, state);
        bool turned = landed && _moveTo.HitGround(ref view);
        turned |= _moveTo.UseTime(ref view);
        if (turned)
            state.Position.Frame.Orientation = view.Position.Frame.Orientation;
        HandOffStick();
    }

    // MoveToManager::BeginNextNode's arrival with the Sticky flag calls PositionManager::StickTo(top_level_object_id,
    // radius, height) itself (CMoveToManager.c, acclient.c:345559); the manager leaves the request for its owner.
    private void HandOffStick()
    {
        if (_moveTo is not { StickPending: true } m)
            return;
        m.StickPending = false;
        PositionManager.StickToChecked(m.StickTarget, m.StickRadius);
    }

    // CPhysicsObj::cancel_moveto, called when a stick ends (PositionManager).
    internal void CancelMoveToForStick() => _moveTo?.CancelFromStick();
}
