using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Transitions.Responses;

/// <summary>
/// The retail CCylSphere responses of a transition's moving spheres to an upright cylinder: step up, step
/// down, slide, land on, collide with point. The cylinder's geometry (the slab test, the collision normal,
/// the cap and wall times) is <see cref="CylSphereCollision"/>'s. Everything is in the check cell's landblock
/// space. Nothing here allocates.
/// </summary>
internal static class CylSphereResponses
{
    /// <summary>
    /// Retail CCylSphere::intersects_sphere: collides the path's check spheres with a cylinder given in the
    /// check position's landblock space (axis world +Z), resolving by step-up, slide, land-on or collide.
    /// </summary>
    public static TransitionState IntersectsSphere(in CylSphere cylinder, Transition transition)
    {
        SpherePath path = transition.SpherePath;
        Sphere first = path.GlobalSphere[0];
        bool hasSecond = path.NumSphere > 1;
        Sphere second = hasSecond ? path.GlobalSphere[1] : default;

        Vector3 disp = first.Center - cylinder.LowPoint;
        Vector3 secondDisp = second.Center - cylinder.LowPoint;
        // Retail: radsum = r_cyl - EPSILON + r_sphere (CCylSphere.c intersects_sphere). Retail quirk: sphere 1
        // is tested with sphere 0's radius sum.
        float radsum = cylinder.Radius - PhysicsConstants.Epsilon + first.Radius;

        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal)
            return AnyCheckSphereHits(cylinder, first, disp, hasSecond, second, secondDisp, radsum) ? TransitionState.Collided : TransitionState.OK;

        if (path.StepDown)
            return StepSphereDown(cylinder, transition, first, disp, radsum);

        if (path.CheckWalkable)
            return AnyCheckSphereHits(cylinder, first, disp, hasSecond, second, secondDisp, radsum) ? TransitionState.Collided : TransitionState.OK;

        if (!path.Collide)
            return ResolveFirstContact(cylinder, transition, first, disp, hasSecond, second, secondDisp, radsum);

        if (!AnyCheckSphereHits(cylinder, first, disp, hasSecond, second, secondDisp, radsum))
            return TransitionState.OK;
        return LandOnTopCap(cylinder, transition, first, disp, radsum);
    }

    /// <summary>
    /// Retail CCylSphere::intersects_sphere(p, scale, …): places a cylinder given in its owner's space
    /// (owner at <paramref name="owner"/>, scaled by <paramref name="scale"/>) into the check position's
    /// landblock space and collides it. Retail quirks: the axis stays world +Z whatever the owner's
    /// rotation (only the low point is transformed), and the path's local space is first set to the owner
    /// (cache_localspace_sphere(p, 1.0)), which <see cref="StepSphereUp"/> later uses to rotate its normal.
    /// </summary>
    public static TransitionState IntersectsSphere(in CylSphere localCylinder, in Position owner, float scale, Transition transition)
    {
        SpherePath path = transition.SpherePath;
        path.CacheLocalSpaceSphere(owner, 1.0f);
        CylSphere placed = CylSphereCollision.ToCheckSpace(localCylinder, owner, scale, path.CheckPos);
        return IntersectsSphere(placed, transition);
    }

    /// <summary>
    /// Retail CCylSphere::collide_with_point: a path-clipped mover hit the cylinder. Without perfect clip the
    /// normal is recorded and the result is Collided. With perfect clip the time of impact along the move
    /// is solved (a cap solve on Z, or a swept-circle quadratic in XY with radsum + EPSILON, taking the far
    /// root when the near one is negative), a time outside [0, 1] is Collided, and otherwise the check
    /// sphere is put at the impact (Adjusted).
    /// Retail quirk: the move is measured from sphere 0's current centre whatever <paramref name="sphereNum"/>
    /// is (CCylSphere.c, acclient.c:361704).
    /// </summary>
    internal static TransitionState CollideWithPoint(in CylSphere cylinder, Transition transition, in Sphere checkSphere, Vector3 disp, float radsum, int sphereNum)
    {
        SpherePath path = transition.SpherePath;
        CollisionInfo collisions = transition.CollisionInfo;

        bool definite = CylSphereCollision.CollisionNormal(cylinder, path.GlobalCurrCenter[sphereNum].Center, checkSphere, disp, radsum, out Vector3 normal);
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        if ((transition.ObjectInfo.State & ObjectInfoState.PerfectClip) == 0)
        {
            collisions.SetCollisionNormal(normal);
            return TransitionState.Collided;
        }

        Vector3 current = path.GlobalCurrCenter[0].Center;
        Vector3 movement = checkSphere.Center - current + path.CurToCheckBlockOffset();
        Vector3 startDisp = current - cylinder.LowPoint;
        float reach = radsum + PhysicsConstants.Epsilon;

        float time;
        Vector3 travelled;
        if (!definite)
        {
            // Not sure which face: try the cap first, fall back on the wall if the cap point misses.
            if (MathF.Abs(movement.Z) < PhysicsConstants.Epsilon)
                return TransitionState.Collided;
            time = CylSphereCollision.CapTime(cylinder, checkSphere.Radius, startDisp.Z, movement.Z, out normal);
            travelled = movement * time;
            float capX = travelled.X + startDisp.X, capY = travelled.Y + startDisp.Y;
            if (capX * capX + capY * capY >= reach * reach)
            {
                float moveXYSq = movement.X * movement.X + movement.Y * movement.Y;
                if (MathF.Abs(moveXYSq) < PhysicsConstants.Epsilon)
                    return TransitionState.Collided;
                // Retail quirk: when the wall quadratic has no root the cap time and point are kept, but
                // the normal still becomes radial at that point (CCylSphere.c, acclient.c:361704).
                if (moveXYSq > PhysicsConstants.Epsilon && CylSphereCollision.WallTime(movement, startDisp, reach, moveXYSq, out float wallTime))
                {
                    time = wallTime;
                    travelled = movement * time;
                }
                normal = RadialNormal(current + travelled - cylinder.LowPoint, reach);
            }
        }
        else if (normal.Z != 0.0f)
        {
            if (MathF.Abs(movement.Z) < PhysicsConstants.Epsilon)
                return TransitionState.Collided;
            time = CylSphereCollision.CapTime(cylinder, checkSphere.Radius, startDisp.Z, movement.Z, out _);
            travelled = movement * time;
        }
        else
        {
            float moveXYSq = movement.X * movement.X + movement.Y * movement.Y;
            if (moveXYSq < PhysicsConstants.Epsilon || !CylSphereCollision.WallTime(movement, startDisp, reach, moveXYSq, out time))
                return TransitionState.Collided;
            travelled = movement * time;
            if (time < 0.0f || time > 1.0f)
                return TransitionState.Collided;
            normal = RadialNormal(current + travelled - cylinder.LowPoint, reach);
        }

        if (time < 0.0f || time > 1.0f)
            return TransitionState.Collided;

        path.AddOffsetToCheckPos(current + travelled - checkSphere.Center);
        collisions.SetCollisionNormal(normal);
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CCylSphere::land_on_cylinder: an airborne mover touched the cylinder. Records a step-up
    /// candidate along normal_of_collision (set_collide) and lowers the walkable allowance to the landing
    /// limit; Collided when there is no usable normal.
    /// </summary>
    internal static TransitionState LandOnCylinder(in CylSphere cylinder, Transition transition, in Sphere checkSphere, Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        CylSphereCollision.CollisionNormal(cylinder, path.GlobalCurrCenter[0].Center, checkSphere, disp, radsum, out Vector3 normal);
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        path.SetCollide(normal);
        path.WalkableAllowance = PhysicsConstants.LandingZ;
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CCylSphere::step_sphere_up: a grounded mover's sphere 0 hit the cylinder. When climbing onto
    /// the top (sphere radius + height - disp.z) exceeds the step-up height it slides; otherwise it tries the
    /// transition's step-up along the collision normal, and on failure step_up_slide.
    /// Retail quirk: the normal, already in landblock space, is rotated once more by the path's local-space
    /// frame (localtoglobalvec(localspace_pos)) before step_up (CCylSphere.c, acclient.c:361975).
    /// </summary>
    internal static TransitionState StepSphereUp(in CylSphere cylinder, Transition transition, in Sphere checkSphere, Vector3 disp, float radsum)
    {
        if (transition.ObjectInfo.StepUpHeight < checkSphere.Radius + cylinder.Height - disp.Z)
            return SlideSphere(cylinder, transition, checkSphere, disp, radsum, 0);

        SpherePath path = transition.SpherePath;
        CylSphereCollision.CollisionNormal(cylinder, path.GlobalCurrCenter[0].Center, checkSphere, disp, radsum, out Vector3 normal);
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        Vector3 stepNormal = path.LocalSpacePos.LocalToGlobalVec(normal);
        return transition.StepUp(stepNormal) ? TransitionState.OK : transition.StepUpSlide();
    }

    /// <summary>
    /// Retail CCylSphere::step_sphere_down: while stepping down, lifts the check position so that
    /// <paramref name="checkSphere"/> rests on the top cap, recording a +Z contact plane there. OK when no
    /// check sphere touches; Collided when the step-down cannot resolve it.
    /// </summary>
    internal static TransitionState StepSphereDown(in CylSphere cylinder, Transition transition, in Sphere checkSphere, Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        bool hits = CylSphereCollision.CollidesWithSphere(cylinder, checkSphere, disp, radsum);
        if (!hits && path.NumSphere > 1)
        {
            Sphere second = path.GlobalSphere[1];
            hits = CylSphereCollision.CollidesWithSphere(cylinder, second, second.Center - cylinder.LowPoint, radsum);
        }
        if (!hits)
            return TransitionState.OK;

        // Retail keeps these on the x87 stack at double precision and rounds only its float stores
        // (CCylSphere::step_sphere_down, acclient.c:361573; see SphereCollision.StepSphereDown).
        double stepDown = (double)path.StepDownAmt * path.WalkInterp;
        if (Math.Abs(stepDown) < PhysicsConstants.Epsilon)
            return TransitionState.Collided;

        // How far sphere 0 must rise for its bottom to sit on the top cap.
        double liftWide = (double)cylinder.Height + checkSphere.Radius - disp.Z;
        double walkInterp = (1.0 - liftWide / stepDown) * path.WalkInterp;
        if (walkInterp >= path.WalkInterp || walkInterp < -0.1f)
            return TransitionState.Collided;

        float lift = (float)liftWide;
        Vector3 contact = new(checkSphere.Center.X, checkSphere.Center.Y, (float)((double)lift - checkSphere.Radius + checkSphere.Center.Z));
        SphereResponses.SetRetailContactPlane(transition, Vector3.UnitZ, contact);
        path.WalkInterp = (float)walkInterp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, lift));
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// Retail CCylSphere::slide_sphere: slides check sphere <paramref name="sphereNum"/> along
    /// normal_of_collision by <see cref="SphereResponses.SlideSphere"/> from its current centre;
    /// Collided when there is no usable normal.
    /// </summary>
    internal static TransitionState SlideSphere(in CylSphere cylinder, Transition transition, in Sphere checkSphere, Vector3 disp, float radsum, int sphereNum)
    {
        SpherePath path = transition.SpherePath;
        CylSphereCollision.CollisionNormal(cylinder, path.GlobalCurrCenter[sphereNum].Center, checkSphere, disp, radsum, out Vector3 normal);
        if (VectorMath.NormalizeCheckSmall(ref normal))
            return TransitionState.Collided;
        return SphereResponses.SlideSphere(transition, checkSphere.Center, checkSphere.Radius, ref normal, path.GlobalCurrCenter[sphereNum].Center);
    }

    // ---- helpers ----------------------------------------------------------------------------------

    private static Vector3 RadialNormal(Vector3 fromLow, float reach)
        => new Vector3(fromLow.X, fromLow.Y, 0f) * (1.0f / reach);

    private static bool AnyCheckSphereHits(
        in CylSphere cylinder, in Sphere first, Vector3 disp, bool hasSecond, in Sphere second, Vector3 secondDisp, float radsum)
        => CylSphereCollision.CollidesWithSphere(cylinder, first, disp, radsum)
           || (hasSecond && CylSphereCollision.CollidesWithSphere(cylinder, second, secondDisp, radsum));

    /// <summary>The first-contact ladder of intersects_sphere: grounded, path-clipped, or airborne.</summary>
    private static TransitionState ResolveFirstContact(
        in CylSphere cylinder, Transition transition, in Sphere first, Vector3 disp,
        bool hasSecond, in Sphere second, Vector3 secondDisp, float radsum)
    {
        ObjectInfoState state = transition.ObjectInfo.State;
        if ((state & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
        {
            if (CylSphereCollision.CollidesWithSphere(cylinder, first, disp, radsum))
                return StepSphereUp(cylinder, transition, first, disp, radsum);
            // Retail passes sphere 1's own displacement here; ACE's port passes sphere 0's.
            if (hasSecond && CylSphereCollision.CollidesWithSphere(cylinder, second, secondDisp, radsum))
                return SlideSphere(cylinder, transition, second, secondDisp, radsum, 1);
        }
        else if ((state & ObjectInfoState.PathClipped) != 0)
        {
            if (CylSphereCollision.CollidesWithSphere(cylinder, first, disp, radsum))
                return CollideWithPoint(cylinder, transition, first, disp, radsum, 0);
        }
        else
        {
            if (CylSphereCollision.CollidesWithSphere(cylinder, first, disp, radsum))
                return LandOnCylinder(cylinder, transition, first, disp, radsum);
            if (hasSecond && CylSphereCollision.CollidesWithSphere(cylinder, second, secondDisp, radsum))
                return CollideWithPoint(cylinder, transition, second, secondDisp, radsum, 1);
        }
        return TransitionState.OK;
    }

    /// <summary>
    /// The set_collide arm of intersects_sphere: backs sphere 0 up along its move until its bottom sits on
    /// the top cap. OK when that point is off the cap in XY; Collided when the move has no vertical part or
    /// the time is out of range; else a +Z contact plane is recorded (Adjusted).
    /// </summary>
    private static TransitionState LandOnTopCap(in CylSphere cylinder, Transition transition, in Sphere first, Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        Vector3 back = path.GlobalCurrCenter[0].Center - first.Center - path.CurToCheckBlockOffset();
        if (MathF.Abs(back.Z) < PhysicsConstants.Epsilon)
            return TransitionState.Collided;

        float time = (cylinder.Height + first.Radius - disp.Z) / back.Z;
        Vector3 lift = back * time;
        float landX = lift.X + disp.X, landY = lift.Y + disp.Y;
        if (radsum * radsum < landX * landX + landY * landY)
            return TransitionState.OK;

        float walkInterp = (1.0f - time) * path.WalkInterp;
        if (!(walkInterp < path.WalkInterp && walkInterp >= -0.1f))
            return TransitionState.Collided;

        Vector3 contact = first.Center + lift;
        contact.Z -= first.Radius;
        SphereResponses.SetRetailContactPlane(transition, Vector3.UnitZ, contact);
        path.WalkInterp = walkInterp;
        path.AddOffsetToCheckPos(lift);
        return TransitionState.Adjusted;
    }
}
