using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Transitions;

internal sealed partial class Transition
{
    /// <summary>
    /// Retail transitional_insert: inserts the check position into its cell and the other cells it
    /// touches, up to <paramref name="attempts"/> times while collisions keep adjusting it; then settles
    /// pending negative-polygon hits, step-ups, and the step down that keeps a grounded mover grounded.
    /// </summary>
    internal TransitionState TransitionalInsert(int attempts)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        if (path.CheckCell is null)
            return TransitionState.OK;
        if (attempts <= 0)
            return TransitionState.Invalid;

        var state = TransitionState.Invalid;
        for (int attempt = 0; attempt < attempts; attempt++)
        {
            state = InsertIntoCell(path.CheckCell, attempts);
            switch (state)
            {
                case TransitionState.OK:
                    state = CheckOtherCells(path.CheckCell);
                    if (state != TransitionState.OK)
                        path.NegPolyHit = false;
                    if (state == TransitionState.Collided)
                        return state;
                    break;
                case TransitionState.Collided:
                    path.NegPolyHit = false;
                    return state;
                case TransitionState.Adjusted:
                    path.NegPolyHit = false;
                    break;
                case TransitionState.Slid:
                    ci.ClearContactPlane();
                    path.NegPolyHit = false;
                    break;
            }
            if (state != TransitionState.OK)
                continue;

            if (path.Collide)
                return ResolveStepUpCandidate(attempts);

            if (path.NegPolyHit && !path.StepDown && !path.StepUp)
            {
                path.NegPolyHit = false;
                if (path.NegStepUp)
                {
                    if (!StepUp(path.NegCollisionNormal))
                        state = StepUpSlide();
                }
                else
                {
                    state = SphereResponses.SlideSphere(this, path.GlobalSphere[0].Center, path.GlobalSphere[0].Radius,
                        ref path.NegCollisionNormal, path.GlobalCurrCenter[0].Center);
                }
                continue;
            }

            if (ci.ContactPlaneValid || (ObjectInfo.State & ObjectInfoState.Contact) == 0 || path.StepDown
                || path.CheckCell is null || !ObjectInfo.StepDown)
                return TransitionState.OK;

            if (KeepGrounded(ref state))
                return state;
        }
        return state;
    }

    /// <summary>
    /// A grounded mover lost its contact plane: step down to find the ground again; failing that, handle
    /// the edge. True when <paramref name="state"/> is final.
    /// </summary>
    private bool KeepGrounded(ref TransitionState state)
    {
        var path = SpherePath;
        float zLimit = PhysicsConstants.LandingZ;
        float depth = PhysicsConstants.DefaultStepDown;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
        {
            zLimit = ObjectInfo.GetWalkableZ();
            depth = ObjectInfo.StepDownHeight;
        }
        path.WalkableAllowance = zLimit;
        path.SaveCheckPos();
        float diameter = path.GlobalSphere[0].Radius * 2;
        // Retail: a one-sphere mover whose step-down exceeds its diameter probes only half its radius;
        // a probe deeper than the diameter is tried as two half probes.
        if (path.NumSphere < 2 && diameter < depth)
            depth = path.GlobalSphere[0].Radius * 0.5f;
        if (diameter >= depth)
        {
            if (StepDown(depth, zLimit))
            {
                path.Walkable = null;
                state = TransitionState.OK;
                return true;
            }
        }
        else
        {
            depth *= 0.5f;
            if (StepDown(depth, zLimit) || StepDown(depth, zLimit))
            {
                path.Walkable = null;
                state = TransitionState.OK;
                return true;
            }
        }
        return EdgeSlide(ref state, depth, zLimit);
    }

    /// <summary>
    /// After an insert that recorded a step-up candidate (a low obstacle hit while grounded): accept the
    /// position if the ground holds, else go back and report the obstacle.
    /// </summary>
    private TransitionState ResolveStepUpCandidate(int attempts)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        var state = TransitionState.OK;
        bool reset = false;
        path.Collide = false;
        if (ci.ContactPlaneValid && CheckWalkable(PhysicsConstants.LandingZ))
        {
            path.Backup = path.InsertType;
            path.InsertType = InsertType.Placement;
            state = TransitionalInsert(attempts);
            path.InsertType = path.Backup;
            if (state != TransitionState.OK)
            {
                state = TransitionState.OK;
                reset = true;
            }
        }
        else
        {
            reset = true;
        }
        path.Walkable = null;
        if (!reset)
            return state;
        path.RestoreCheckPos();
        ci.ClearContactPlane();
        if (ci.LastKnownContactPlaneValid)
        {
            ci.LastKnownContactPlaneValid = false;
            ci.VelocityKilled = true;
        }
        else
            ci.SetCollisionNormal(path.StepUpNormal);
        return TransitionState.Collided;
    }

    /// <summary>Retail insert_into_cell: collides with one cell until the result is OK or Collided, or attempts run out.</summary>
    internal TransitionState InsertIntoCell(Cell? cell, int attempts)
    {
        if (cell is null)
            return TransitionState.Collided;
        var state = TransitionState.OK;
        for (int i = 0; i < attempts; i++)
        {
            state = FindCollisions(cell);
            if (state == TransitionState.OK || state == TransitionState.Collided)
                return state;
            if (state == TransitionState.Slid)
                CollisionInfo.ClearContactPlane();
        }
        return state;
    }

    /// <summary>
    /// Retail check_other_cells: collides with every other cell the check spheres touch, then moves the
    /// check position into the cell that holds it (or fails when none does).
    /// </summary>
    internal TransitionState CheckOtherCells(Cell? current)
    {
        var path = SpherePath;
        var holder = BuildCellArray(findContaining: true);
        for (int i = 0; i < CellArray.Count; i++)
        {
            var cell = CellArray[i];
            if (ReferenceEquals(cell, current))
                continue;
            var state = FindCollisions(cell);
            switch (state)
            {
                case TransitionState.Slid:
                    CollisionInfo.ClearContactPlane();
                    return state;
                case TransitionState.Collided:
                case TransitionState.Adjusted:
                    return state;
            }
        }
        // Usually the check position stays in its cell: then the store (and its GC write barrier) is skipped.
        if (!ReferenceEquals(path.CheckCell, holder))
            path.CheckCell = holder;
        if (holder is not null)
        {
            if (holder.Id != path.CheckPos.CellId)
                Observer?.OnCellChanged(path.CheckPos.CellId, holder.Id);
            path.AdjustCheckPos(holder.Id);
            return TransitionState.OK;
        }
        return path.StepDown ? TransitionState.Collided : AdjustToOutside();
    }

    /// <summary>No cell holds the check position: an outdoor position outside any known cell is refused.</summary>
    private TransitionState AdjustToOutside()
    {
        var path = SpherePath;
        if (!LandDefs.IsLandCell(path.CheckPos.CellId))
            return TransitionState.Collided;
        var offset = path.CheckPos.Origin;
        uint block = path.CheckPos.CellId >> 16;
        float size = PhysicsConstants.LandblockLength;
        int dx = (int)System.MathF.Floor(offset.X / size), dy = (int)System.MathF.Floor(offset.Y / size);
        int bx = (int)(block >> 8) + dx, by = (int)(block & 0xFF) + dy;
        if (bx < 0 || by < 0 || bx > 0xFE || by > 0xFE)
            return TransitionState.Collided;
        var local = new Vector3(offset.X - dx * size, offset.Y - dy * size, offset.Z);
        uint cellId = LandDefs.LandCellAt(((uint)bx << 8) | (uint)by, local);
        var cell = cellId == 0 ? null : World.Cells.Get(cellId);
        if (cell is null)
            return TransitionState.Collided;
        path.AdjustCheckPos(cellId);
        path.SetCheckPos(path.CheckPos, cell);
        path.CellArrayValid = true;
        return TransitionState.OK;
    }

    /// <summary>
    /// Collides with one cell: its own geometry, then (outdoors) the building standing in it, then the
    /// objects listed in it (retail CObjCell::find_collisions and its overrides).
    /// </summary>
    internal TransitionState FindCollisions(Cell cell)
    {
        // The cell kinds are two sealed classes (Cell's constructor is private protected): one test of the kind
        // calls the cell's own routine directly, and a cell that is not a land cell is an env cell.
        TransitionState state;
        Building? building = null;
        if (cell is LandCell land)
        {
            state = CellCollisions.FindEnvCollisions(land, this);
            building = land.Building;
        }
        else
        {
            state = CellCollisions.FindEnvCollisions(Unsafe.As<EnvCell>(cell), this);
        }
        if (state != TransitionState.OK)
            return state;
        if (building is not null)
        {
            state = CellCollisions.FindBuildingCollisions(building, this);
            if (state != TransitionState.OK)
                return state;
        }
        return ObjectCollisions.FindInCell(this, cell.Id);
    }

    /// <summary>
    /// Retail OBJECTINFO::validate_walkable against a terrain contact plane: records the plane as contact,
    /// and pushes a sphere that sank into it back up. The camera (IsViewer) takes its own arm,
    /// <see cref="ValidateViewerWalkable"/>.
    /// </summary>
    internal TransitionState ValidateWalkable(in Sphere check, in Plane plane, bool isWater, float waterDepth, uint cellId)
    {
        if (IsViewer)
            return ValidateViewerWalkable(check, plane);
        var path = SpherePath;
        var ci = CollisionInfo;
        // The scalar dot product is the vector one's sum and rounding; a zero dist may differ in sign only,
        // and nothing below reads that sign (the tests against ±EPSILON, and zDist only below -EPSILON).
        float dist = VectorMath.Dot(check.Center - new Vector3(0, 0, check.Radius), plane.Normal) + plane.D + waterDepth;
        bool mayTakePlane = path.StepDown || (ObjectInfo.State & ObjectInfoState.OnWalkable) == 0 || ObjectInfo.IsValidWalkable(plane.Normal);
        bool reportGround = (ObjectInfo.State & ObjectInfoState.Contact) == 0 && !path.StepDown;
        if (dist >= -PhysicsConstants.Epsilon)
        {
            if (dist > PhysicsConstants.Epsilon)
                return TransitionState.OK;
            if (mayTakePlane)
            {
                ci.SetContactPlane(plane, isWater);
                ci.ContactPlaneCellId = cellId;
                ci.SetGround(GroundKind.Terrain);
            }
            if (reportGround)
            {
                ci.SetCollisionNormal(plane.Normal);
                ci.CollidedWithEnvironment = true;
            }
            return TransitionState.OK;
        }
        if (path.CheckWalkable)
            return TransitionState.Collided;
        float zDist = dist / plane.Normal.Z;
        if (mayTakePlane)
        {
            ci.SetContactPlane(plane, isWater);
            ci.ContactPlaneCellId = cellId;
            ci.SetGround(GroundKind.Terrain);
            if (path.StepDown)
            {
                float interp = (1.0f - -1.0f / (path.StepDownAmt * path.WalkInterp) * zDist) * path.WalkInterp;
                if (interp >= path.WalkInterp || interp < -0.1f)
                    return TransitionState.Collided;
                path.WalkInterp = interp;
            }
            path.AddOffsetToCheckPos(new Vector3(0, 0, -zDist));
        }
        if (reportGround)
        {
            ci.SetCollisionNormal(plane.Normal);
            ci.CollidedWithEnvironment = true;
        }
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// The camera's arm of retail OBJECTINFO::validate_walkable (acclient 0x0050D010, CObjectInfo.c:136):
    /// the viewer sphere never takes the terrain as a contact plane. When it has sunk more than EPSILON
    /// into the plane it is moved back along its sub-step to the point where it touches (the plane distance
    /// over the sub-step's approach), the plane becomes the collision normal and the result is Adjusted.
    /// Retail quirk kept: a camera that began indoors ignores the terrain when that back-off fraction is
    /// outside (0, 1]. Not retail: a sub-step parallel to the plane (no finite fraction) is accepted as it
    /// is instead of moving the camera to infinity.
    /// </summary>
    private TransitionState ValidateViewerWalkable(in Sphere check, in Plane plane)
    {
        var path = SpherePath;
        float dist = Vector3.Dot(check.Center, plane.Normal) + plane.D - check.Radius;
        if (dist > -PhysicsConstants.Epsilon)
            return TransitionState.OK;
        var motion = check.Center - path.GlobalCurrCenter[0].Center;
        float interp = dist / Vector3.Dot(motion, plane.Normal);
        if (!float.IsFinite(interp))
            return TransitionState.OK;
        bool beganIndoors = path.HasBeginPos && !LandDefs.IsLandCell(path.BeginPos.CellId);
        if ((interp <= 0f || interp > 1f) && beganIndoors)
            return TransitionState.OK;
        path.AddOffsetToCheckPos(motion * -interp);
        CollisionInfo.SetCollisionNormal(plane.Normal);
        CollisionInfo.CollidedWithEnvironment = true;
        return TransitionState.Adjusted;
    }
}
