using System.Numerics;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Transitions;

internal sealed partial class Transition
{
    /// <summary>
    /// Retail step_up: tries to climb the obstacle whose normal is given by stepping the check position
    /// down onto it from above. True when the mover found walkable ground within its step height.
    /// </summary>
    public bool StepUp(Vector3 collisionNormal)
    {
        var path = SpherePath;
        CollisionInfo.ClearContactPlane();
        path.StepUp = true;
        path.StepUpNormal = collisionNormal;
        float zLimit = PhysicsConstants.LandingZ;
        float height = PhysicsConstants.DefaultStepDown;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) != 0)
        {
            zLimit = ObjectInfo.GetWalkableZ();
            height = ObjectInfo.StepUpHeight;
        }
        path.WalkableAllowance = zLimit;
        path.BackupCell = path.CheckCell;
        path.BackupCheckPos = path.CheckPos;
        bool stepped = StepDown(height, zLimit);
        path.StepUp = false;
        path.Walkable = null;
        if (!stepped)
            path.RestoreCheckPos();
        Observer?.OnStepUp(collisionNormal, stepped);
        return stepped;
    }

    /// <summary>
    /// Retail step_down: probes <paramref name="height"/> below the check position (or, while stepping up,
    /// from the raised position the step-up routines set) for ground steeper than <paramref name="zLimit"/>;
    /// on success the check position rests on it.
    /// </summary>
    public bool StepDown(float height, float zLimit)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        path.NegPolyHit = false;
        path.StepDown = true;
        path.StepDownAmt = height;
        path.WalkInterp = 1.0f;
        if (!path.StepUp)
        {
            path.CellArrayValid = false;
            path.AddOffsetToCheckPos(new Vector3(0, 0, -height));
        }
        var state = TransitionalInsert(5);
        path.StepDown = false;
        if (state == TransitionState.OK && ci.ContactPlaneValid && ci.ContactPlane.Normal.Z >= zLimit
            && ((ObjectInfo.State & ObjectInfoState.EdgeSlide) == 0 || path.StepUp || CheckWalkable(zLimit)))
        {
            path.Backup = path.InsertType;
            path.InsertType = InsertType.Placement;
            state = TransitionalInsert(1);
            path.InsertType = path.Backup;
            return state == TransitionState.OK;
        }
        return false;
    }

    /// <summary>Retail SPHEREPATH::step_up_slide: gives up a step-up and slides along the step-up normal instead.</summary>
    public TransitionState StepUpSlide()
    {
        var path = SpherePath;
        CollisionInfo.ClearContactPlane();
        path.StepUp = false;
        return SphereResponses.SlideSphere(this, path.GlobalSphere[0].Center, path.GlobalSphere[0].Radius,
            ref path.StepUpNormal, path.GlobalCurrCenter[0].Center);
    }

    /// <summary>
    /// Retail check_walkable: for an edge-sliding grounded mover, probes below the check position to see
    /// whether ground continues there. True when it does (or no probe is needed).
    /// </summary>
    internal bool CheckWalkable(float zCheck)
    {
        var path = SpherePath;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) == 0 || path.CheckWalkables())
            return true;
        // Retail keeps this probe's restore point in locals (CTransition.c:979, 1012), so the path's saved
        // backup position survives for the caller.
        var savedPos = path.CheckPos;
        var savedCell = path.CheckCell;
        float height = ObjectInfo.StepDownHeight;
        path.WalkableAllowance = zCheck;
        path.CheckWalkable = true;
        float radius = path.GlobalSphere[0].Radius;
        if (path.NumSphere < 2 && height > radius * 2)
            height = radius * 0.5f;
        if (height > radius * 2)
            height *= 0.5f;
        path.AddOffsetToCheckPos(new Vector3(0, 0, -height));
        var state = TransitionalInsert(1);
        path.CheckWalkable = false;
        path.SetCheckPos(savedPos, savedCell);
        return state != TransitionState.OK;
    }
}
