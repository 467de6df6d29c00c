using System.Numerics;
using System.Runtime.Intrinsics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Transitions.Responses;

/// <summary>Collides a transition with one placed physics model (retail CPhysicsPart + CGfxObj::find_obj_collisions).</summary>
internal static class PartCollision
{
    /// <summary>
    /// False when <see cref="Collide"/> would return OK and change nothing but the path's local-space spheres
    /// (not retail; retail runs the test): in a move's insert (neither placement nor an ethereal obstruction,
    /// whose solid tests are not polygon tests), no check sphere reaches the box of the part's polygons.
    /// Every other branch of the BSP query (walkable check, step down, step-up search, contact, path
    /// clipped, free) needs a polygon within a sphere's radius of its centre — the precise hit test — before
    /// it changes anything, and a sphere whose box misses the polygons' box is farther than its radius from
    /// all of them. The local-space spheres are read only by the test that prepared them.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool MayTouchPolygons(SpherePath path, in World.ShadowEntry row)
    {
        if (path.InsertType != InsertType.Transition || path.ObstructionEthereal)
            return true;
        // The walkable check, the step down and the step-up search take only walkable polygons, whose normal
        // faces the world's up more than the walkable allowance (retail's are 0.0872 and up): with one of at
        // least twice UpFacingZ, only polygons facing up by more than UpFacingZ qualify, allowing for an
        // upright part's up being off by 1e-4 and for rounding.
        bool walkableOnly = (path.CheckWalkable || path.StepDown || path.Collide) && path.WalkableAllowance >= 2f * BspTree.UpFacingZ;
        // The box in the check position's landblock space.
        var toCheck = LandDefs.BlockOffset(path.CheckPos.CellId, row.PartPosition.CellId);
        var min = (walkableOnly ? row.WalkableMin : row.PolygonsMin) + toCheck;
        var max = (walkableOnly ? row.WalkableMax : row.PolygonsMax) + toCheck;
        // A sphere reaches the box when, on each axis, centre + radius >= min and centre - radius <= max. The
        // lanes make the very same float sums and comparisons, all at once; the fourth lane (centre 0 against
        // -inf..+inf) passes unless the radius is NaN, when every axis fails too.
        var low = Vector128.Create(min.X, min.Y, min.Z, float.NegativeInfinity);
        var high = Vector128.Create(max.X, max.Y, max.Z, float.PositiveInfinity);
        for (int i = 0; i < path.NumSphere; i++)
        {
            ref readonly var s = ref path.GlobalSphere[i];
            var centre = s.Center.AsVector128();
            var radius = Vector128.Create(s.Radius);
            var inside = Vector128.GreaterThanOrEqual(centre + radius, low) & Vector128.LessThanOrEqual(centre - radius, high);
            if (inside.ExtractMostSignificantBits() == 0xF)
                return true;
        }
        return false;
    }

    /// <summary>
    /// Expresses the path in the part's space, and when a mover sphere touches the model's bounding
    /// sphere, runs the BSP query (the placement insert for an initial placement). A placement test whose
    /// answer is known (<see cref="SpherePath.KnownSolidHit"/>) is answered without either; the local-space
    /// spheres it would have prepared are read only by the test that prepares them.
    /// </summary>
    public static TransitionState Collide(Transition transition, PhysicsModel model, in Position partPosition, float scale)
    {
        var path = transition.SpherePath;
        if (path.KnownSolidHit(model, partPosition, scale))
            return TransitionState.Collided;
        path.CacheLocalSpaceSphere(partPosition, scale);
        var bounds = model.BoundingSphere;
        for (int i = 0; i < path.NumSphere; i++)
        {
            var local = path.LocalSpaceSphere[i];
            float reach = bounds.Radius + local.Radius;
            if (Vector3.DistanceSquared(bounds.Center, local.Center) - reach * reach < PhysicsConstants.Epsilon)
            {
                return path.InsertType == InsertType.InitialPlacement
                    ? BspResponses.PlacementInsert(model.Bsp, transition)
                    : BspResponses.FindCollisions(model.Bsp, transition, scale, model);
            }
        }
        return TransitionState.OK;
    }
}
