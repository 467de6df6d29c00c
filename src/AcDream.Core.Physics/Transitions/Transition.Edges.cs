using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Transitions;

internal sealed partial class Transition
{
    /// <summary>
    /// Retail edge_slide: a grounded mover found no ground below. Without EdgeSlide it may walk off; with
    /// it, it slides along the cliff (contact plane too steep), the precipice (edge of the walkable polygon),
    /// or is stopped. True when <paramref name="state"/> is final.
    /// </summary>
    internal bool EdgeSlide(ref TransitionState state, float stepDownHeight, float zLimit)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        if ((ObjectInfo.State & ObjectInfoState.OnWalkable) == 0 || (ObjectInfo.State & ObjectInfoState.EdgeSlide) == 0)
        {
            ResetForEdgeSlide(true, true);
            state = TransitionState.OK;
            return true;
        }
        // Retail restores the check position and clears the contact plane first, then slides from there
        // (CTransition::edge_slide, acclient CTransition.c:1205-1217): the slide must not be undone.
        if (ci.ContactPlaneValid && ci.ContactPlane.Normal.Z < zLimit)
        {
            var cliff = ci.ContactPlane;
            ResetForEdgeSlide(true, false);
            state = CliffSlide(cliff);
            return false;
        }
        if (path.Walkable is not null)
        {
            ResetForEdgeSlide(false, false);
            state = PrecipiceSlide();
            return state == TransitionState.Collided;
        }
        if (ci.ContactPlaneValid)
        {
            ResetForEdgeSlide(true, true);
            state = TransitionState.OK;
            return true;
        }

        // Nothing known underfoot: go back to the current position and look for the walkable polygon there.
        path.AddOffsetToCheckPos(path.GlobalCurrCenter[0].Center - path.GlobalSphere[0].Center);
        StepDown(stepDownHeight, zLimit);
        ci.ClearContactPlane();
        path.RestoreCheckPos();
        if (path.Walkable is not null)
        {
            path.CacheLocalSpaceSphere(path.WalkablePos, path.WalkableScale);
            path.WalkableCheckPos = path.LocalSpaceSphere[0];
            state = PrecipiceSlide();
            return state == TransitionState.Collided;
        }
        path.Walkable = null;
        path.CellArrayValid = true;
        state = TransitionState.Collided;
        return true;
    }

    /// <summary>Retail set_edge_slide: restores the check position and clears the contact plane, before any slide.</summary>
    private void ResetForEdgeSlide(bool dropWalkable, bool cellsValid)
    {
        var path = SpherePath;
        if (dropWalkable)
            path.Walkable = null;
        path.RestoreCheckPos();
        CollisionInfo.ClearContactPlane();
        if (cellsValid)
            path.CellArrayValid = true;
    }

    /// <summary>
    /// Retail cliff_slide: slides along the line where the steep contact plane meets the last known
    /// ground, keeping the mover on the ground's side.
    /// </summary>
    private TransitionState CliffSlide(in Plane contactPlane)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        var line = Vector3.Cross(contactPlane.Normal, ci.LastKnownContactPlane.Normal);
        line.Z = 0.0f;
        // Retail builds the horizontal perpendicular as (z - y, x - z, 0) with z already zero.
        var normal = new Vector3(line.Z - line.Y, line.X - line.Z, 0);
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.OK;
        var moved = path.GlobalSphere[0].Center - path.GlobalCurrCenter[0].Center + path.CurToCheckBlockOffset();
        float along = Vector3.Dot(normal, moved);
        if (along <= 0.0f)
        {
            path.AddOffsetToCheckPos(normal * along);
            ci.SetCollisionNormal(normal);
        }
        else
        {
            path.AddOffsetToCheckPos(normal * -along);
            ci.SetCollisionNormal(-normal);
        }
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail SPHEREPATH::precipice_slide: slides along the edge of the walkable polygon the mover was
    /// about to leave; Collided when no crossed edge is found.
    /// </summary>
    internal TransitionState PrecipiceSlide()
    {
        var path = SpherePath;
        var walkable = path.Walkable!;
        bool found = PolygonQuery.FindCrossedEdge(walkable, path.WalkableCheckPos, path.WalkableUp, out var edgeNormal);
        path.Walkable = null;
        if (!found)
            return TransitionState.Collided;
        path.StepUp = false;
        edgeNormal = path.WalkablePos.LocalToGlobalVec(edgeNormal);
        var moved = path.GlobalSphere[0].Center - path.GlobalCurrCenter[0].Center + path.CurToCheckBlockOffset();
        if (Vector3.Dot(edgeNormal, moved) > 0.0f)
            edgeNormal = -edgeNormal;
        return SphereResponses.SlideSphere(this, path.GlobalSphere[0].Center, path.GlobalSphere[0].Radius, ref edgeNormal, path.GlobalCurrCenter[0].Center);
    }
}
