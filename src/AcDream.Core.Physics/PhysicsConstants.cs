namespace AcDream.Core.Physics;

/// <summary>
/// Numeric constants of the retail collision code. Every value is the retail client's own;
/// a few are odd on purpose and are kept that way (see each remark).
/// </summary>
public static class PhysicsConstants
{
    /// <summary>
    /// The general tolerance of the collision code. Retail stores 0.00019999999 (decompiled);
    /// ACE's PhysicsGlobals rounds it to 0.0002.
    /// </summary>
    public const float Epsilon = 0.0002f;

    /// <summary>
    /// The smallest Z of a unit normal on which a mover can stand. Retail quirk: it is the cosine of
    /// 48.381 used as radians-from-degrees, an odd angle, and retail walks by it
    /// (ACE PhysicsGlobals.FloorZ; holtburger notes). Do not "fix" it to cos(45°).
    /// </summary>
    public const float FloorZ = 0.66417414f;

    /// <summary>Z of a normal steep enough to land on when not walking: cos(85°) (ACE PhysicsGlobals.LandingZ).</summary>
    public const float LandingZ = 0.0871557f;

    /// <summary>
    /// Gravity along world Z, in m/s²: retail PhysicsGlobals::gravity = -9.8000002 (acclient_data.h:6877, the
    /// float nearest -9.8), applied by CPhysicsObj::calc_acceleration to a body with the Gravity state.
    /// </summary>
    public const float Gravity = -9.8f;

    /// <summary>
    /// Speed limit of a physics object, m/s: CPhysicsObj::UpdatePhysicsInternal and set_velocity rescale a
    /// longer velocity to this length (CPhysicsObj.c:2182-2190, compared as 50.0 * 50.0).
    /// </summary>
    public const float MaxVelocity = 50.0f;

    /// <summary>
    /// Below this speed a moving object is stopped, m/s: UpdatePhysicsInternal zeroes the velocity when
    /// |v|² − 0.25² &lt; EPSILON (CPhysicsObj.c:2192), with |v|² taken before friction.
    /// </summary>
    public const float SmallVelocity = 0.25f;

    /// <summary>
    /// The step-down probe used when a mover is not on walkable ground: retail hard-codes
    /// 0.039999999 in transitional_insert and step_up (ACE Transition.cs).
    /// </summary>
    public const float DefaultStepDown = 0.04f;

    /// <summary>Retail refuses a transition cut into more sub-steps than this (ACE Transition.FindTransitionalPosition).</summary>
    public const int MaxSubSteps = 1000;

    /// <summary>Side length of a landblock in metres (8 × 8 land cells of 24 m).</summary>
    public const float LandblockLength = 192.0f;

    /// <summary>Side length of one outdoor land cell in metres.</summary>
    public const float LandCellLength = 24.0f;

    // ---- the body (CPhysicsObj::update_object and friends) ----

    /// <summary>
    /// The shortest physics tick, seconds: retail's CPhysics::UseTime updates no object until 1/30 s has
    /// passed since its last update (CPhysics.c:222, MIN_QUANTUM_93 = 1.0 / 30.0 at CPhysics.c:491), and
    /// CPhysicsObj::update_object steps a remainder after whole max quanta only when it is longer than this
    /// (MIN_QUANTUM_97 = 1.0 / 30.0 at CPhysicsObj.c:7957, tested at 7557); a shorter remainder waits for the next tick.
    /// </summary>
    public const double MinQuantum = 1.0 / 30.0;

    /// <summary>
    /// The longest single quantum, seconds: update_object steps a longer elapsed time in quanta of this
    /// length (MAX_QUANTUM_97 = 1.0 / 5.0, CPhysicsObj.c:7963; loop at 7546-7556). ACE uses 0.1 with a note
    /// that 0.2 "is buggy with MoveToManager turning"; retail is 0.2 and so is this library.
    /// </summary>
    public const double MaxQuantum = 1.0 / 5.0;

    /// <summary>
    /// An elapsed time longer than this is dropped, seconds: update_object resynchronizes its clock and
    /// moves nothing (CPhysicsObj.c:7544, "v6 &lt;= 2.0"). ACE PhysicsGlobals.HugeQuantum.
    /// </summary>
    public const double HugeQuantum = 2.0;

    /// <summary>A physics object's default friction coefficient (DEFAULT_FRICTION = 0.94999999, acclient_data.h:1430).</summary>
    public const float DefaultFriction = 0.95f;

    /// <summary>A physics object's default elasticity (DEFAULT_ELASTICITY = 0.050000001, acclient_data.h:1431).</summary>
    public const float DefaultElasticity = 0.05f;

    /// <summary>
    /// The largest elasticity retail's setter accepts: CPhysicsObj::set_elasticity stores 0.1 for anything
    /// larger and 0 for anything negative (CPhysicsObj.c:1503-1525). ACE PhysicsGlobals.MaxElasticity.
    /// </summary>
    public const float MaxElasticity = 0.1f;

    /// <summary>
    /// Seconds after its last touch at which retail forgets a collision record and reports the end of the
    /// contact: CPhysicsObj::report_collision_end ends a record when curr_time − touched_time &gt; 1.0
    /// (CPhysicsObj.c:6177), or &gt; 0 for an ethereal object. See <see cref="ContactTracker"/>.
    /// </summary>
    public const double CollisionRecordTimeout = 1.0;

    /// <summary>
    /// calc_friction leaves the velocity alone when it leaves the contact plane at this speed or faster,
    /// m/s (v·N ≥ 0.25, CPhysicsObj.c:556 and 582).
    /// </summary>
    public const float FrictionSeparationSpeed = 0.25f;

    /// <summary>A sledding body's friction when fast on a slope steeper than 10° (frict = 0.2, CPhysicsObj.c:558).</summary>
    public const float SleddingFriction = 0.2f;

    /// <summary>
    /// Below this squared speed (1.25², m²/s²) a sledding body gets friction 1 (stops at once) (calc_friction,
    /// CPhysicsObj.c:566-575).
    /// </summary>
    public const float SleddingSlowSpeedSquared = 1.5625f;

    /// <summary>
    /// From this squared speed (2.5², m²/s²) a sledding body on a slope steeper than 10° gets
    /// <see cref="SleddingFriction"/> (calc_friction, CPhysicsObj.c:568).
    /// </summary>
    public const float SleddingFastSpeedSquared = 6.25f;

    /// <summary>cos(10°): a contact plane at least this flat counts as level for sledding friction (cos(0.1745329251994329), CPhysicsObj.c:568).</summary>
    public const float SleddingLevelZ = 0.98480775f;
}
