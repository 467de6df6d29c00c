using System;

namespace AcDream.Core.Physics;

/// <summary>The retail CCylSphere collision routines against a transition's moving spheres.</summary>
public static class CylSphereCollision
{
    /// <summary>
    /// Retail CCylSphere::intersects_sphere: collides the path's check spheres with a cylinder given in the
    /// check position's landblock space (axis world +Z), resolving by step-up, slide, land-on or collide.
    /// </summary>
    public static TransitionState IntersectsSphere(in CylSphere cylinder, Transition transition)
        => throw new NotImplementedException();
}
