using System;
using System.Numerics;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics;

/// <summary>The outcome of one frame of one mover.</summary>
/// <remarks>
/// <para>
/// What is reported follows retail's COLLISIONINFO, filled while the frame's sub-steps run
/// (CTransition::find_transitional_position, CTransition.c 0050BDF0; CPhysicsObj::FindObjCollisions,
/// CPhysicsObj.c 0050F050). Nothing is reported for a frame in which no sub-step ran:
/// </para>
/// <list type="bullet">
/// <item><b>Refused frames after the first contact.</b> A mover that touched something carries its sliding
/// normal (and contact plane) into the next frame in <see cref="Next"/>; a request that pushes straight into
/// it again is cut to nothing before the first sub-step, and retail refuses the frame there:
/// <see cref="Succeeded"/> is false, <see cref="CollisionNormalValid"/> is false and
/// <see cref="CollidedObjects"/> is empty, although the mover is still against the same object. The object
/// was reported in the frame of first contact.</item>
/// <item><b>Static objects</b> (<see cref="PhysicsState.Static"/>) are never listed in
/// <see cref="CollidedObjects"/>: retail counts them as environment, like walls and terrain.</item>
/// <item>Hits found while probing for the ground below (the step-down after a sub-step) are not listed either.</item>
/// </list>
/// <para>
/// To find out what blocked a move: an object id in <see cref="CollidedObjects"/> (the last one that
/// stopped the mover is <see cref="LastCollidedObject"/>) names a non-static object; otherwise a
/// <see cref="CollisionNormal"/> with nothing listed means cell geometry, a building, terrain or a static
/// object; a refused frame with neither means the mover is still pushing into what it touched before (see
/// <see cref="MoverState.SlidingNormal"/>), or the request exceeded <see cref="PhysicsConstants.MaxSubSteps"/>.
/// To know which static object or which shape it was, set <see cref="PhysicsEngine.Observer"/> (for
/// example to a <see cref="Diagnostics.TransitionEventLog"/>): it receives every object shape tested, with its id, and
/// the normal that won.
/// </para>
/// </remarks>
public readonly struct MoveResult
{
    internal MoveResult(bool succeeded, in MoverState next, TransitionState lastState, bool collisionNormalValid, Vector3 collisionNormal,
        bool collidedWithEnvironment, ReadOnlyMemory<uint> collidedObjects, uint lastCollidedObject, bool velocityKilled = false)
    {
        VelocityKilled = velocityKilled;
        Succeeded = succeeded;
        _next = next;
        LastState = lastState;
        CollisionNormalValid = collisionNormalValid;
        CollisionNormal = collisionNormal;
        CollidedWithEnvironment = collidedWithEnvironment;
        CollidedObjects = collidedObjects;
        LastCollidedObject = lastCollidedObject;
    }

    /// <summary>
    /// The outcome of a transition, read from its collision info and path: an accepted move sets every
    /// field of the next state, a failed one keeps <paramref name="previous"/>. Written field by field
    /// into the result, without an intermediate state (a copy of ~140 bytes through the stack otherwise).
    /// A move <paramref name="refused"/> before its first sub-step reads nothing from the transition
    /// (which still holds an earlier move): nothing moved and nothing was hit.
    /// </summary>
    internal MoveResult(Transition t, bool succeeded, bool refused, in MoverState previous)
    {
        Succeeded = succeeded;
        if (refused)
        {
            _next = previous;
            LastState = TransitionState.Collided;
            CollidedObjects = ReadOnlyMemory<uint>.Empty;
            return;
        }
        var ci = t.CollisionInfo;
        if (succeeded)
        {
            // Copied whole from where it lies, labelled already: a caller's first read of the position
            // (as a whole) then takes it straight from this store.
            _next.Position = t.ResolvedPosition();
            _next.ContactPlane = ci.ContactPlane;
            _next.ContactPlaneCellId = ci.ContactPlaneCellId;
            _next.ContactPlaneIsWater = ci.ContactPlaneIsWater;
            _next.Contact = ci.ContactPlaneValid;
            _next.OnWalkable = ci.ContactPlaneValid && ci.ContactPlane.Normal.Z >= PhysicsConstants.FloorZ;
            _next.SlidingNormalValid = ci.SlidingNormalValid;
            _next.SlidingNormal = ci.SlidingNormal;
            _next.Ground = ci.ContactGround;
            _next.GroundObjectId = ci.ContactGroundObject;
            LastState = TransitionState.OK;
        }
        else
        {
            _next = previous;
            LastState = TransitionState.Collided;
        }
        CollisionNormalValid = ci.CollisionNormalValid;
        CollisionNormal = ci.CollisionNormal;
        CollidedWithEnvironment = ci.CollidedWithEnvironment;
        CollidedObjects = ci.CollidedObjects;
        LastCollidedObject = ci.LastCollidedObject;
        VelocityKilled = ci.VelocityKilled;
    }

    /// <summary>
    /// False when retail refuses the move and the mover stays put: the first sub-step could not move at all
    /// (it is pushing into what it touched last frame), the motion needs more than
    /// <see cref="PhysicsConstants.MaxSubSteps"/> sub-steps, or (<see cref="PhysicsEngine.Place"/>) no free spot was found.
    /// </summary>
    public bool Succeeded { get; }
    /// <summary>The mover's state for the next frame: resolved position and cell, contact, walkable, sliding normal.</summary>
    public MoverState Next => _next;

    private readonly MoverState _next;
    /// <summary>The transition's result (OK when the move was accepted).</summary>
    public TransitionState LastState { get; }
    /// <summary>
    /// A sub-step of this frame recorded a collision normal: the mover was stopped by, or slid along, cell
    /// geometry, a building, terrain or an object (static or not), failed a step-up or met an edge; or a
    /// sub-step was rejected with no normal of its own, which records straight up (0, 0, 1) (retail
    /// CTransition::validate_transition, 0050AA70). False in a frame refused before its first sub-step (see
    /// the remarks); false when an airborne mover only touched an object's sphere (retail
    /// CSphere::land_on_sphere records a landing candidate instead); cleared after passing through an
    /// ethereal object or an ignored creature.
    /// </summary>
    public bool CollisionNormalValid { get; }
    /// <summary>The last collision normal recorded in the frame, unit length (zero if too short to normalize), landblock space.</summary>
    public Vector3 CollisionNormal { get; }
    /// <summary>
    /// The mover, having no contact at the start of the frame (<see cref="MoverState.Contact"/> false: it was
    /// airborne), hit cell geometry, a building, terrain or a static object. A grounded mover walking into a
    /// wall does not set it (retail sets collided_with_environment only without contact); use
    /// <see cref="CollisionNormalValid"/>.
    /// </summary>
    public bool CollidedWithEnvironment { get; }
    /// <summary>
    /// The non-static objects collided with in this frame, in the order hit, each once (retail
    /// COLLISIONINFO::add_object), including ethereal objects and ignored creatures the mover passed
    /// through. Empty in refused frames after the first contact and for static objects (see the remarks).
    /// Backed by the engine's buffer: valid until its next call; copy it to keep it.
    /// </summary>
    public ReadOnlyMemory<uint> CollidedObjects { get; }
    /// <summary>The last object in <see cref="CollidedObjects"/> that stopped or deflected the mover (not one passed through), or 0.</summary>
    public uint LastCollidedObject { get; }
    /// <summary>The resolved position.</summary>
    public Position Position => Next.Position;
    /// <summary>Retail asked for the mover's velocity to be zeroed (kill_velocity); a client applies it.</summary>
    public bool VelocityKilled { get; }
}
