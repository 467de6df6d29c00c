using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Transitions.Responses;

/// <summary>
/// The retail CSphere responses of a transition's moving spheres to an obstacle sphere: step up, step down,
/// slide, land on, collide with point. A "target" is the obstacle sphere (retail's <c>this</c>); the "check
/// spheres" are the mover's spheres at the check position (<see cref="SpherePath.GlobalSphere"/>). The
/// geometric tests they ask (overlap, time of collision, placing a sphere) are
/// <see cref="SphereCollision"/>'s. Everything is in the check cell's landblock space. Nothing here allocates.
/// </summary>
internal static class SphereResponses
{
    /// <summary>
    /// Retail CSphere::intersects_sphere: collides the path's check spheres with a target sphere given in
    /// the check position's landblock space, resolving by step-up, slide, land-on or collide as the path's
    /// mode requires. <paramref name="isCreature"/> marks the target as a creature.
    /// </summary>
    public static TransitionState IntersectsSphere(in Sphere target, Transition transition, bool isCreature)
    {
        SpherePath path = transition.SpherePath;
        Sphere first = path.GlobalSphere[0];
        bool hasSecond = path.NumSphere > 1;
        Sphere second = hasSecond ? path.GlobalSphere[1] : default;

        Vector3 disp = first.Center - target.Center;
        Vector3 secondDisp = second.Center - target.Center;
        // Retail shrinks the contact distance by EPSILON so that resting spheres do not re-collide.
        float radsum = target.Radius + first.Radius - PhysicsConstants.Epsilon;

        // Placement, or the obstruction was found ethereal: a plain overlap test, no resolution.
        // Retail quirk: sphere 1 is tested with sphere 0's radius sum (retail CSphere::intersects_sphere).
        if (path.ObstructionEthereal || path.InsertType == InsertType.Placement)
            return AnyCheckSphereHits(disp, hasSecond, secondDisp, radsum) ? TransitionState.Collided : TransitionState.OK;

        if (path.StepDown)
        {
            // A creature is never a floor to step down onto.
            return isCreature ? TransitionState.OK : StepSphereDown(target, transition, first, ref disp, radsum);
        }

        // Probing whether the ground continues: only overlap matters.
        if (path.CheckWalkable)
            return AnyCheckSphereHits(disp, hasSecond, secondDisp, radsum) ? TransitionState.Collided : TransitionState.OK;

        if (!path.Collide)
            return ResolveFirstContact(target, transition, first, disp, hasSecond, second, secondDisp, radsum);

        // A step-up candidate collision is pending (set_collide ran): try to land on top of the target.
        if (isCreature)
            return TransitionState.OK;
        if (!AnyCheckSphereHits(disp, hasSecond, secondDisp, radsum))
            return TransitionState.OK;
        return LandOnTopOfTarget(target, transition, first, disp, radsum);
    }

    /// <summary>
    /// Retail CSphere::intersects_sphere(p, scale, …): places a sphere given in its owner's space
    /// (owner at <paramref name="owner"/>, scaled by <paramref name="scale"/>) into the check position's
    /// landblock space, then collides it as <see cref="IntersectsSphere(in Sphere, Transition, bool)"/>.
    /// </summary>
    public static TransitionState IntersectsSphere(in Sphere localTarget, in Position owner, float scale, Transition transition, bool isCreature)
    {
        Sphere placed = SphereCollision.ToCheckSpace(localTarget, owner, scale, transition.SpherePath.CheckPos);
        return IntersectsSphere(placed, transition, isCreature);
    }

    /// <summary>
    /// Retail CSphere::collide_with_point: a path-clipped mover's check sphere <paramref name="checkSphere"/>
    /// (sphere <paramref name="sphereNum"/>) hit the target. A perfect-clip mover is moved back to the time of
    /// impact (Adjusted); anyone else records the normal from the target to its current position and
    /// is Collided.
    /// </summary>
    internal static TransitionState CollideWithPoint(in Sphere target, Transition transition, in Sphere checkSphere, float radsum, int sphereNum)
    {
        SpherePath path = transition.SpherePath;
        CollisionInfo collisions = transition.CollisionInfo;
        Vector3 current = path.GlobalCurrCenter[sphereNum].Center;

        if ((transition.ObjectInfo.State & ObjectInfoState.PerfectClip) == 0)
        {
            Vector3 away = current - target.Center;
            if (!VectorMath.NormalizeCheckSmall(ref away))
                collisions.SetCollisionNormal(away);
            return TransitionState.Collided;
        }

        float reach = radsum + PhysicsConstants.Epsilon;
        Vector3 startDisp = current - target.Center;
        Vector3 movement = MoveFromCurrent(path, checkSphere.Center, current);
        double time = SphereCollision.FindTimeOfCollision(movement, startDisp, reach);
        if (time < PhysicsConstants.Epsilon || time > 1.0)
            return TransitionState.Collided;

        // Pull the check sphere back from the end of the move to the point of impact.
        Vector3 pullBack = movement * (float)time - movement;
        Vector3 normal = (pullBack + checkSphere.Center - target.Center) * (1.0f / reach);
        collisions.SetCollisionNormal(normal);
        path.AddOffsetToCheckPos(pullBack);
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CSphere::land_on_sphere: an airborne mover touched the target. Records a step-up candidate
    /// (set_collide) along the normal from the target to the current position and lowers the walkable
    /// allowance to the landing limit; Collided when there is no usable normal.
    /// </summary>
    internal static TransitionState LandOnSphere(in Sphere target, Transition transition)
    {
        SpherePath path = transition.SpherePath;
        Vector3 normal = path.GlobalCurrCenter[0].Center - target.Center;
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        path.SetCollide(normal);
        path.WalkableAllowance = PhysicsConstants.LandingZ;
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CSphere::step_sphere_up: a grounded mover's sphere 0 hit the target. When the climb
    /// (radsum + EPSILON - disp.z) exceeds the mover's step-up height it slides; otherwise it tries the
    /// transition's step-up, and on failure step_up_slide.
    /// Retail quirk: the normal handed to step_up is not normalized (CSphere.c, acclient.c:359071).
    /// </summary>
    internal static TransitionState StepSphereUp(in Sphere target, Transition transition, Vector3 disp, float radsum)
    {
        float reach = radsum + PhysicsConstants.Epsilon;
        if (transition.ObjectInfo.StepUpHeight < reach - disp.Z)
            return SlideSphereFromTarget(target, transition, disp, 0);

        Vector3 towardsMover = transition.SpherePath.GlobalCurrCenter[0].Center - target.Center;
        return transition.StepUp(towardsMover) ? TransitionState.OK : transition.StepUpSlide();
    }

    /// <summary>
    /// Retail CSphere::step_sphere_down: while stepping down, lifts <paramref name="checkSphere"/> back up to
    /// rest on top of the target, recording a contact plane tangent to the target at the rest point.
    /// OK when nothing touches or the rest normal is too steep; Collided when the step-down cannot resolve it.
    /// <paramref name="disp"/> (check sphere 0 minus target centre) is overwritten with the rest normal, as retail.
    /// </summary>
    internal static TransitionState StepSphereDown(in Sphere target, Transition transition, in Sphere checkSphere, ref Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        if (!SphereCollision.CollidesWithSphere(disp, radsum))
        {
            if (path.NumSphere <= 1)
                return TransitionState.OK;
            if (!SphereCollision.CollidesWithSphere(path.GlobalSphere[1].Center - target.Center, radsum))
                return TransitionState.OK;
        }

        // Retail evaluates this routine on the x87 stack at double precision (the client sets 53-bit
        // precision, ClientMain::ConfigureFPU, acclient.c:60885) and rounds to float only where it stores
        // a float (CSphere::step_sphere_down, acclient.c:358615). Each rounding point below is one of those
        // stores; the rest stays double. In float the rest normal lands one float step off and positions
        // drift over repeated contacts.
        double stepDownWide = (double)path.StepDownAmt * path.WalkInterp;
        if (Math.Abs(stepDownWide) < PhysicsConstants.Epsilon)
            return TransitionState.Collided;
        float stepDown = (float)stepDownWide;

        // Height above the target's centre at which sphere 0 would just touch it, over its current XY.
        double reachWide = (double)radsum + PhysicsConstants.Epsilon;
        float reach = (float)reachWide;
        float xx = disp.X * disp.X, yy = disp.Y * disp.Y;
        double fraction = (Math.Sqrt(reachWide * reach - ((double)xx + yy)) - disp.Z) / stepDown;
        double walkInterp = (1.0 - fraction) * path.WalkInterp;
        if (walkInterp >= path.WalkInterp || walkInterp < -0.1f)
            return TransitionState.Collided;

        float lift = (float)(stepDown * fraction);
        double restZ = (double)lift + disp.Z;
        double inverseReach = 1.0 / reach;
        double normalZ = restZ * inverseReach;
        disp = new Vector3((float)(inverseReach * disp.X), (float)(inverseReach * disp.Y), (float)normalZ);
        if (normalZ <= path.WalkableAllowance)
            return TransitionState.OK;

        Vector3 restPoint = target.Center + disp * target.Radius;
        SetRetailContactPlane(transition, disp, restPoint);
        path.WalkInterp = (float)walkInterp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, lift));
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CSphere::slide_sphere(object, path, collisions, disp, radsum, sphere_num): slides check sphere
    /// <paramref name="sphereNum"/> along the crease of the target and the contact plane. The normal runs
    /// from the target to the sphere's current position. With no crease (normal parallel to the contact
    /// plane's), a sphere pressing into the plane (<paramref name="disp"/> against it) is Collided, else the
    /// move is projected off the normal.
    /// </summary>
    internal static TransitionState SlideSphereFromTarget(in Sphere target, Transition transition, Vector3 disp, int sphereNum)
    {
        SpherePath path = transition.SpherePath;
        CollisionInfo collisions = transition.CollisionInfo;
        Vector3 current = path.GlobalCurrCenter[sphereNum].Center;

        Vector3 normal = current - target.Center;
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        collisions.SetCollisionNormal(normal);

        Vector3 planeNormal = ContactNormal(collisions);
        Vector3 move = path.GlobalSphere[sphereNum].Center - current + path.CurToCheckBlockOffset();
        if (TrySlideAlongCrease(path, normal, planeNormal, move, out var slid))
            return slid;

        // Retail tests the contact plane's normal against disp here, not the collision normal
        // (CSphere.c, acclient.c:358708).
        if (Vector3.Dot(planeNormal, disp) < 0.0f)
            return TransitionState.Collided;
        path.AddOffsetToCheckPos(-Vector3.Dot(move, normal) * normal);
        return TransitionState.Slid;
    }

    /// <summary>
    /// Retail CSphere::slide_sphere(object, path, collisions, check_pos, disp, radsum, sphere_number): the
    /// normal runs from the target to check sphere <paramref name="sphereNum"/>'s current position, and the
    /// check sphere slides by <see cref="SlideSphere(Transition, Vector3, float, ref Vector3, Vector3)"/>.
    /// </summary>
    internal static TransitionState SlideCheckSphere(in Sphere target, Transition transition, in Sphere checkSphere, int sphereNum)
    {
        Vector3 current = transition.SpherePath.GlobalCurrCenter[sphereNum].Center;
        Vector3 normal = current - target.Center;
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        return SlideSphere(transition, checkSphere.Center, checkSphere.Radius, ref normal, current);
    }

    /// <summary>
    /// Retail CSphere::slide_sphere(transition, normal, curr_pos): slides the check sphere (of radius
    /// <paramref name="radius"/>, centre <paramref name="center"/>) along the plane of
    /// <paramref name="collisionNormal"/> and the contact plane, from <paramref name="currPos"/>.
    /// A zero normal moves the sphere half way back to <paramref name="currPos"/> (Adjusted). Otherwise the
    /// move is projected onto cross(normal, contact normal) (Slid), or Collided when that projection is
    /// shorter than EPSILON. With no crease, a normal facing the contact plane's side projects the move
    /// off the normal (Slid); a normal facing against it is replaced by the reversed move, recorded, and
    /// the sphere is Collided.
    /// </summary>
    public static TransitionState SlideSphere(Transition transition, Vector3 center, float radius, ref Vector3 collisionNormal, Vector3 currPos)
    {
        SpherePath path = transition.SpherePath;
        CollisionInfo collisions = transition.CollisionInfo;
        _ = radius; // Retail passes the radius to add_offset_to_check_pos; our path re-caches every sphere.

        if (collisionNormal == Vector3.Zero)
        {
            path.AddOffsetToCheckPos((currPos - center) * 0.5f);
            return TransitionState.Adjusted;
        }

        collisions.SetCollisionNormal(collisionNormal);
        Vector3 move = center - currPos + path.CurToCheckBlockOffset();
        Vector3 planeNormal = ContactNormal(collisions);
        if (TrySlideAlongCrease(path, collisionNormal, planeNormal, move, out var slid))
            return slid;

        if (Vector3.Dot(collisionNormal, planeNormal) >= 0.0f)
        {
            path.AddOffsetToCheckPos(-Vector3.Dot(collisionNormal, move) * collisionNormal);
            return TransitionState.Slid;
        }

        // Retail returns Collided here (CSphere.c, acclient.c:358898); ACE's port returns OK.
        collisionNormal = -move;
        if (!VectorMath.NormalizeCheckSmall(ref collisionNormal))
            collisions.SetCollisionNormal(collisionNormal);
        return TransitionState.Collided;
    }

    // ---- helpers ----------------------------------------------------------------------------------

    private static bool AnyCheckSphereHits(Vector3 disp, bool hasSecond, Vector3 secondDisp, float radsum)
        => SphereCollision.CollidesWithSphere(disp, radsum) || (hasSecond && SphereCollision.CollidesWithSphere(secondDisp, radsum));

    /// <summary>The first-contact ladder of intersects_sphere: grounded, path-clipped, or airborne.</summary>
    private static TransitionState ResolveFirstContact(
        in Sphere target, Transition transition, in Sphere first, Vector3 disp,
        bool hasSecond, in Sphere second, Vector3 secondDisp, float radsum)
    {
        ObjectInfoState state = transition.ObjectInfo.State;
        if ((state & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
        {
            if (SphereCollision.CollidesWithSphere(disp, radsum))
                return StepSphereUp(target, transition, disp, radsum);
            if (hasSecond && SphereCollision.CollidesWithSphere(secondDisp, radsum))
                return SlideCheckSphere(target, transition, second, 1);
        }
        else if ((state & ObjectInfoState.PathClipped) != 0)
        {
            if (SphereCollision.CollidesWithSphere(disp, radsum))
                return CollideWithPoint(target, transition, first, radsum, 0);
        }
        else
        {
            if (SphereCollision.CollidesWithSphere(disp, radsum))
                return LandOnSphere(target, transition);
            if (hasSecond && SphereCollision.CollidesWithSphere(secondDisp, radsum))
                return CollideWithPoint(target, transition, second, radsum, 1);
        }
        return TransitionState.OK;
    }

    /// <summary>
    /// The set_collide arm of intersects_sphere: backs sphere 0 up along its move until it rests on the
    /// target, and records a contact plane there when it is walkable enough.
    /// </summary>
    private static TransitionState LandOnTopOfTarget(in Sphere target, Transition transition, in Sphere first, Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        // The move backwards, from the check position to the current one, in the check landblock.
        Vector3 back = path.GlobalCurrCenter[0].Center - first.Center - path.CurToCheckBlockOffset();
        float reach = radsum + PhysicsConstants.Epsilon;
        float backLenSq = back.LengthSquared();
        if (MathF.Abs(backLenSq) < PhysicsConstants.Epsilon)
            return TransitionState.Collided;

        double closing = -(double)Vector3.Dot(back, disp);
        double numerator = Math.Sqrt(closing * closing - ((double)disp.LengthSquared() - (double)reach * reach) * backLenSq) + closing;
        // Retail quirk: it compares the root's numerator, not the time, with 1 before choosing the other
        // root (CSphere.c intersects_sphere, acclient.c:359156). A NaN root falls through to Collided.
        if (numerator > 1.0)
            numerator = closing * 2.0 - numerator;
        float time = (float)(numerator / backLenSq);
        float walkInterp = (1.0f - time) * path.WalkInterp;
        if (!(walkInterp < path.WalkInterp && walkInterp >= -0.1f))
            return TransitionState.Collided;

        Vector3 lift = back * time;
        Vector3 restNormal = (disp + lift) * (1.0f / reach);
        if (!path.IsWalkableAllowable(restNormal.Z))
            return TransitionState.OK;

        // Retail quirk: the plane passes through the bottom of the check sphere before it is lifted, not
        // the rest point (CSphere.c intersects_sphere, acclient.c:359156: the offset is added afterwards).
        Vector3 restPoint = first.Center - restNormal * first.Radius;
        SetRetailContactPlane(transition, restNormal, restPoint);
        path.WalkInterp = walkInterp;
        path.AddOffsetToCheckPos(lift);
        return TransitionState.Adjusted;
    }

    /// <summary>The vector from the current centre to a check centre, in the check landblock.</summary>
    private static Vector3 MoveFromCurrent(SpherePath path, Vector3 checkCenter, Vector3 current)
        => checkCenter - current + path.CurToCheckBlockOffset();

    /// <summary>The contact plane's normal, or the last known one when there is no contact plane.</summary>
    private static Vector3 ContactNormal(CollisionInfo collisions)
        => collisions.ContactPlaneValid ? collisions.ContactPlane.Normal : collisions.LastKnownContactPlane.Normal;

    /// <summary>
    /// Records a contact plane through <paramref name="point"/> in the check cell. Retail quirk: the shape
    /// routines pass is_water = 1 to set_contact_plane (CSphere.c / CCylSphere.c; ACE keeps it too).
    /// </summary>
    internal static void SetRetailContactPlane(Transition transition, Vector3 normal, Vector3 point)
    {
        var plane = new Plane(normal, VectorMath.PlaneDThrough(normal, point));
        transition.CollisionInfo.SetContactPlane(plane, isWater: true);
        transition.CollisionInfo.ContactPlaneCellId = transition.SpherePath.CheckPos.CellId;
        transition.CollisionInfo.SetGround(GroundKind.Object);
    }

    /// <summary>
    /// The shared heart of retail's slide_sphere variants: when the collision plane and the contact plane
    /// meet in a line (their normals' cross product is not too short), keep only the part of the move
    /// along that line. Retail quirk: a slide shorter than √EPSILON (its squared length under EPSILON) is
    /// refused as Collided. False when the planes have no usable crease; the caller handles that case.
    /// </summary>
    private static bool TrySlideAlongCrease(SpherePath path, Vector3 collisionNormal, Vector3 planeNormal, Vector3 move, out TransitionState state)
    {
        Vector3 crease = Vector3.Cross(collisionNormal, planeNormal);
        float creaseLenSq = crease.LengthSquared();
        if (creaseLenSq < PhysicsConstants.Epsilon)
        {
            state = TransitionState.OK;
            return false;
        }
        Vector3 along = crease * (Vector3.Dot(move, crease) / creaseLenSq);
        if (along.LengthSquared() < PhysicsConstants.Epsilon)
        {
            state = TransitionState.Collided;
            return true;
        }
        path.AddOffsetToCheckPos(along - move);
        state = TransitionState.Slid;
        return true;
    }
}
