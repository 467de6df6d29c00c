using System;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail's MoveToManager (acclient-src PORTAL/canim/CMoveToManager.c, acclient.c:344714-346150): moves a creature to a
/// position or an object, or turns it to a heading or an object, by giving its motion interpreter walk, run and turn
/// commands. Retail has no path finding: a list of nodes (turn to the heading of the target, then move straight at
/// it, then optionally turn to a final heading) is worked through, the move re-aiming with an auxiliary turn when the
/// heading is off by more than 20°, arriving within the distance to the object, and measuring its progress
/// (CheckProgressMade). One instance per object, owned by <see cref="ObjectMotion"/>; the body step calls
/// <see cref="UseTime"/> after each quantum's transition (MovementManager::UseTime). No allocation once built.
/// </summary>
internal sealed class MoveToManager
{
    // ---- retail constants (CMoveToManager.c) ----

    /// <summary>CheckProgressMade (acclient.c:344832): progress is judged over windows longer than 1 s…</summary>
    internal const double ProgressWindow = 1.0;
    /// <summary>…and fails below 0.25 m/s, both since the last sample and since the move began.</summary>
    internal const double MinProgressSpeed = 0.25;
    /// <summary>HandleMoveToPosition (acclient.c:345576): an aim error above 20° (either way) turns while moving.</summary>
    internal const double AimTolerance = 20.0;

    private const int NodeMove = 7, NodeTurn = 9; // the node types (movement types MoveToPosition, TurnToHeading)
    private const int MaxNodes = 4;               // retail builds at most turn, move, final turn

    private struct Node
    {
        public int Type;
        public float Heading;
    }

    private readonly MotionInterpreter _interp;
    private readonly MotionTableManager _table;
    private readonly Node[] _nodes = new Node[MaxNodes];
    private int _head, _count;

    // The retail fields (MoveToManager, acclient.c:344912 InitializeLocalVariables).
    public MoveToKind MovementType;
    public MoveToParameters Params;
    public Position SoughtPosition, CurrentTargetPosition, StartingPosition;
    public float PreviousHeading, PreviousDistance, OriginalDistance;
    public double PreviousDistanceTime, OriginalDistanceTime;
    public int FailProgressCount;
    /// <summary>When the current run of failed progress checks began (the give-up rule's clock).</summary>
    public double FailingSince;
    public uint SoughtObjectId, TopLevelObjectId;
    public float SoughtObjectRadius, SoughtObjectHeight;
    public uint CurrentCommand, AuxCommand;
    public bool MovingAway, Initialized;

    /// <summary>Timer::cur_time: the object's own clock, seconds, advanced by each quantum.</summary>
    public double Now;

    /// <summary>What the last move ended with, and whether it has ended since it started.</summary>
    public MoveToError Result;
    public MoveToStatus Status;
    /// <summary>CountOnly (0, the default) is retail's client; GiveUp is the opt-in server cancel (MoveToProgressRule).</summary>
    public MoveToProgressRule ProgressRule;
    /// <summary>The object an arrival with <see cref="MoveToFlags.Sticky"/> asked to stick to (PositionManager::StickTo), 0 when none.</summary>
    public uint StickTarget;
    public float StickRadius, StickHeight;
    /// <summary>An arrival has asked to stick and the owner has not yet passed it to PositionManager::StickTo.</summary>
    public bool StickPending;

    // The body of the call in progress.
    private MoveToBody _body;
    private bool _headingChanged;

    public MoveToManager(MotionInterpreter interp, MotionTableManager table)
    {
        _interp = interp;
        _table = table;
        Params = MoveToParameters.Default;
        InitializeLocalVariables();
    }

    /// <summary>A move or turn is in progress (is_moving_to).</summary>
    public bool Active => MovementType != MoveToKind.Invalid;

    /// <summary>The nodes left (type 7 = move, 9 = turn), for tests and snapshots.</summary>
    internal int NodeCount => _count;
    internal (int Type, float Heading) NodeAt(int i) => (_nodes[_head + i].Type, _nodes[_head + i].Heading);

    // ---- the calls, each with the object's body: returns whether the heading was set ----

    /// <summary>PerformMovement → MoveToPosition (acclient.c:346118, 345789).</summary>
    public bool MoveToPosition(ref MoveToBody body, in Position target, in MoveToParameters p)
    {
        Begin(ref body);
        PerformMovement();
        StopCompletely();
        CurrentTargetPosition = target;
        SoughtObjectRadius = 0f;
        // Retail measures this with the parameters left by InitializeLocalVariables (bitfield 0: the origins' distance).
        float distance = CurrentDistance();
        var me = _body.Position;
        float toTarget = Headings.Towards(me, target);
        p.GetCommand(distance, out uint command, out _, out _);
        if (command != 0)
        {
            AddNode(NodeTurn, toTarget);
            AddNode(NodeMove, 0f);
        }
        if (p.Has(MoveToFlags.UseFinalHeading))
            AddNode(NodeTurn, p.DesiredHeading);
        SoughtPosition = target;
        StartingPosition = me;
        MovementType = MoveToKind.MoveToPosition;
        Params = p with { Flags = p.Flags & ~MoveToFlags.Sticky };
        Status = MoveToStatus.Moving;
        BeginNextNode();
        return End(ref body);
    }

    /// <summary>PerformMovement → MoveToObject (acclient.c:345183): waits for the first target update unless the object is itself.</summary>
    public bool MoveToObject(ref MoveToBody body, uint objectId, uint topLevelId, float radius, float height, in MoveToParameters p)
    {
        Begin(ref body);
        PerformMovement();
        StopCompletely();
        StartingPosition = _body.Position;
        SoughtObjectId = objectId;
        SoughtObjectRadius = radius;
        SoughtObjectHeight = height;
        MovementType = MoveToKind.MoveToObject;
        TopLevelObjectId = topLevelId;
        Params = p;
        Initialized = false;
        Status = MoveToStatus.WaitingForTarget;
        if (topLevelId == _body.Id)
            SelfTarget();
        return End(ref body);
    }

    /// <summary>PerformMovement → TurnToObject (acclient.c:345241).</summary>
    public bool TurnToObject(ref MoveToBody body, uint objectId, uint topLevelId, in MoveToParameters p)
    {
        Begin(ref body);
        PerformMovement();
        if (p.Has(MoveToFlags.StopCompletely))
            StopCompletely();
        MovementType = MoveToKind.TurnToObject;
        SoughtObjectId = objectId;
        // Retail keeps the relative heading in the target frame's heading; TurnToObject_Internal adds it.
        CurrentTargetPosition.Frame.Orientation = Headings.Facing(p.DesiredHeading);
        TopLevelObjectId = topLevelId;
        Params = p;
        Status = MoveToStatus.WaitingForTarget;
        if (topLevelId != _body.Id)
            Initialized = false;
        else
            SelfTarget();
        return End(ref body);
    }

    /// <summary>PerformMovement → TurnToHeading (acclient.c:345953): the turn node, begun at once.</summary>
    public bool TurnToHeading(ref MoveToBody body, in MoveToParameters p)
    {
        Begin(ref body);
        PerformMovement();
        if (p.Has(MoveToFlags.StopCompletely))
            StopCompletely();
        Params = p with { Flags = p.Flags & ~MoveToFlags.Sticky };
        SoughtPosition.Frame.Orientation = Headings.Facing(p.DesiredHeading);
        MovementType = MoveToKind.TurnToHeading;
        AddNode(NodeTurn, p.DesiredHeading);
        Status = MoveToStatus.Moving;
        BeginNextNode();
        return End(ref body);
    }

    /// <summary>
    /// HandleUpdateTarget (acclient.c:346050): the sought object's position (<paramref name="present"/> false: it is gone).
    /// Returns false when the update is for another object (ignored, as retail).
    /// </summary>
    public bool UpdateTarget(ref MoveToBody body, uint objectId, in Position target, in Position interpolated, bool present, out bool headingChanged)
    {
        headingChanged = false;
        if (TopLevelObjectId != objectId || !Active)
            return false;
        Begin(ref body);
        if (Initialized)
        {
            if (present)
            {
                if (MovementType == MoveToKind.MoveToObject)
                {
                    // Retail keeps both (acclient.c:346050): the sought position is the update's interpolated one, the
                    // position steered at and measured to (GetCurrentDistance, HandleMoveToPosition) the target's own.
                    SoughtPosition = interpolated;
                    CurrentTargetPosition = target;
                    // Retail restarts both progress samples (float.MaxValue, acclient.c:346050): the next check only
                    // takes a sample, and the average test passes until the next BeginMoveForward.
                    PreviousDistance = float.MaxValue;
                    PreviousDistanceTime = Now;
                    OriginalDistance = float.MaxValue;
                    OriginalDistanceTime = Now;
                }
            }
            else
            {
                CancelMoveTo(MoveToError.ObjectGone);
            }
        }
        else if (present)
        {
            if (MovementType == MoveToKind.MoveToObject)
                MoveToObjectInternal(target, interpolated);
            else if (MovementType == MoveToKind.TurnToObject)
                TurnToObjectInternal(target);
        }
        else
        {
            CancelMoveTo(MoveToError.NoObject);
        }
        headingChanged = End(ref body);
        return true;
    }

    /// <summary>CancelMoveTo (acclient.c:345296): drops the nodes, stops the commands and the object.</summary>
    public void Cancel(ref MoveToBody body, MoveToError error)
    {
        Begin(ref body);
        CancelMoveTo(error);
        End(ref body);
    }

    /// <summary>
    /// CPhysicsObj::cancel_moveto from the sticky manager (a stick ended): MovementManager::CancelMoveTo(0x36). The
    /// cancel only stops the move's motions and clears its fields, so it reads no body view.
    /// </summary>
    public void CancelFromStick() => CancelMoveTo(MoveToError.ActionCancelled);

    /// <summary>
    /// UseTime (acclient.c:346017), after a quantum's transition: with contact, and once the target is known, the head
    /// node's handler runs. Returns whether it set the heading (the caller copies <paramref name="body"/>'s orientation).
    /// </summary>
    public bool UseTime(ref MoveToBody body)
    {
        if (_count == 0 || !body.Contact)
            return false;
        if (TopLevelObjectId != 0 && MovementType != MoveToKind.Invalid && !Initialized)
            return false;
        Begin(ref body);
        if (_nodes[_head].Type == NodeMove)
            HandleMoveToPosition();
        else
            HandleTurnToHeading();
        return End(ref body);
    }

    /// <summary>HitGround (acclient.c:345569): landing restarts the head node.</summary>
    public bool HitGround(ref MoveToBody body)
    {
        if (!Active)
            return false;
        Begin(ref body);
        BeginNextNode();
        return End(ref body);
    }

    // PerformMovement (acclient.c:346118): a new move cancels the one in progress (ActionCancelled) and starts from a
    // clean slate (its unstick_from_object is the owner's: ObjectMotion unsticks before each start).
    private void PerformMovement()
    {
        CancelMoveTo(MoveToError.ActionCancelled);
        StickTarget = 0;
        StickPending = false;
    }

    private void Begin(ref MoveToBody body)
    {
        _body = body;
        _headingChanged = false;
    }

    private bool End(ref MoveToBody body)
    {
        body = _body;
        return _headingChanged;
    }

    // ---- retail's internals ----

    private void InitializeLocalVariables()
    {
        MovementType = MoveToKind.Invalid;
        Params = Params with { Flags = MoveToFlags.None };
        PreviousDistance = float.MaxValue;
        PreviousDistanceTime = Now;
        OriginalDistance = float.MaxValue;
        OriginalDistanceTime = Now;
        PreviousHeading = 0f;
        FailProgressCount = 0;
        CurrentCommand = 0;
        AuxCommand = 0;
        MovingAway = false;
        Initialized = false;
        SoughtPosition = default;
        CurrentTargetPosition = default;
        SoughtObjectId = 0;
        TopLevelObjectId = 0;
        SoughtObjectRadius = 0f;
        SoughtObjectHeight = 0f;
    }

    private void AddNode(int type, float heading)
    {
        if (_count == MaxNodes)
            throw new InvalidOperationException("MoveToManager: more than four nodes (retail builds at most three).");
        if (_head + _count == MaxNodes)
        {
            Array.Copy(_nodes, _head, _nodes, 0, _count);
            _head = 0;
        }
        _nodes[_head + _count++] = new Node { Type = type, Heading = heading };
    }

    private void RemoveHead()
    {
        if (_count == 0)
            return;
        _head++;
        if (--_count == 0)
            _head = 0;
    }

    private void ClearNodes()
    {
        _head = 0;
        _count = 0;
    }

    private void MoveToObjectInternal(in Position target, in Position interpolated)
    {
        // MoveToObject_Internal (acclient.c:345858): the same nodes as MoveToPosition, the first turn towards the
        // interpolated position (the sought one), the distance to the target's own (current_target_position).
        SoughtPosition = interpolated;
        CurrentTargetPosition = target;
        float toTarget = Headings.Towards(_body.Position, interpolated);
        float distance = CurrentDistance();
        Params.GetCommand(distance, out uint command, out _, out _);
        if (command != 0)
        {
            AddNode(NodeTurn, toTarget);
            AddNode(NodeMove, 0f);
        }
        if (Params.Has(MoveToFlags.UseFinalHeading))
        {
            float final = toTarget + Params.DesiredHeading;
            if (final >= 360f)
                final -= 360f;
            AddNode(NodeTurn, final);
        }
        Initialized = true;
        Status = MoveToStatus.Moving;
        BeginNextNode();
    }

    private void TurnToObjectInternal(in Position target)
    {
        // TurnToObject_Internal (acclient.c:345910): the heading towards the object plus the relative heading kept.
        CurrentTargetPosition.CellId = target.CellId;
        CurrentTargetPosition.Frame = target.Frame;
        float relative = Headings.Of(SoughtPosition.Frame);
        float heading = (float)(((double)Headings.Towards(_body.Position, CurrentTargetPosition) + relative) % 360.0);
        SoughtPosition.Frame.Orientation = Headings.Facing(heading);
        AddNode(NodeTurn, heading);
        Initialized = true;
        Status = MoveToStatus.Moving;
        BeginNextNode();
    }

    // The object is its own target: retail cleans up at once (MoveToObject/TurnToObject) and reports success
    // (HandleUpdateTarget's CleanUpAndCallWeenie(0)); nothing moves.
    private void SelfTarget()
    {
        SoughtPosition = _body.Position;
        CurrentTargetPosition = _body.Position;
        CleanUp();
        StopCompletely();
        EndWith(MoveToError.None);
    }

    /// <summary>GetCurrentDistance (acclient.c:344855): between the cylinders with UseSpheres, else between the origins.</summary>
    private float CurrentDistance() =>
        Params.Has(MoveToFlags.UseSpheres)
            ? Headings.CylinderDistance(_body.Radius, _body.Height, _body.Position, SoughtObjectRadius, SoughtObjectHeight, CurrentTargetPosition)
            : Headings.Distance(_body.Position, CurrentTargetPosition);

    private void BeginNextNode()
    {
        // BeginNextNode (acclient.c:345520).
        if (_count > 0)
        {
            if (_nodes[_head].Type == NodeMove)
                BeginMoveForward();
            else
                BeginTurnToHeading();
            return;
        }
        bool sticky = Params.Has(MoveToFlags.Sticky);
        uint stickTo = TopLevelObjectId;
        float radius = SoughtObjectRadius, height = SoughtObjectHeight;
        CleanUp();
        StopCompletely();
        if (sticky)
        {
            // PositionManager::StickTo(top_level_object_id, radius, height): handed to the owner.
            StickTarget = stickTo;
            StickRadius = radius;
            StickHeight = height;
            StickPending = true;
        }
        EndWith(MoveToError.None);
    }

    private void BeginMoveForward()
    {
        // BeginMoveForward (acclient.c:345370).
        float distance = CurrentDistance();
        float heading = AngleFrom(Headings.Towards(_body.Position, CurrentTargetPosition) - (double)Headings.Of(_body.Position.Frame));
        Params.GetCommand(distance, out uint motion, out var key, out bool away);
        _ = heading; // get_command takes the heading but does not read it (acclient.c:346174)
        if (motion == 0)
        {
            RemoveHead();
            BeginNextNode();
            return;
        }
        var error = DoMotion(motion, Params.Speed, key);
        if (error != MotionError.None)
        {
            CancelMoveTo((MoveToError)error);
            return;
        }
        CurrentCommand = motion;
        MovingAway = away;
        Params = Params with { HoldKey = key };
        PreviousDistance = distance;
        PreviousDistanceTime = Now;
        OriginalDistance = distance;
        OriginalDistanceTime = Now;
    }

    private void BeginTurnToHeading()
    {
        // BeginTurnToHeading (acclient.c:345455): turn the short way; nothing to do within EPSILON.
        if (MotionsPending())
            return;
        float target = _nodes[_head].Heading;
        double diff = Headings.Diff(target, Headings.Of(_body.Position.Frame), MotionCommand.TurnRight);
        uint turn;
        if (diff <= 180.0)
        {
            if (!(diff > PhysicsConstants.Epsilon))
            {
                RemoveHead();
                BeginNextNode();
                return;
            }
            turn = MotionCommand.TurnRight;
        }
        else
        {
            if (diff + PhysicsConstants.Epsilon >= 360.0)
            {
                RemoveHead();
                BeginNextNode();
                return;
            }
            turn = MotionCommand.TurnLeft;
        }
        var error = DoMotion(turn, Params.Speed, Params.HoldKey);
        if (error != MotionError.None)
        {
            CancelMoveTo((MoveToError)error);
            return;
        }
        CurrentCommand = turn;
        // Retail quirk: the heading difference, not the heading, is kept (acclient.c:345455), so the first
        // HandleTurnToHeading may count one failed check.
        PreviousHeading = (float)diff;
    }

    private void HandleMoveToPosition()
    {
        // HandleMoveToPosition (acclient.c:345576).
        if (MotionsPending())
        {
            if (AuxCommand != 0)
            {
                StopMotion(AuxCommand, Params.Speed);
                AuxCommand = 0;
            }
        }
        else
        {
            double wanted = (double)Headings.Towards(_body.Position, CurrentTargetPosition)
                + MoveToParameters.DesiredHeadingOffset(CurrentCommand, MovingAway);
            float aim = (float)wanted;
            if (aim >= 360f)
                aim -= 360f;
            double error = AngleFrom(aim - (double)Headings.Of(_body.Position.Frame));
            if (error <= AimTolerance || error >= 360.0 - AimTolerance)
            {
                if (AuxCommand != 0)
                {
                    StopMotion(AuxCommand, Params.Speed);
                    AuxCommand = 0;
                }
            }
            else
            {
                uint turn = error >= 180.0 ? MotionCommand.TurnLeft : MotionCommand.TurnRight;
                if (turn != AuxCommand)
                {
                    DoMotion(turn, Params.Speed, Params.HoldKey);
                    AuxCommand = turn;
                }
            }
        }

        float distance = CurrentDistance();
        if (!CheckProgressMade(distance))
        {
            // Counted only while nothing else moves the object (acclient.c:345659: !IsInterpolating && !motions_pending).
            if (Stalled())
            {
                if (FailProgressCount++ == 0)
                    FailingSince = Now;
                // Retail's client only counts (CountOnly, the default). The opt-in GiveUp rule stands for the server's
                // cancel of a creature that makes no progress: the checks have kept failing for a further whole window
                // (no progress for more than 2 s in all), not a passing dip such as a creature turning about to move away.
                if (ProgressRule == MoveToProgressRule.GiveUp && Now - FailingSince > ProgressWindow)
                    CancelMoveTo(MoveToError.CantGetThere);
            }
            return;
        }
        FailProgressCount = 0;
        bool arrived = MovingAway ? distance >= Params.MinDistance : distance <= Params.DistanceToObject;
        if (arrived)
        {
            RemoveHead();
            StopMotion(CurrentCommand, Params.Speed);
            CurrentCommand = 0;
            if (AuxCommand != 0)
            {
                StopMotion(AuxCommand, Params.Speed);
                AuxCommand = 0;
            }
            BeginNextNode();
            return;
        }
        if (Headings.Distance(StartingPosition, _body.Position) > Params.FailDistance)
            CancelMoveTo(MoveToError.YouChargedTooFar);
    }

    private void HandleTurnToHeading()
    {
        // HandleTurnToHeading (acclient.c:345711).
        if (CurrentCommand is not (MotionCommand.TurnRight or MotionCommand.TurnLeft))
        {
            BeginTurnToHeading();
            return;
        }
        float heading = Headings.Of(_body.Position.Frame);
        float target = _nodes[_head].Heading;
        if (Headings.Greater(heading, target, CurrentCommand))
        {
            // Past it: snap to the heading exactly (set_heading), then the next node.
            FailProgressCount = 0;
            _body.Position.Frame.Orientation = Headings.Facing(target);
            _headingChanged = true;
            RemoveHead();
            StopMotion(CurrentCommand, 1f);
            CurrentCommand = 0;
            BeginNextNode();
            return;
        }
        double turned = Headings.Diff(heading, PreviousHeading, CurrentCommand);
        PreviousHeading = heading;
        if (turned >= 180.0 || turned <= PhysicsConstants.Epsilon)
        {
            // HandleTurnToHeading (acclient.c:345711): the same condition as the move's.
            if (Stalled())
                FailProgressCount++;
        }
        else
        {
            FailProgressCount = 0;
        }
    }

    /// <summary>
    /// CheckProgressMade (acclient.c:344832): true until more than <see cref="ProgressWindow"/> has passed since the last
    /// sample; then false when the distance closed (or opened, moving away) slower than <see cref="MinProgressSpeed"/> since
    /// that sample (the sample is then kept), or, after a new sample is taken, slower than that since the move began.
    /// </summary>
    internal bool CheckProgressMade(float distance)
    {
        double elapsed = Now - PreviousDistanceTime;
        if (!(elapsed > ProgressWindow))
            return true;
        double progress = MovingAway ? (double)distance - PreviousDistance : (double)PreviousDistance - distance;
        if (progress / elapsed < MinProgressSpeed)
            return false;
        PreviousDistance = distance;
        PreviousDistanceTime = Now;
        double overall = MovingAway ? (double)distance - OriginalDistance : (double)OriginalDistance - distance;
        return !(overall / (Now - OriginalDistanceTime) < MinProgressSpeed);
    }

    private void CancelMoveTo(MoveToError error)
    {
        // CancelMoveTo (acclient.c:345296): only while a move is on.
        if (MovementType == MoveToKind.Invalid)
            return;
        ClearNodes();
        CleanUp();
        StopCompletely();
        EndWith(error);
    }

    private void CleanUp()
    {
        // CleanUp (acclient.c:345142): the commands stopped with the move's hold key, then the fields reset.
        if (CurrentCommand != 0)
            StopMotion(CurrentCommand, 1f);
        if (AuxCommand != 0)
            StopMotion(AuxCommand, 1f);
        InitializeLocalVariables();
    }

    private void EndWith(MoveToError error)
    {
        ClearNodes();
        Result = error;
        Status = MoveToStatus.Ended;
    }

    // heading − current heading in [0, 360), zero within EPSILON (BeginMoveForward, HandleMoveToPosition).
    private static float AngleFrom(double d)
    {
        if (Math.Abs(d) < PhysicsConstants.Epsilon)
            d = 0.0;
        if (d < -PhysicsConstants.Epsilon)
            d += 360.0;
        return (float)d;
    }

    // ---- the motion interpreter (MoveToManager::_DoMotion / _StopMotion, acclient.c:344752, 344792) ----

    private MotionError DoMotion(uint motion, float speed, HoldKey key)
    {
        _interp.AdjustMotion(ref motion, ref speed, key);
        return _interp.DoInterpretedMotion(motion, Parameters(speed, key));
    }

    private void StopMotion(uint motion, float speed)
    {
        var key = Params.HoldKey;
        _interp.AdjustMotion(ref motion, ref speed, key);
        _interp.StopInterpretedMotion(motion, Parameters(speed, key));
    }

    // A default MovementParameters with CancelMoveTo cleared, the speed and the hold key (retail's local params).
    private static MotionParameters Parameters(float speed, HoldKey key) =>
        new(speed, key, SetHoldKey: true, ModifyRawState: true, ModifyInterpretedState: true, DisableJumpDuringLink: false);

    private void StopCompletely()
    {
        // CPhysicsObj::StopCompletely(0) → CMotionInterp::StopCompletely; the motions that need no animation complete.
        _interp.StopCompletely();
        _table.CheckForCompletedMotions();
    }

    // CPhysicsObj::motions_pending (the interpreter's queue).
    private bool MotionsPending() => _interp.PendingCount > 0;

    // A failed progress check counts only when neither the interpolation nor pending motions move the object.
    private bool Stalled() => !_body.Interpolating && !MotionsPending();
}
