using AcDream.Core.Physics.Transitions;
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

    /// <summary>Gravity along world Z, in m/s².</summary>
    public const float Gravity = -9.8f;

    /// <summary>Speed limit of a physics object, m/s.</summary>
    public const float MaxVelocity = 50.0f;

    /// <summary>Below this speed a moving object is considered still, m/s.</summary>
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
}
