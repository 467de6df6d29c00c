using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>The retail CSphere collision routines against a transition's moving spheres.</summary>
public static class SphereCollision
{
    /// <summary>
    /// Retail CSphere::intersects_sphere: collides the path's check spheres with a target sphere given in
    /// the check position's landblock space, resolving by step-up, slide, land-on or collide as the path's
    /// mode requires. <paramref name="isCreature"/> marks the target as a creature.
    /// </summary>
    public static TransitionState IntersectsSphere(in Sphere target, Transition transition, bool isCreature)
        => throw new NotImplementedException();

    /// <summary>
    /// Retail CSphere::slide_sphere(transition, normal, curr_pos): slides the check sphere (of radius
    /// <paramref name="radius"/>, centre <paramref name="center"/>) along the plane of
    /// <paramref name="collisionNormal"/> and the contact plane, from <paramref name="currPos"/>.
    /// </summary>
    public static TransitionState SlideSphere(Transition transition, Vector3 center, float radius, ref Vector3 collisionNormal, Vector3 currPos)
        => throw new NotImplementedException();
}
