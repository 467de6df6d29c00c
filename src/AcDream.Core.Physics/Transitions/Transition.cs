using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// One move of one mover through the world (retail CTransition): the mover (<see cref="ObjectInfo"/>),
/// its path (<see cref="SpherePath"/>) and what it touched (<see cref="CollisionInfo"/>). Reusable: a
/// transition allocates nothing after its first use. Not thread-safe: use one per thread.
/// </summary>
public sealed partial class Transition
{
    /// <summary>The mover.</summary>
    public readonly ObjectInfo ObjectInfo = new();
    /// <summary>The path.</summary>
    public readonly SpherePath SpherePath = new();
    /// <summary>The contacts.</summary>
    public readonly CollisionInfo CollisionInfo = new();

    /// <summary>
    /// Retail step_up: tries to climb the obstacle whose normal is given by stepping the check position
    /// down onto it from above. True when the mover found walkable ground within its step height.
    /// </summary>
    public bool StepUp(Vector3 collisionNormal) => throw new NotImplementedException();

    /// <summary>
    /// Retail SPHEREPATH::step_up_slide: gives up a step-up and slides along the step-up normal instead.
    /// </summary>
    public TransitionState StepUpSlide() => throw new NotImplementedException();
}
