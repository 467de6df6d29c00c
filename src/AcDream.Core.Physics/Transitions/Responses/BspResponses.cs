using System;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Transitions.Responses;

/// <summary>
/// The transition-facing modes of a physics BSP tree (retail BSPTREE::find_collisions, placement_insert and
/// the responses they choose): they read the path's mode and its local-space spheres, ask the tree's
/// geometric queries (<see cref="BspNodeQuery"/>, <see cref="BspQuery"/>), and step up, slide, land or stop.
/// Spheres and points are in the tree's own (unscaled) space; results that move the mover are turned into
/// the check position's landblock space through <see cref="SpherePath.LocalSpacePos"/> and the tree's
/// scale. Nothing here allocates.
/// </summary>
internal static class BspResponses
{
    /// <summary>Retail BSPTREE::placement_insert gives up after this many tries (hard-coded in retail).</summary>
    private const int PlacementIterations = 20;

    /// <summary>
    /// Retail BSPTREE::find_collisions: collides the path's local-space spheres (prepared by
    /// <see cref="SpherePath.CacheLocalSpaceSphere"/>) with the tree, in every mode the path is in
    /// (placement, walkable check, step down, collide, step up…), updating the transition.
    /// <paramref name="scale"/> is the scale of the tree's space.
    /// </summary>
    /// <remarks>
    /// The branches, in retail's order:
    /// placement or ethereal obstruction → solid test of both spheres (Collided / OK);
    /// walkable check → <see cref="CheckWalkable"/>; step down → <see cref="StepSphereDown"/>;
    /// collide (a step-up candidate is pending) → the walkable search along the move, Adjusted onto it or OK;
    /// in contact → a front hit of sphere 0 steps up, of sphere 1 slides; a polygon only grazed from behind
    /// is recorded as a negative-polygon hit (sphere 1's first, then sphere 0's, and only for two-sphere
    /// movers) and the result is OK;
    /// not in contact, path-clipped → <see cref="CollideWithPoint"/>;
    /// not in contact → a hit of sphere 0 records a step-up candidate (walkable allowance drops to
    /// landing_z) and is Adjusted; a hit of sphere 1 sets the collision normal and is Collided.
    /// Retail quirk (acclient.c:361295): in the last two cases a polygon grazed from behind counts as a hit.
    /// </remarks>
    /// <param name="tree">The tree.</param>
    /// <param name="transition">The transition, its local-space spheres prepared for the tree.</param>
    /// <param name="scale">The scale of the tree's space.</param>
    /// <param name="owner">The placed model or env cell whose tree this is; when given, a hit of sphere 0 is
    /// remembered for the placement test that may follow (<see cref="SolidHitMemo"/>).</param>
    public static TransitionState FindCollisions(BspTree tree, Transition transition, float scale, object? owner = null)
    {
        ArgumentNullException.ThrowIfNull(tree);
        ArgumentNullException.ThrowIfNull(transition);
        var path = transition.SpherePath;
        var collisions = transition.CollisionInfo;
        var sphere0 = path.LocalSpaceSphere[0];
        var currCenter = path.LocalSpaceCurrCenter.Center;
        var movement = sphere0.Center - currCenter;
        bool twoSpheres = path.NumSphere > 1;

        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal)
        {
            bool centerCheck = !path.BuildingCheck || !path.HitsInteriorCell;
            if (BspNodeQuery.SphereIntersectsSolid(tree, 0, sphere0, centerCheck)
                || (twoSpheres && BspNodeQuery.SphereIntersectsSolid(tree, 0, path.LocalSpaceSphere[1], centerCheck)))
                return TransitionState.Collided;
            return TransitionState.OK;
        }

        if (path.CheckWalkable)
            return CheckWalkable(tree, path, sphere0, scale);

        if (path.StepDown)
            return StepSphereDown(tree, transition, sphere0, scale);

        Polygon? hitPolygon = null;
        var contactPoint = Vector3.Zero;

        if (path.Collide)
        {
            var validPos = sphere0;
            bool changed = false;
            BspNodeQuery.FindWalkable(tree, 0, ref validPos, ref hitPolygon, movement, path.LocalSpaceZ,
                path.WalkableAllowance, ref path.WalkInterp, ref changed);
            if (!changed || hitPolygon is null)
                return TransitionState.OK;
            var offset = path.LocalSpaceMatrix.PositionToGlobal(validPos.Center - sphere0.Center) * scale;
            path.AddOffsetToCheckPos(offset);
            RecordWalkableContact(path, collisions, validPos, hitPolygon, scale);
            return TransitionState.Adjusted;
        }

        if ((transition.ObjectInfo.State & ObjectInfoState.Contact) != 0)
        {
            if (BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere0, movement, ref hitPolygon, ref contactPoint))
            {
                // The step-up's placement insert at this check position will test this tree again.
                if (owner is not null)
                    path.SolidHit.Remember(owner, path, scale);
                return StepSphereUp(transition, hitPolygon!.Plane.Normal);
            }
            if (twoSpheres)
            {
                Polygon? hitPolygon1 = null;
                if (BspNodeQuery.SphereIntersectsPoly(tree, 0, path.LocalSpaceSphere[1], movement, ref hitPolygon1, ref contactPoint))
                    return SlideSphere(transition, hitPolygon1!.Plane.Normal);
                if (hitPolygon1 is not null)
                {
                    path.SetNegPolyHit(false, ToGlobal(path, hitPolygon1.Plane.Normal));
                    return TransitionState.OK;
                }
                if (hitPolygon is not null)
                {
                    path.SetNegPolyHit(true, ToGlobal(path, hitPolygon.Plane.Normal));
                    return TransitionState.OK;
                }
            }
            return TransitionState.OK;
        }

        if ((transition.ObjectInfo.State & ObjectInfoState.PathClipped) != 0)
        {
            if (BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere0, movement, ref hitPolygon, ref contactPoint) || hitPolygon is not null)
                return CollideWithPoint(tree, transition, sphere0, currCenter, hitPolygon!, contactPoint, scale);
            return TransitionState.OK;
        }

        if (BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere0, movement, ref hitPolygon, ref contactPoint) || hitPolygon is not null)
        {
            // A polygon is set only when the precise test found it touching sphere 0 (also when grazed from
            // behind); the step-up candidate's placement insert may test this tree again here.
            if (owner is not null)
                path.SolidHit.Remember(owner, path, scale);
            path.SetCollide(ToGlobal(path, hitPolygon!.Plane.Normal));
            path.WalkableAllowance = PhysicsConstants.LandingZ;
            return TransitionState.Adjusted;
        }
        if (twoSpheres
            && (BspNodeQuery.SphereIntersectsPoly(tree, 0, path.LocalSpaceSphere[1], movement, ref hitPolygon, ref contactPoint) || hitPolygon is not null))
        {
            collisions.SetCollisionNormal(ToGlobal(path, hitPolygon!.Plane.Normal));
            return TransitionState.Collided;
        }
        return TransitionState.OK;
    }

    /// <summary>
    /// Retail BSPTREE::placement_insert for a cell's BSP: pushes the path's local-space spheres out of the
    /// tree's polygons (<see cref="PolygonQuery.AdjustToPlacementPoly"/>), at most 20 tries. OK when they
    /// were clear at once, Adjusted (check position moved) when pushing freed them, Collided otherwise.
    /// </summary>
    /// <remarks>
    /// Retail details kept (acclient.c:360778): when the solid test reports the centre in solid but names
    /// no polygon, the routing radius doubles for the next try; after a push it is reset to sphere 0's
    /// radius. The final offset is turned into landblock space by the tree's rotation only — retail does
    /// not multiply it by a scale (cell trees are unscaled).
    /// </remarks>
    public static TransitionState PlacementInsert(BspTree tree, Transition transition)
    {
        ArgumentNullException.ThrowIfNull(tree);
        ArgumentNullException.ThrowIfNull(transition);
        var path = transition.SpherePath;
        var validPos = path.LocalSpaceSphere[0];
        var validPos1 = path.NumSphere > 1 ? path.LocalSpaceSphere[1] : default;
        float radius = validPos.Radius;
        bool centerCheck = !path.BuildingCheck || !path.HitsInteriorCell;
        Polygon? hitPolygon = null;

        for (int attempt = 0; attempt < PlacementIterations; attempt++)
        {
            bool centerSolid = false;
            if (BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, validPos, radius, ref centerSolid, ref hitPolygon, centerCheck))
            {
                if (hitPolygon is null)
                {
                    radius += radius;
                    continue;
                }
                PolygonQuery.AdjustToPlacementPoly(hitPolygon, ref validPos, ref validPos1, radius, centerSolid, centerCheck);
                hitPolygon = null;
                radius = validPos.Radius;
                continue;
            }

            if (path.NumSphere > 1
                && BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, validPos1, radius, ref centerSolid, ref hitPolygon, centerCheck))
            {
                if (hitPolygon is null)
                {
                    radius += radius;
                    continue;
                }
                PolygonQuery.AdjustToPlacementPoly(hitPolygon, ref validPos1, ref validPos, radius, centerSolid, centerCheck);
                hitPolygon = null;
                radius = validPos.Radius;
                continue;
            }

            if (attempt == 0)
                return TransitionState.OK;
            var offset = path.LocalSpaceMatrix.PositionToGlobal(validPos.Center - path.LocalSpaceSphere[0].Center);
            path.AddOffsetToCheckPos(offset);
            return TransitionState.Adjusted;
        }
        return TransitionState.Collided;
    }

    /// <summary>
    /// Retail BSPTREE::check_walkable: Collided when walkable ground under the sphere still holds the mover
    /// (<see cref="BspNodeQuery.HitsWalkable"/> with the path's local up and walkable allowance), OK otherwise.
    /// <paramref name="scale"/> is unused, as in retail.
    /// </summary>
    public static TransitionState CheckWalkable(BspTree tree, SpherePath path, in Sphere checkPos, float scale)
    {
        _ = scale;
        return BspNodeQuery.HitsWalkable(tree, 0, checkPos, path.LocalSpaceZ, path.WalkableAllowance)
            ? TransitionState.Collided
            : TransitionState.OK;
    }

    /// <summary>
    /// Retail BSPTREE::step_sphere_down: probes down by <c>StepDownAmt × WalkInterp</c> (divided by the
    /// tree's scale) for walkable ground. When found, moves the check position onto it, sets the contact
    /// plane (not water, in the check cell) and the path's walkable polygon, and returns Adjusted; else OK.
    /// </summary>
    public static TransitionState StepSphereDown(BspTree tree, Transition transition, in Sphere checkPos, float scale)
    {
        ArgumentNullException.ThrowIfNull(tree);
        ArgumentNullException.ThrowIfNull(transition);
        var path = transition.SpherePath;
        float depth = -(path.StepDownAmt * path.WalkInterp);
        var movement = path.LocalSpaceZ * depth * (1f / scale);
        var validPos = checkPos;
        Polygon? found = null;
        bool changed = false;
        BspNodeQuery.FindWalkable(tree, 0, ref validPos, ref found, movement, path.LocalSpaceZ,
            path.WalkableAllowance, ref path.WalkInterp, ref changed);
        if (!changed || found is null)
            return TransitionState.OK;
        var offset = path.LocalSpaceMatrix.PositionToGlobal(validPos.Center - checkPos.Center) * scale;
        path.AddOffsetToCheckPos(offset);
        RecordWalkableContact(path, transition.CollisionInfo, validPos, found, scale);
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail BSPTREE::step_sphere_up: tries to climb the polygon whose local normal is given
    /// (<see cref="Transition.StepUp"/> with the normal in landblock space); OK when it climbed, otherwise
    /// the result of <see cref="Transition.StepUpSlide"/>.
    /// </summary>
    public static TransitionState StepSphereUp(Transition transition, Vector3 localNormal)
    {
        ArgumentNullException.ThrowIfNull(transition);
        var normal = ToGlobal(transition.SpherePath, localNormal);
        return transition.StepUp(normal) ? TransitionState.OK : transition.StepUpSlide();
    }

    /// <summary>
    /// Retail BSPTREE::slide_sphere: slides the path's check sphere 0 along the polygon whose local normal
    /// is given (turned into landblock space), from the current sphere 0 (<see cref="SphereResponses.SlideSphere"/>).
    /// </summary>
    public static TransitionState SlideSphere(Transition transition, Vector3 localNormal)
    {
        ArgumentNullException.ThrowIfNull(transition);
        var path = transition.SpherePath;
        var normal = ToGlobal(path, localNormal);
        var check = path.GlobalSphere[0];
        return SphereResponses.SlideSphere(transition, check.Center, check.Radius, ref normal, path.GlobalCurrCenter[0].Center);
    }

    /// <summary>
    /// Retail BSPTREE::collide_with_pt, for path-clipped movers: without PERFECT_CLIP it records the hit
    /// polygon's normal and returns Collided. With it, the sphere is backed off along its move to where it
    /// no longer hits (<see cref="BspQuery.AdjustToPlane"/>), the check position moved there, the normal recorded, and
    /// Adjusted returned; Collided when that search fails.
    /// </summary>
    public static TransitionState CollideWithPoint(BspTree tree, Transition transition, in Sphere checkPos, Vector3 currPos,
        Polygon hitPolygon, Vector3 contactPoint, float scale)
    {
        ArgumentNullException.ThrowIfNull(tree);
        ArgumentNullException.ThrowIfNull(transition);
        ArgumentNullException.ThrowIfNull(hitPolygon);
        var path = transition.SpherePath;
        var collisions = transition.CollisionInfo;
        if ((transition.ObjectInfo.State & ObjectInfoState.PerfectClip) == 0)
        {
            collisions.SetCollisionNormal(ToGlobal(path, hitPolygon.Plane.Normal));
            return TransitionState.Collided;
        }
        var validPos = checkPos;
        // Retail reads the normal of the polygon it started with, even if the search below re-aims it.
        var normal = ToGlobal(path, hitPolygon.Plane.Normal);
        if (!BspQuery.AdjustToPlane(tree, ref validPos, currPos, hitPolygon, ref contactPoint))
            return TransitionState.Collided;
        collisions.SetCollisionNormal(normal);
        var offset = path.LocalSpaceMatrix.PositionToGlobal(validPos.Center - checkPos.Center) * scale;
        path.AddOffsetToCheckPos(offset);
        return TransitionState.Adjusted;
    }

    /// <summary>Rotates a direction from the tested space into the check position's landblock space.</summary>
    private static Vector3 ToGlobal(SpherePath path, Vector3 localVector) => path.LocalSpaceMatrix.PositionToGlobal(localVector);

    /// <summary>
    /// Retail Plane::localtoglobal followed by the scale fix-up of find_collisions / step_sphere_down:
    /// the polygon's plane in the check position's landblock space. Retail quirk: D is computed from the
    /// unscaled local plane and then multiplied by the scale, which is exact only for scale 1 or a tree
    /// placed at the landblock origin.
    /// </summary>
    private static Plane ContactPlaneOf(SpherePath path, Polygon polygon, float scale)
    {
        var local = polygon.Plane;
        ref readonly var space = ref path.LocalSpacePos;
        ref readonly var matrix = ref path.LocalSpaceMatrix;
        var normal = matrix.PlaneNormalToGlobal(local.Normal);
        var pointOnPlane = LandDefs.BlockOffset(path.CheckPos.CellId, space.CellId) + matrix.PositionToGlobal(local.Normal * -local.D, space.Frame.Origin);
        return new Plane(normal, VectorMath.PlaneDThrough(normal, pointOnPlane) * scale);
    }

    private static void RecordWalkableContact(SpherePath path, CollisionInfo collisions, in Sphere validPos, Polygon polygon, float scale)
    {
        collisions.SetContactPlane(ContactPlaneOf(path, polygon, scale), isWater: false);
        collisions.ContactPlaneCellId = path.CheckPos.CellId;
        collisions.SetGround(path.BuildingCheck ? GroundKind.Building : GroundKind.EnvCell);
        path.SetWalkable(validPos, polygon, path.LocalSpaceZ, path.LocalSpacePos, scale);
    }
}