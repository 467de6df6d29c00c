using System;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// The facade a game client or server calls once per frame per mover: a requested target in, the
/// resolved position and contact state out, exactly as the retail transition resolves it.
/// One engine per thread: it reuses one <see cref="Transition"/> and allocates nothing per call once warm.
/// The world may be shared by engines on several threads while nobody modifies it.
/// </summary>
public sealed partial class PhysicsEngine
{
    private readonly Transition _transition;
    private RefusalMemo _lastRefusal;
    // Transitions accepted since a body step began (BodyStepResult.Transitions).
    private int _acceptedTransitions;

    /// <summary>Creates an engine over a world.</summary>
    public PhysicsEngine(PhysicsWorld world) => _transition = new Transition(world);

    /// <summary>Creates an engine taking <paramref name="shortcuts"/> (<see cref="Shortcuts.None"/>: retail's path step for step).</summary>
    internal PhysicsEngine(PhysicsWorld world, Shortcuts shortcuts) => _transition = new Transition(world, shortcuts);

    /// <summary>The world.</summary>
    public PhysicsWorld World => _transition.World;

    /// <summary>The engine's reusable transition, for the component benchmarks.</summary>
    internal Transition Transition => _transition;

    /// <summary>Sub-step length in sphere radii: 1 (default) is retail; see <see cref="Transition.SubStepScale"/>.</summary>
    internal float SubStepScale
    {
        get => _transition.SubStepScale;
        set
        {
            _transition.SubStepScale = value;
            _lastRefusal.Clear();
        }
    }

    /// <summary>Structured diagnostics; null (default) costs nothing.</summary>
    public ITransitionObserver? Observer
    {
        get => _transition.Observer;
        set => _transition.Observer = value;
    }

    /// <summary>
    /// Moves a mover from <paramref name="state"/>'s position towards <paramref name="target"/> (a position
    /// in the same or a neighbouring landblock's frame, labelled with the start cell or any cell of the
    /// target's landblock). Throws <see cref="ArgumentException"/> naming the field, before anything is
    /// changed, for non-finite or out-of-range input (coordinates beyond ±<see cref="InputLimits.MaxCoordinate"/>),
    /// zero-length rotations or rotations whose length overflows, a contact plane whose normal is not a unit
    /// vector, unknown cells (the state's cell, the target's cell label and a non-zero contact-plane cell
    /// must all be in the world), and a state whose origin lies more than
    /// <see cref="InputLimits.MaxDistanceFromCell"/> plus the mover's reach outside its cell.
    /// A grounded mover with <see cref="PhysicsState.EdgeSlide"/> (the retail player, <see cref="MoverDescription.Player"/>)
    /// is not moved over a drop deeper than its step-down height: it slides along the edge or stops at it
    /// (retail CTransition::edge_slide); without the flag it is moved out over the drop, out of contact
    /// (<see cref="MoverDescription.With"/> makes the copy without it).
    /// A motion cut into more than <see cref="PhysicsConstants.MaxSubSteps"/> sub-steps (kilometres in one
    /// frame) is not an error: as in retail it is refused at once, with <see cref="MoveResult.Succeeded"/>
    /// false and <see cref="MoveResult.Next"/> equal to <paramref name="state"/>.
    /// Thread safety: one engine per thread; engines on several threads may share a world as long as
    /// nothing registers, moves or unregisters objects or adds cells meanwhile.
    /// </summary>
    public MoveResult Resolve(MoverDescription mover, in MoverState state, Position target)
    {
        ArgumentNullException.ThrowIfNull(mover);
        return ResolveCore(mover, state, target, 0, trusted: false);
    }

    /// <summary>
    /// <see cref="Resolve"/> with the transition's stationary-fall counter seeded, as retail's
    /// CPhysicsObj::transition seeds it from the object's transient state (0 for a mover without a body).
    /// <paramref name="trusted"/>: the state is one a body step has validated (<see cref="ValidateState"/>, once per
    /// step) or one the engine's own transition produced since, and the target's cell is the state's; then the
    /// state is not checked again (the checks could only pass: an accepted transition leaves the mover in a loaded
    /// cell that holds it — check_other_cells, AdjustToOutside — with a contact plane and sliding normal it
    /// computed), only its cell is looked up. The poses are still checked, because checking normalizes: a
    /// caller's rotation retail would not accept is normalized here in the first quantum, as before.
    /// </summary>
    private MoveResult ResolveCore(MoverDescription mover, in MoverState state, Position target, int framesStationaryFall, bool trusted)
    {
        // The result is built in one place, straight into the caller's copy: one result built on each way
        // out is copied whole into a shared one, reading back what was just written a field at a time.
        bool ok = Move(mover, state, target, framesStationaryFall, trusted, out bool refused);
        return new MoveResult(_transition, ok, refused, state);
    }

    /// <summary>
    /// The work of <see cref="ResolveCore"/>: checks the request and runs the transition; true when it was
    /// accepted. <paramref name="refused"/>: the move was refused before its first sub-step and the
    /// transition was left as it was.
    /// </summary>
    private bool Move(MoverDescription mover, in MoverState state, Position target, int framesStationaryFall, bool trusted, out bool refused)
    {
        refused = true;
        if (_lastRefusal.Matches(mover, state, target, _transition.World.Cells.RemovalCount))
            return false;
        // The start position is read where it lies, copied only when its rotation must be normalized: a
        // copy is written a field at a time and the path reads it whole soon after, which waits for the
        // stores to land.
        scoped ref readonly Position begin = ref state.Position;
        Position normalized;
        if (!Guard.PoseAsGiven(state.Position.Frame, "state.position"))
        {
            normalized = state.Position;
            Guard.Pose(ref normalized.Frame, "state.position");
            begin = ref normalized;
        }
        Guard.Pose(ref target.Frame, "target");
        var cell = trusted ? _transition.World.Cells.Get(begin.CellId)! : ValidateState(mover, state, begin, target.CellId);

        var t = _transition;
        if (t.RefusesBeforeFirstStep(mover, state, begin, target, out var plan))
        {
            // Shortcut RefusalMemo: see RefusalMemo's header (off: nothing is remembered, nothing matches).
            if ((t.Shortcuts & Shortcuts.RefusalMemo) != 0)
                _lastRefusal.Remember(mover, state, target, _transition.World.Cells.RemovalCount);
            return false;
        }
        refused = false;
        Prepare(t, mover, state);
        t.SpherePath.InitSphere(mover);
        t.SpherePath.InitPath(cell, in begin, in target);
        t.CollisionInfo.FramesStationaryFall = framesStationaryFall;
        // Shortcut StepPlan: see StepPlan's header (off: the step count is worked out again from the path).
        bool ok = (t.Shortcuts & Shortcuts.StepPlan) != 0 ? t.FindTransitionalPosition(in plan) : t.FindTransitionalPosition();
        if (ok) _acceptedTransitions++;
        return ok;
    }

    /// <summary>
    /// Checks a mover's state (its pose already checked into <paramref name="begin"/>: cell, distance from
    /// it, contact plane, sliding normal) and that <paramref name="targetCellId"/> is loaded; returns the
    /// state's cell. The cell ids are usually one and the same: each distinct id is looked up once.
    /// </summary>
    internal World.Cell ValidateState(MoverDescription mover, in MoverState state, in Position begin, uint targetCellId)
    {
        var cells = _transition.World.Cells;
        // GetRequired only to throw its error: the lookup alone inlines.
        var cell = cells.Get(begin.CellId) ?? cells.GetRequired(begin.CellId, "state.position.cell");
        Guard.NearCell(cell.DistanceOutside(begin.Frame.Origin), mover.Reach, begin.CellId, begin.Frame.Origin, "state.position.origin");
        if (targetCellId != begin.CellId && cells.Get(targetCellId) is null)
            cells.GetRequired(targetCellId, "target.cell");
        if (state.Contact || state.ContactPlaneCellId != 0)
        {
            Guard.UnitNormal(state.ContactPlane.Normal, "state.contactPlane.normal");
            Guard.Coordinate(state.ContactPlane.D, "state.contactPlane.d");
            uint planeCell = state.ContactPlaneCellId;
            if (planeCell != 0 && planeCell != begin.CellId && planeCell != targetCellId && cells.Get(planeCell) is null)
                cells.GetRequired(planeCell, "state.contactPlaneCellId");
        }
        if (state.SlidingNormalValid)
            Guard.Finite(state.SlidingNormal, "state.slidingNormal");
        return cell;
    }

    /// <summary>
    /// Places a mover into the world at <paramref name="position"/> the retail way (an initial placement):
    /// pushed out of cell geometry, moved to the nearest free spot within 4 m when an object is in the way,
    /// and settled onto the ground below when it is close. Not succeeded when no spot was found.
    /// </summary>
    public MoveResult Place(MoverDescription mover, Position position)
    {
        ArgumentNullException.ThrowIfNull(mover);
        Guard.Pose(ref position.Frame, "position");
        var cell = _transition.World.Cells.GetRequired(position.CellId, "position.cell");
        Guard.NearCell(cell.DistanceOutside(position.Frame.Origin), mover.Reach, position.CellId, position.Frame.Origin, "position.origin");
        var t = _transition;
        var airborne = MoverState.Airborne(position);
        Prepare(t, mover, airborne);
        t.SpherePath.InitSphere(mover);
        t.SpherePath.InitPath(cell, null, position);
        bool ok = t.FindPlacementPosition();
        return Collect(t, ok, airborne);
    }

    internal static void Prepare(Transition t, MoverDescription mover, in MoverState state)
    {
        t.SpherePath.Reset();
        t.CollisionInfo.Reset();
        var info = t.ObjectInfo;
        info.ObjectId = mover.ObjectId;
        info.PhysicsState = mover.PhysicsState;
        info.State = mover.Flags;
        if ((mover.PhysicsState & PhysicsState.EdgeSlide) != 0)
            info.State |= ObjectInfoState.EdgeSlide;
        if ((mover.PhysicsState & PhysicsState.Missile) != 0)
            info.State |= ObjectInfoState.PathClipped; // CPhysicsObj::get_object_info: MISSILE_PS → PATH_CLIPPED
        info.Scale = mover.Scale;
        info.StepUpHeight = mover.StepUpHeight * mover.Scale;
        info.StepDownHeight = mover.StepDownHeight * mover.Scale;
        info.Ethereal = (mover.PhysicsState & PhysicsState.Ethereal) != 0;
        info.StepDown = (mover.PhysicsState & PhysicsState.Missile) == 0;
        info.TargetId = mover.TargetId;
        if (state.Contact)
        {
            t.InitContactPlane(state.ContactPlaneCellId, state.ContactPlane, state.ContactPlaneIsWater);
            info.State |= ObjectInfoState.Contact;
            if (state.OnWalkable)
                info.State |= ObjectInfoState.OnWalkable;
        }
        else if (state.ContactPlaneCellId != 0)
        {
            t.InitLastKnownContactPlane(state.ContactPlaneCellId, state.ContactPlane, state.ContactPlaneIsWater);
        }
        if (state.SlidingNormalValid)
            t.InitSlidingNormal(state.SlidingNormal);
        if (state.Ground != GroundKind.None)
            t.InitGround(state.Ground, state.GroundObjectId);
    }

    internal static MoveResult Collect(Transition t, bool ok, in MoverState previous) => new(t, ok, refused: false, previous);
}
