using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// What a mover is: its spheres, step heights and flags. Validated on construction (radii, heights and
/// scale finite, radii and scale positive, all at most <see cref="InputLimits.MaxExtent"/> also after
/// scaling); immutable, so one description may be shared by engines on several threads.
/// </summary>
public sealed class MoverDescription
{
    private readonly Sphere[] _spheres;

    /// <summary>Creates a mover description.</summary>
    /// <param name="objectId">The mover's retail object id (it never collides with itself); 0 for none.</param>
    /// <param name="spheres">One or two spheres in the mover's space (retail uses at most two).</param>
    /// <param name="stepUpHeight">How high it may step up, metres.</param>
    /// <param name="stepDownHeight">How far it steps down to stay grounded, metres.</param>
    /// <param name="physicsState">Its PhysicsState (Gravity, EdgeSlide, Missile, Ethereal…).</param>
    /// <param name="flags">Its ObjectInfo bits that describe what it is (IsPlayer, IsPK, IsViewer…); Contact and OnWalkable come from <see cref="MoverState"/>.</param>
    /// <param name="scale">Its scale, applied to spheres and step heights.</param>
    /// <param name="targetId">A missile's target id, or 0.</param>
    public MoverDescription(uint objectId, ReadOnlySpan<Sphere> spheres, float stepUpHeight, float stepDownHeight,
        PhysicsState physicsState = PhysicsState.Gravity, ObjectInfoState flags = ObjectInfoState.None, float scale = 1f, uint targetId = 0)
    {
        if (spheres.Length < 1 || spheres.Length > 2)
            throw new ArgumentException($"mover.spheres: a mover has one or two spheres, got {spheres.Length}.", nameof(spheres));
        for (int i = 0; i < spheres.Length; i++)
            Guard.Sphere(spheres[i], $"mover.spheres[{i}]");
        Guard.Extent(stepUpHeight, true, "mover.stepUpHeight");
        Guard.Extent(stepDownHeight, true, "mover.stepDownHeight");
        Guard.Extent(scale, false, "mover.scale");
        for (int i = 0; i < spheres.Length; i++)
        {
            Guard.Extent(spheres[i].Radius * scale, false, $"mover.spheres[{i}].radius × scale");
            Guard.Finite(spheres[i].Center * scale, $"mover.spheres[{i}].center × scale");
        }
        if ((flags & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
            throw new ArgumentException("mover.flags: Contact and OnWalkable are per-frame state; pass them in MoverState.", nameof(flags));
        ObjectId = objectId;
        _spheres = spheres.ToArray();
        foreach (var sphere in spheres)
            Reach = MathF.Max(Reach, (sphere.Center.Length() + sphere.Radius) * scale);
        StepUpHeight = stepUpHeight;
        StepDownHeight = stepDownHeight;
        PhysicsState = physicsState;
        Flags = flags;
        Scale = scale;
        TargetId = targetId;
    }

    /// <summary>The farthest point of the (scaled) spheres from the mover's origin, in metres.</summary>
    internal float Reach { get; }

    /// <summary>The retail player setup's step-down height (Setup 0x02000001: step-up 0.6, step-down 1.5; holtburger notes).</summary>
    public const float PlayerStepDownHeight = 1.5f;

    /// <summary>
    /// The retail player (Setup 0x02000001): spheres of radius 0.48 at heights 0.475 and 1.35, step-up 0.6,
    /// step-down 1.5 (<see cref="PlayerStepDownHeight"/>), gravity, edge slide, a player. The seed's door
    /// tests used a step-down of 0.04; pass it as <paramref name="stepDownHeight"/> to reproduce them.
    /// </summary>
    /// <remarks>
    /// <see cref="PhysicsState.EdgeSlide"/> (retail's player state word 0x00400408 carries EDGE_SLIDE_PS) means
    /// a mover on walkable ground does not walk off a drop deeper than its step-down height: at such an edge
    /// it slides along it or stops there (CTransition::edge_slide), in <see cref="PhysicsEngine.Resolve"/> and
    /// <c>PhysicsEngine.Step</c> alike. A drop within the step-down is stepped down; a mover in the air
    /// (a jump) is not held. For a mover that walks or runs off such an edge and falls, drop the flag:
    /// <c>MoverDescription.Player().With(physicsState: PhysicsState.Gravity)</c> (see <see cref="With"/>).
    /// </remarks>
    public static MoverDescription Player(uint objectId = 0x50000001, float stepDownHeight = PlayerStepDownHeight, ObjectInfoState extraFlags = ObjectInfoState.None) =>
        new(objectId, [new Sphere(new Vector3(0, 0, 0.475f), 0.48f), new Sphere(new Vector3(0, 0, 1.35f), 0.48f)],
            0.6f, stepDownHeight, PhysicsState.Gravity | PhysicsState.EdgeSlide, ObjectInfoState.IsPlayer | extraFlags);

    /// <summary>
    /// A copy of this description with the given fields replaced and every other field, the spheres too, kept:
    /// the <c>with</c> of a record, for this immutable class. The copy is checked like a new description
    /// (the same exceptions as the constructor); this one is not changed. For example the retail player
    /// without <see cref="PhysicsState.EdgeSlide"/>, which walks off a drop deeper than its step-down instead
    /// of stopping at it: <c>MoverDescription.Player().With(physicsState: PhysicsState.Gravity)</c>.
    /// </summary>
    /// <param name="objectId">The new <see cref="ObjectId"/>, or null to keep it.</param>
    /// <param name="stepUpHeight">The new <see cref="StepUpHeight"/>, or null to keep it.</param>
    /// <param name="stepDownHeight">The new <see cref="StepDownHeight"/>, or null to keep it.</param>
    /// <param name="physicsState">The new <see cref="PhysicsState"/> (all the bits), or null to keep it.</param>
    /// <param name="flags">The new <see cref="Flags"/> (all the bits), or null to keep them.</param>
    /// <param name="scale">The new <see cref="Scale"/>, or null to keep it.</param>
    /// <param name="targetId">The new <see cref="TargetId"/>, or null to keep it.</param>
    public MoverDescription With(uint? objectId = null, float? stepUpHeight = null, float? stepDownHeight = null,
        PhysicsState? physicsState = null, ObjectInfoState? flags = null, float? scale = null, uint? targetId = null) =>
        new(objectId ?? ObjectId, _spheres, stepUpHeight ?? StepUpHeight, stepDownHeight ?? StepDownHeight,
            physicsState ?? PhysicsState, flags ?? Flags, scale ?? Scale, targetId ?? TargetId);

    /// <summary>The mover's id.</summary>
    public uint ObjectId { get; }
    /// <summary>The spheres, mover space, unscaled.</summary>
    public ReadOnlySpan<Sphere> Spheres => _spheres;
    /// <summary>Step-up height, unscaled.</summary>
    public float StepUpHeight { get; }
    /// <summary>Step-down height, unscaled.</summary>
    public float StepDownHeight { get; }
    /// <summary>PhysicsState bits.</summary>
    public PhysicsState PhysicsState { get; }
    /// <summary>ObjectInfo bits describing the mover.</summary>
    public ObjectInfoState Flags { get; }
    /// <summary>Scale.</summary>
    public float Scale { get; }
    /// <summary>Missile target id or 0.</summary>
    public uint TargetId { get; }
}

/// <summary>
/// What a mover carries from one frame to the next: where it is, and its contact with the ground
/// (retail keeps these on the physics object between transitions).
/// </summary>
public struct MoverState
{
    /// <summary>The position (cell and landblock-local frame).</summary>
    public Position Position;
    /// <summary>The mover touched a contact plane at the end of the last frame.</summary>
    public bool Contact;
    /// <summary>That plane was walkable.</summary>
    public bool OnWalkable;
    /// <summary>
    /// What set the contact plane (<see cref="GroundKind"/>): terrain, an indoor cell's floor, a building, an
    /// object (<see cref="GroundObjectId"/>), or None when no plane is known. Kept with the plane from frame
    /// to frame, as the plane is; it changes no result.
    /// </summary>
    public GroundKind Ground;
    /// <summary>The last contact plane (valid when it was ever set).</summary>
    public Plane ContactPlane;
    /// <summary>The cell whose landblock space <see cref="ContactPlane"/> is in; 0 when no plane is known.</summary>
    public uint ContactPlaneCellId;
    /// <summary>The contact plane is water.</summary>
    public bool ContactPlaneIsWater;
    /// <summary>The mover was sliding along <see cref="SlidingNormal"/>.</summary>
    public bool SlidingNormalValid;
    /// <summary>The sliding normal.</summary>
    public Vector3 SlidingNormal;
    /// <summary>The object whose shape set the contact plane when <see cref="Ground"/> is <see cref="GroundKind.Object"/>, else 0.</summary>
    public uint GroundObjectId;

    /// <summary>
    /// The contact in retail's terms (<see cref="Physics.GroundState"/>): <see cref="Contact"/> and
    /// <see cref="OnWalkable"/> summed up as walkable ground, a steep surface, or airborne.
    /// </summary>
    public readonly GroundState GroundState =>
        !Contact ? GroundState.Airborne : OnWalkable ? GroundState.WalkableGround : GroundState.SteepSurface;

    /// <summary>A mover in the air (no known ground) at a position.</summary>
    public static MoverState Airborne(Position position) => new() { Position = position };

    /// <summary>A mover standing on a horizontal floor at height <paramref name="floorZ"/> (landblock space).</summary>
    public static MoverState OnFloor(Position position, float floorZ) => new()
    {
        Position = position,
        // Checked here too, so the mistake is reported where it was made.
        Contact = Guard.CoordinateOk(floorZ, "floorZ"),
        OnWalkable = true,
        ContactPlane = new Plane(Vector3.UnitZ, -floorZ),
        ContactPlaneCellId = position.CellId,
    };
}

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
