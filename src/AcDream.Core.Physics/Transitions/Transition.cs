using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// One move of one mover through the world (retail CTransition): the mover (<see cref="ObjectInfo"/>),
/// its path (<see cref="SpherePath"/>) and what it touched (<see cref="CollisionInfo"/>). Reusable: a
/// transition allocates nothing after its first use. Not thread-safe: use one per thread.
/// The work is split by concern over partial files: sub-stepping and validation here, insertion into
/// cells in Transition.Insert.cs, stepping in Transition.Steps.cs, edge handling in Transition.Edges.cs.
/// </summary>
internal sealed partial class Transition
{
    /// <summary>The mover.</summary>
    public readonly ObjectInfo ObjectInfo = new();
    /// <summary>The path.</summary>
    public readonly SpherePath SpherePath;
    /// <summary>The contacts.</summary>
    public readonly CollisionInfo CollisionInfo;
    /// <summary>Which objects of each cell the check spheres can reach (shortcut <see cref="Shortcuts.ObjectCull"/>).</summary>
    internal readonly ObjectCull Cull = new();
    /// <summary>The cells the check position touches.</summary>
    public readonly CellArray CellArray = new();
    /// <summary>The non-retail shortcuts this transition takes (see <see cref="Physics.Shortcuts"/>); fixed at construction.</summary>
    internal readonly Shortcuts Shortcuts;

    /// <summary>Creates a transition over a world, taking the default shortcuts (<see cref="ShortcutSettings.Default"/>).</summary>
    public Transition(PhysicsWorld world) : this(world, ShortcutSettings.Default) { }

    /// <summary>Creates a transition over a world, taking <paramref name="shortcuts"/> (none: retail's path step for step).</summary>
    internal Transition(PhysicsWorld world, Shortcuts shortcuts)
    {
        World = world ?? throw new ArgumentNullException(nameof(world));
        Shortcuts = shortcuts;
        SpherePath = new SpherePath(shortcuts);
        CollisionInfo = new CollisionInfo(shortcuts);
        _interpolation = new RotationInterpolationMemo(shortcuts);
        _slideLine = UnitMemo.For(shortcuts);
    }

    /// <summary>The world collided with.</summary>
    public PhysicsWorld World { get; }

    /// <summary>Diagnostics sink; null (the default) costs nothing.</summary>
    public ITransitionObserver? Observer { get; set; }

    /// <summary>
    /// The sub-step length in units of sphere 0's radius. 1 (the default) is retail; other values are
    /// offered for speed/accuracy studies and are not retail behaviour.
    /// </summary>
    public float SubStepScale
    {
        get => _subStepScale;
        set
        {
            if (!(value > 0f) || !float.IsFinite(value))
                throw new ArgumentException($"SubStepScale: must be a finite number greater than zero, got {value}.", nameof(value));
            _subStepScale = value;
        }
    }

    private float _subStepScale = 1f;
    private readonly RotationInterpolationMemo _interpolation;
    // The last line along a sliding normal and the contact plane (adjust_offset's slide), normalized.
    private UnitMemo _slideLine;

    /// <summary>Retail's step-count rule, exposed for tests and tools.</summary>
    /// <param name="offset">The whole motion.</param>
    /// <param name="radius">The radius of sphere 0.</param>
    /// <param name="isViewer">The camera's arm differs.</param>
    /// <param name="offsetPerStep">The motion of one sub-step.</param>
    /// <returns>The number of sub-steps.</returns>
    public static int CalcNumSteps(Vector3 offset, float radius, bool isViewer, out Vector3 offsetPerStep)
    {
        // Retail (CTransition::calc_num_steps, acclient.c:311763) measures the motion, divides it by the
        // radius and scales the per-step offset on the x87 stack at double precision, rounding each
        // per-step component once.
        double squared = VectorMath.LengthSquaredWide(offset);
        if (!isViewer)
        {
            // A motion no longer than the radius is one step, known without the square root and division:
            // the radius squared is exact in double, so squared <= radius² gives dist <= |radius| after the
            // correctly rounded root, and then dist / radius <= 1 (or NaN for a zero radius, or negative):
            // "step > 1" fails exactly when retail's does.
            double walk = squared <= (double)radius * radius ? 0.0 : Math.Sqrt(squared) / radius;
            if (walk > 1.0)
            {
                double n = Math.Ceiling(walk);
                offsetPerStep = VectorMath.Scale(offset, 1.0 / n);
                return n > int.MaxValue ? int.MaxValue : (int)n;
            }
            offsetPerStep = offset;
            return offset != Vector3.Zero ? 1 : 0;
        }
        double dist = Math.Sqrt(squared);
        double step = dist / radius;
        if (dist <= PhysicsConstants.Epsilon)
        {
            offsetPerStep = Vector3.Zero;
            return 0;
        }
        offsetPerStep = VectorMath.Scale(offset, 1.0 / step);
        double floor = Math.Floor(step) + 1;
        return floor > int.MaxValue ? int.MaxValue : (int)floor;
    }

    /// <summary>
    /// Retail find_transitional_position: walks the path from the current position to the end in
    /// sub-steps, inserting each into the world and keeping what the collisions allow. True when the last
    /// step was accepted.
    /// </summary>
    public bool FindTransitionalPosition()
    {
        var path = SpherePath;
        if (path.BeginCell is null)
            return false;
        var plan = new StepPlan { NumSteps = 1 };
        if (path.HasBeginPos)
        {
            plan.Offset = path.BeginPos.GetOffset(path.EndPos);
            plan.NumSteps = CalcNumSteps(plan.Offset, path.LocalSphere[0].Radius * _subStepScale, IsViewer, out plan.PerStep);
        }
        return FindTransitionalPosition(in plan);
    }

    /// <summary>
    /// <see cref="FindTransitionalPosition()"/> with the step count (and perhaps the first sub-step's
    /// constrained motion) already worked out from this path's begin and end positions, sphere and
    /// carried contact state.
    /// </summary>
    internal bool FindTransitionalPosition(in StepPlan plan)
    {
        var path = SpherePath;
        _aloneCell = null;
        if (path.BeginCell is null)
            return false;
        var state = TransitionState.OK;
        Vector3 offset = plan.Offset, perStep = plan.PerStep;
        int numSteps = plan.NumSteps;
        if (numSteps > PhysicsConstants.MaxSubSteps)
            return false;
        bool freeRotate = (ObjectInfo.State & ObjectInfoState.FreeRotate) != 0;
        if (freeRotate)
            path.CurPos.Frame.Orientation = path.EndPos.Frame.Orientation;
        path.SetCheckPos(path.CurPos, path.CurCell);

        if (numSteps <= 0)
        {
            if (!freeRotate)
                path.CurPos.Frame.Orientation = path.EndPos.Frame.Orientation;
            path.SetCheckPos(path.CurPos, path.CurCell);
            path.CellArrayValid = true;
            path.HitsInteriorCell = false;
            BuildCellArray(findContaining: false);
            return true;
        }

        // The camera arm passes over the leading sub-steps it proves touch nothing (Transition.ViewerSkip.cs).
        int first = IsViewer ? PassClearViewerSteps(in plan) : 0;
        for (int step = first; step < numSteps; step++)
        {
            if (IsViewer && step == numSteps - 1)
            {
                // The camera's last step covers exactly what is left of the motion.
                double length = Math.Sqrt((double)offset.Z * offset.Z + (double)offset.Y * offset.Y + (double)offset.X * offset.X);
                if (length > PhysicsConstants.Epsilon)
                    perStep = VectorMath.Scale(offset, (length - (double)(path.LocalSphere[0].Radius * _subStepScale) * (numSteps - 1)) / length);
            }
            if (step == 0 && plan.FirstKnown)
            {
                CollisionInfo.SlidingNormalValid = plan.FirstSlidingNormalValid;
                path.GlobalOffset = LiftOntoContactPlane(plan.FirstOffset);
            }
            else
            {
                path.GlobalOffset = AdjustOffset(perStep);
            }
            if (!IsViewer && VectorMath.Dot(path.GlobalOffset, path.GlobalOffset) < PhysicsConstants.Epsilon * PhysicsConstants.Epsilon)
                return step != 0 && state == TransitionState.OK;
            if (!freeRotate && _interpolation.Between(path.BeginPos.Frame, path.EndPos.Frame, (float)(step + 1) / numSteps, out var turned))
                path.CheckPos.Frame.Orientation = turned;

            CollisionInfo.SlidingNormalValid = false;
            CollisionInfo.ClearContactPlane();
            Observer?.OnSubStep(step, path.CheckPos.Origin, path.GlobalOffset);

            if (path.InsertType != InsertType.Transition)
            {
                state = ValidatePlacementTransition(TransitionalInsert(3));
                if (state == TransitionState.OK)
                    return true;
                if (!path.PlacementAllowsSliding)
                    return false;
                path.AddOffsetToCheckPos(path.GlobalOffset);
            }
            else
            {
                path.AddOffsetToCheckPos(path.GlobalOffset);
                state = ValidateTransition(TransitionalInsert(3));
                if (CollisionInfo.FramesStationaryFall > 0)
                    break;
            }
            if (CollisionInfo.CollisionNormalValid && (ObjectInfo.State & ObjectInfoState.PathClipped) != 0)
                break;
        }
        return state == TransitionState.OK;
    }

    private bool IsViewer => (ObjectInfo.State & ObjectInfoState.IsViewer) != 0;

    /// <summary>
    /// Retail adjust_offset: constrains a sub-step's motion by the sliding normal and the contact plane
    /// (<see cref="ConstrainOffset"/>), and lifts the check position back onto the contact plane when it has
    /// sunk into it.
    /// </summary>
    public Vector3 AdjustOffset(Vector3 offset)
    {
        var ci = CollisionInfo;
        return LiftOntoContactPlane(ConstrainOffset(offset, ref ci.SlidingNormalValid, ci.SlidingNormal, ci.ContactPlaneValid, ci.ContactPlane, ref _slideLine));
    }

    /// <summary>
    /// The second half of retail adjust_offset: lifts the check position back onto the contact plane when
    /// it has sunk into it; returns the (constrained) offset unchanged.
    /// </summary>
    private Vector3 LiftOntoContactPlane(Vector3 offset)
    {
        var ci = CollisionInfo;
        if (!ci.ContactPlaneValid || ci.ContactPlaneCellId == 0 || ci.ContactPlaneIsWater)
            return offset;
        var sphere = SpherePath.GlobalSphere[0];
        var blockOffset = LandDefs.BlockOffset(SpherePath.CheckPos.CellId, ci.ContactPlaneCellId);
        float dist = VectorMath.Distance(ci.ContactPlane, sphere.Center - blockOffset);
        if (dist >= sphere.Radius - PhysicsConstants.Epsilon)
            return offset;
        float lift = (sphere.Radius - dist) / ci.ContactPlane.Normal.Z;
        if (sphere.Radius > MathF.Abs(lift))
            SpherePath.AddOffsetToCheckPos(new Vector3(0, 0, lift));
        return offset;
    }

    /// <summary>
    /// The first half of retail adjust_offset, which depends on nothing but its arguments: a motion into a
    /// valid sliding normal slides along it (along the line where it meets the contact plane, when there is
    /// one); otherwise a contact plane takes the part of the motion into it away, or bends a motion away
    /// from it onto it. A sliding normal the motion does not go into stops being valid.
    /// </summary>
    internal static Vector3 ConstrainOffset(Vector3 offset, ref bool slidingNormalValid, Vector3 slidingNormal, bool contactPlaneValid, in Plane contactPlane,
        ref UnitMemo slideLine)
    {
        bool slide = false;
        float slideAngle = VectorMath.Dot(offset, slidingNormal);
        if (slidingNormalValid)
        {
            if (slideAngle < 0.0f) slide = true;
            else slidingNormalValid = false;
        }
        if (!contactPlaneValid)
            return slide ? offset - slidingNormal * slideAngle : offset;

        float planeAngle = VectorMath.Dot(offset, contactPlane.Normal);
        if (slide)
        {
            var along = Vector3.Cross(contactPlane.Normal, slidingNormal);
            return slideLine.NormalizeCheckSmall(ref along) ? Vector3.Zero : Vector3.Dot(along, offset) * along;
        }
        if (planeAngle <= 0.0f)
            return offset - contactPlane.Normal * planeAngle;
        return VectorMath.SnapToPlane(contactPlane, offset);
    }

    /// <summary>
    /// True when retail find_transitional_position would give up before its first sub-step is inserted:
    /// the motion is cut into more than <see cref="PhysicsConstants.MaxSubSteps"/> sub-steps, or the first
    /// sub-step's motion, constrained by the carried sliding normal and contact plane, is shorter than
    /// EPSILON (a mover pushing into a wall it already slid against). Such a move fails and changes
    /// nothing the caller sees, so the engine answers it without setting up the path (not retail; changes
    /// no result). Never true for the camera, whose last sub-step differs. <paramref name="plan"/> receives
    /// the step count and the first sub-step's constrained motion, for <see cref="FindTransitionalPosition(in StepPlan)"/>
    /// once the path is set up from the same mover, state and positions.
    /// Shortcut <see cref="Shortcuts.EarlyRefusal"/> (not retail). Skips: setting up the path for a move that
    /// fails before its first insert. Same result: the failing move changes nothing the caller sees (the result
    /// is the state handed in, no contact, no normal). Proof: RefusedMoveTests, and the suite with shortcuts
    /// off (then this only fills the plan's step count and never refuses).
    /// </summary>
    internal bool RefusesBeforeFirstStep(MoverDescription mover, in MoverState state, in Position begin, in Position end, out StepPlan plan)
    {
        // Worked out in locals and written to the plan once (it lives in the caller's frame).
        var offset = begin.GetOffset(end);
        // The radius as SpherePath.InitSphere scales it (a mover has at least one sphere).
        float radius = mover.Spheres[0].Radius * mover.Scale;
        bool isViewer = (mover.Flags & ObjectInfoState.IsViewer) != 0;
        int numSteps = CalcNumSteps(offset, radius * _subStepScale, isViewer, out var perStep);
        if (isViewer || numSteps <= 0 || numSteps > PhysicsConstants.MaxSubSteps || (Shortcuts & Shortcuts.EarlyRefusal) == 0)
        {
            plan = new StepPlan { Offset = offset, PerStep = perStep, NumSteps = numSteps };
            return !isViewer && numSteps > PhysicsConstants.MaxSubSteps && (Shortcuts & Shortcuts.EarlyRefusal) != 0;
        }
        // As Prepare carries them into the collision info: the sliding normal's horizontal unit (zero
        // when none), the contact plane when in contact.
        bool slidingValid = state.SlidingNormalValid;
        var sliding = slidingValid ? CollisionInfo.HorizontalUnit(state.SlidingNormal) : Vector3.Zero;
        var first = ConstrainOffset(perStep, ref slidingValid, sliding, state.Contact, state.ContactPlane, ref _slideLine);
        plan = new StepPlan
        {
            Offset = offset, PerStep = perStep, NumSteps = numSteps,
            FirstKnown = true, FirstOffset = first, FirstSlidingNormalValid = slidingValid,
        };
        return VectorMath.Dot(first, first) < PhysicsConstants.Epsilon * PhysicsConstants.Epsilon;
    }

    /// <summary>
    /// Retail validate_transition: accepts or rejects the sub-step's result, restores the current position
    /// on failure (remembering a collision normal), keeps the last known contact plane, and updates the
    /// mover's Contact / OnWalkable state.
    /// </summary>
    internal TransitionState ValidateTransition(TransitionState state)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        bool redo = true;
        if (state != TransitionState.OK || PositionsEqual(path.CheckPos, path.CurPos))
        {
            redo = false;
            if (state != TransitionState.OK)
            {
                if (state != TransitionState.Invalid)
                {
                    if (ci.LastKnownContactPlaneValid)
                    {
                        ci.VelocityKilled = true;
                        float dist = VectorMath.Distance(ci.LastKnownContactPlane, path.GlobalCurrCenter[0].Center);
                        if (path.GlobalSphere[0].Radius + PhysicsConstants.Epsilon > MathF.Abs(dist))
                        {
                            ci.SetContactPlane(ci.LastKnownContactPlane, ci.LastKnownContactPlaneIsWater);
                            ci.ContactPlaneCellId = ci.LastKnownContactPlaneCellId;
                            (ci.ContactGround, ci.ContactGroundObject) = (ci.LastKnownGround, ci.LastKnownGroundObject);
                            if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
                                redo = true;
                        }
                    }
                    if (!ci.CollisionNormalValid)
                        ci.SetCollisionNormal(Vector3.UnitZ);
                    path.SetCheckPos(path.CurPos, path.CurCell);
                    BuildCellArray(findContaining: false);
                    state = TransitionState.OK;
                }
            }
            else
            {
                SetCurrentCheckPos();
            }
        }
        else
        {
            SetCurrentCheckPos();
        }

        if (ci.CollisionNormalValid)
            ci.SetSlidingNormal(ci.CollisionNormal);

        if (!IsViewer && (ObjectInfo.PhysicsState & PhysicsState.Gravity) != 0)
            UpdateStationaryFall(redo);

        ci.LastKnownContactPlaneValid = ci.ContactPlaneValid;
        if (ci.ContactPlaneValid)
        {
            ci.LastKnownContactPlane = ci.ContactPlane;
            ci.LastKnownContactPlaneCellId = ci.ContactPlaneCellId;
            ci.LastKnownContactPlaneIsWater = ci.ContactPlaneIsWater;
            (ci.LastKnownGround, ci.LastKnownGroundObject) = (ci.ContactGround, ci.ContactGroundObject);
            ObjectInfo.State |= ObjectInfoState.Contact;
            if (ObjectInfo.IsValidWalkable(ci.ContactPlane.Normal))
                ObjectInfo.State |= ObjectInfoState.OnWalkable;
            else
                ObjectInfo.State &= ~ObjectInfoState.OnWalkable;
        }
        else
        {
            ObjectInfo.State &= ~(ObjectInfoState.Contact | ObjectInfoState.OnWalkable);
        }
        return state;
    }

    /// <summary>
    /// Retail's stationary-fall counter: a falling mover that fails to move for three sub-steps in a row
    /// is given a floor under its feet.
    /// </summary>
    private void UpdateStationaryFall(bool redo)
    {
        var ci = CollisionInfo;
        if (redo)
        {
            ci.FramesStationaryFall = 0;
            return;
        }
        if (ci.FramesStationaryFall == 0) { ci.FramesStationaryFall = 1; return; }
        if (ci.FramesStationaryFall == 1) { ci.FramesStationaryFall = 2; return; }
        ci.FramesStationaryFall = 3;
        var sphere = SpherePath.GlobalSphere[0];
        var floor = new Plane(Vector3.UnitZ, sphere.Radius - sphere.Center.Z);
        ci.SetContactPlane(floor, false);
        ci.ContactPlaneCellId = SpherePath.CheckPos.CellId;
        (ci.ContactGround, ci.ContactGroundObject) = (GroundKind.StationaryFall, 0u);
        if ((ObjectInfo.State & ObjectInfoState.Contact) == 0)
        {
            ci.SetCollisionNormal(floor.Normal);
            ci.CollidedWithEnvironment = true;
        }
    }

    /// <summary>
    /// Retail Frame::is_equal: the same within EPSILON on every origin axis and quaternion component
    /// (acclient MasterProperty.c:1794); the cell ids must match.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool PositionsEqual(in Position a, in Position b)
    {
        if (a.CellId != b.CellId)
            return false;
        const float e = PhysicsConstants.Epsilon;
        var d = a.Frame.Origin - b.Frame.Origin;
        var q = a.Frame.Orientation - b.Frame.Orientation;
        return MathF.Abs(d.X) <= e && MathF.Abs(d.Y) <= e && MathF.Abs(d.Z) <= e
            && MathF.Abs(q.X) < e && MathF.Abs(q.Y) < e && MathF.Abs(q.Z) < e && MathF.Abs(q.W) < e;
    }

    /// <summary>
    /// Where the move ended: the current position, labelled with the current cell's id when they differ
    /// (the id the result reports). Labelled in place rather than on the result's copy, so that the copy
    /// is one whole store: a caller reads the position back as a whole at once (the next move's start),
    /// and a whole read of a copy patched after it was written waits for both stores to land.
    /// </summary>
    internal ref readonly Position ResolvedPosition()
    {
        var path = SpherePath;
        if (path.CurCell is { } cell && cell.Id != path.CurPos.CellId)
            path.CurPos.CellId = cell.Id;
        return ref path.CurPos;
    }

    /// <summary>Accepts the check position as the current one.</summary>
    internal void SetCurrentCheckPos()
    {
        var path = SpherePath;
        path.CurPos = path.CheckPos;
        path.CurCell = path.CheckCell;
        path.CacheGlobalCurrCenter();
        // Retail then sets the check position and cell to the current ones, which they already are:
        // what remains of set_check_pos is the cell list going stale and the check spheres recomputed.
        path.CellArrayValid = false;
        path.CacheGlobalSphere();
    }

    /// <summary>Retail build_cell_array: the cells the check spheres touch; optionally the one holding sphere 0.</summary>
    internal Cell? BuildCellArray(bool findContaining)
    {
        var path = SpherePath;
        path.CellArrayValid = true;
        path.HitsInteriorCell = false;
        if (_aloneCell is not null && CellAloneAtCheck(findContaining, out var holder))
            return holder;
        return World.Cells.FindCellList(path.CheckPos, path.GlobalSphere[..path.NumSphere], CellArray, findContaining, out path.HitsInteriorCell);
    }

    /// <summary>Sets the contact plane carried from the previous frame (retail init_contact_plane).</summary>
    public void InitContactPlane(uint cellId, in Plane plane, bool isWater)
    {
        InitLastKnownContactPlane(cellId, plane, isWater);
        CollisionInfo.SetContactPlane(plane, isWater);
        CollisionInfo.ContactPlaneCellId = cellId;
    }

    /// <summary>What set the carried contact plane (the state's <see cref="MoverState.Ground"/>), for both the plane and the last known one.</summary>
    internal void InitGround(GroundKind ground, uint objectId)
    {
        var ci = CollisionInfo;
        (ci.ContactGround, ci.ContactGroundObject) = (ground, objectId);
        (ci.LastKnownGround, ci.LastKnownGroundObject) = (ground, objectId);
    }

    /// <summary>Sets the last known contact plane (retail init_last_known_contact_plane).</summary>
    public void InitLastKnownContactPlane(uint cellId, in Plane plane, bool isWater)
    {
        CollisionInfo.LastKnownContactPlaneValid = true;
        CollisionInfo.LastKnownContactPlane = plane;
        CollisionInfo.LastKnownContactPlaneIsWater = isWater;
        CollisionInfo.LastKnownContactPlaneCellId = cellId;
    }

    /// <summary>
    /// Sets the sliding normal carried from the previous frame: its horizontal part, normalized (retail
    /// CPhysicsObj's transition set-up, acclient CPhysicsObj.c:1695-1710, zeroes Z before normalizing).
    /// </summary>
    public void InitSlidingNormal(Vector3 normal) => CollisionInfo.SetSlidingNormal(normal);
}
