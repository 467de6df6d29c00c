using System;
using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>
/// A projectile in flight, stepped by <see cref="PhysicsEngine.Step(Missile, double)"/>: retail's CPhysicsObj
/// with the Missile state, moved each quantum by its velocity (and gravity when it has the Gravity state)
/// through the transition, and reporting the first thing it hits once.
/// </summary>
/// <remarks>
/// <para>What retail does (CPhysicsObj.c and CObjectInfo.c of the 2013 client):</para>
/// <list type="bullet">
/// <item>get_object_info (CPhysicsObj.c:3516) turns MISSILE_PS into the transition's PATH_CLIPPED (OBJECTINFO 0x8):
/// the transition stops at the first sub-step that records a collision normal (CTransition::find_transitional_position,
/// CTransition.c:1804), so a missile stops at what it meets instead of sliding along it. PERFECT_CLIP is set only
/// for the camera (SmartBox, flags 0x5C), never for a missile.</item>
/// <item>OBJECTINFO::init (CObjectInfo.c:314117) gives a missile no step-down (step_down = !MISSILE_PS): it never
/// follows the ground.</item>
/// <item>OBJECTINFO::missile_ignore (CObjectInfo.c:314069): every mover ignores missile objects; a missile ignores
/// weenie objects other than its target that are ethereal or, when it has a target, are creatures (it passes
/// the archer and other creatures in its way).</item>
/// <item>After the transition, handle_all_collisions (CPhysicsObj.c:6227) reports each object met
/// (track_object_collision → report_object_collision, CPhysicsObj.c:4670) and then the environment
/// (report_environment_collision, CPhysicsObj.c:4636, when the transition collided with the environment or the
/// body landed on walkable ground); the first report clears Missile, AlignPath and PathClipped
/// (state &amp;= 0xFFFFFCBF), so a flight reports once. Then the velocity is reflected off the collision normal
/// by the elasticity, as for any body. Retail's physics does not stop or remove the object: the server's weenie
/// does that on the report. Stepping on after the hit moves the object as a plain body (it falls and bounces).</item>
/// </list>
/// <para>
/// The hit's report is made whether or not the missile has <see cref="PhysicsState.ReportCollisions"/> (retail calls
/// the weenie only with it, but clears the bits either way). With <see cref="PhysicsState.AlignPath"/> (as servers
/// launch missiles) each quantum turns the missile's frame to face along its path before the transition
/// (UpdateObjectInternal, Frame::set_vector_heading), as for any body with that state.
/// </para>
/// </remarks>
public sealed class Missile
{
    /// <summary>The PhysicsState bits retail clears on the first report (mask 0xFFFFFCBF): Missile, AlignPath, PathClipped.</summary>
    public const PhysicsState FlightBits = PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped;

    private readonly MoverDescription _flight;
    private readonly MoverDescription _spent;

    /// <summary>
    /// A missile from a mover description with the <see cref="PhysicsState.Missile"/> state (its spheres, flags,
    /// scale and <see cref="MoverDescription.TargetId"/>), launched from <paramref name="start"/> at
    /// <paramref name="velocity"/>, airborne, with retail's default friction and elasticity.
    /// </summary>
    /// <param name="description">What the missile is; its <see cref="MoverDescription.PhysicsState"/> must include Missile.</param>
    /// <param name="start">The launch position (cell and landblock-local frame); checked against the world at the first step.</param>
    /// <param name="velocity">The launch velocity, landblock axes, m/s.</param>
    /// <exception cref="ArgumentException">A description without the Missile state, a bad frame or a non-finite or too large velocity, named in the message.</exception>
    public Missile(MoverDescription description, Position start, Vector3 velocity)
        : this(description, start, BodyState.Object(velocity), "missile.velocity")
    {
    }

    /// <summary>
    /// A missile launched with a whole <see cref="BodyState"/>: its velocity, spin (a spinning projectile), friction
    /// and elasticity. A missile has no motion interpreter (<see cref="BodyState.HasMotionInterpreter"/> is cleared).
    /// </summary>
    /// <param name="description">What the missile is; its <see cref="MoverDescription.PhysicsState"/> must include Missile.</param>
    /// <param name="start">The launch position (cell and landblock-local frame); checked against the world at the first step.</param>
    /// <param name="body">The launch velocity, spin, friction and elasticity.</param>
    /// <exception cref="ArgumentException">A description without the Missile state, a bad frame or a bad body field, named in the message.</exception>
    public Missile(MoverDescription description, Position start, BodyState body)
        : this(description, start, body, "missile.body.velocity")
    {
    }

    private Missile(MoverDescription description, Position start, BodyState body, string velocityField)
    {
        ArgumentNullException.ThrowIfNull(description);
        if ((description.PhysicsState & PhysicsState.Missile) == 0)
            throw new ArgumentException($"missile.description.physicsState: must include Missile (0x40), got {description.PhysicsState}.", nameof(description));
        Guard.Pose(ref start.Frame, "missile.start");
        BodyGuard.Velocity(body.Velocity, velocityField, "velocity");
        BodyGuard.Check(body, 0.0, Vector3.Zero, 0f);
        _flight = description;
        _spent = description.With(physicsState: description.PhysicsState & ~FlightBits);
        State = MoverState.Airborne(start);
        body.HasMotionInterpreter = false;
        Body = body;
    }

    /// <summary>
    /// A missile as servers launch one (ACE SetProjectilePhysicsState): one sphere of <paramref name="radius"/> on
    /// its origin, the states ReportCollisions, Missile, AlignPath and PathClipped, and Gravity when
    /// <paramref name="gravity"/> (an arrow or a bolt; most spell projectiles fly without).
    /// </summary>
    /// <param name="objectId">The missile's object id.</param>
    /// <param name="radius">Its sphere's radius, metres, more than 0.</param>
    /// <param name="start">The launch position.</param>
    /// <param name="velocity">The launch velocity, landblock axes, m/s.</param>
    /// <param name="targetId">The object it is aimed at (it passes every other creature), or 0 (the default: no target).</param>
    /// <param name="gravity">Whether it falls (default true, an arrow's or a bolt's flight).</param>
    /// <exception cref="ArgumentException">A bad radius, frame or velocity, named in the message.</exception>
    public static Missile Launch(uint objectId, float radius, Position start, Vector3 velocity, uint targetId = 0, bool gravity = true)
    {
        if (!(radius > 0f) || !(radius <= InputLimits.MaxExtent))
            throw new ArgumentException($"missile.radius: must be more than 0 and at most {InputLimits.MaxExtent} m, got {radius}.", nameof(radius));
        var state = PhysicsState.ReportCollisions | FlightBits | (gravity ? PhysicsState.Gravity : PhysicsState.None);
        var description = new MoverDescription(objectId, [new Sphere(Vector3.Zero, radius)], 0f, 0f, state, targetId: targetId);
        return new Missile(description, start, velocity);
    }

    /// <summary>What the missile is now: the launch description while in flight, the same without <see cref="FlightBits"/> after the hit.</summary>
    public MoverDescription Description => InFlight ? _flight : _spent;

    /// <summary>Where it is and how it stands.</summary>
    public MoverState State { get; internal set; }

    /// <summary>Its velocity, spin, friction, elasticity and carried time.</summary>
    public BodyState Body { get; internal set; }

    /// <summary>The flight's hit, or <see cref="MissileHitKind.None"/> while in flight.</summary>
    public MissileHit Hit { get; private set; }

    /// <summary>True until the hit is reported.</summary>
    public bool InFlight => Hit.Kind == MissileHitKind.None;

    /// <summary>Quanta stepped since launch.</summary>
    public int Quanta { get; private set; }

    /// <summary>
    /// After one quantum's accepted transition: retail handle_all_collisions' reports, objects in the order met
    /// (an object with IGNORE_COLLISIONS is not reported; one with REPORT_COLLISIONS_AS_ENVIRONMENT is reported
    /// as environment), then the environment (collided with it, or landed on walkable ground). The first report
    /// ends the flight. True when this quantum reported the hit.
    /// </summary>
    internal bool AfterTransition(CollisionInfo ci, ShadowObjectRegistry objects, bool prevOnWalkable, in MoverState next)
    {
        if (!InFlight)
            return false;
        var ids = ci.CollidedObjects.Span;
        for (int i = 0; i < ids.Length; i++)
        {
            objects.TryGetState(ids[i], out var state);
            if ((state & PhysicsState.ReportCollisionsAsEnvironment) != 0)
                return Report(MissileHitKind.Environment, ids[i], ci, next);
            if ((state & PhysicsState.IgnoreCollisions) == 0)
                return Report(MissileHitKind.Object, ids[i], ci, next);
        }
        if (ci.CollidedWithEnvironment || (!prevOnWalkable && next.OnWalkable))
            return Report(MissileHitKind.Environment, 0, ci, next);
        return false;
    }

    internal void CountQuantum() => Quanta++;

    private bool Report(MissileHitKind kind, uint objectId, CollisionInfo ci, in MoverState next)
    {
        Hit = new MissileHit(kind, objectId, next.Position, ci.CollisionNormalValid, ci.CollisionNormalValid ? ci.CollisionNormal : Vector3.Zero, Quanta);
        return true;
    }
}
