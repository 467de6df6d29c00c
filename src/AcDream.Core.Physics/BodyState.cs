using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// What a moving body carries from one frame to the next besides its <see cref="MoverState"/> (retail keeps
/// these on CPhysicsObj): its velocity, spin, friction and elasticity, the acceleration it had on its last
/// quantum, the stationary-fall counter, and the time not yet stepped. Pass it to
/// <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/> and keep the <see cref="BodyStepResult.Body"/> it returns.
/// </summary>
public struct BodyState
{
    /// <summary>Velocity, world (landblock) axes, m/s (retail m_velocityVector).</summary>
    public Vector3 Velocity;

    /// <summary>
    /// Spin, world axes, rad/s (retail m_omegaVector): each quantum turns the body by Omega × quantum
    /// (Frame::grotate). Retail's calc_acceleration zeroes it when the body stands on walkable ground.
    /// </summary>
    public Vector3 Omega;

    /// <summary>
    /// Friction coefficient, 0..1 (retail default <see cref="PhysicsConstants.DefaultFriction"/>): on walkable
    /// ground the velocity is multiplied by (1 − Friction)^quantum (calc_friction).
    /// </summary>
    public float Friction;

    /// <summary>
    /// Elasticity, 0..1: a collision keeps this share of the speed into the surface, reflected
    /// (handle_all_collisions). Retail's setter caps it at <see cref="PhysicsConstants.MaxElasticity"/>
    /// (<see cref="SetElasticity"/>); a larger value written here directly is not retail and is honoured.
    /// </summary>
    public float Elasticity;

    /// <summary>
    /// Whether the body has a motion interpreter (retail: its movement manager's motion_interpreter is not null,
    /// the test MovementManager::LeaveGround makes, acclient.c:339384; players and creatures have one): a jump
    /// is allowed only from walkable ground (jump_is_allowed), and leaving walkable ground sets the velocity to
    /// the desired motion with the jump's vertical speed (CMotionInterp::LeaveGround). Objects without one
    /// (missiles, thrown items) keep their velocity. A flag only: the interpreter itself belongs to
    /// <see cref="ObjectMotion"/>.
    /// </summary>
    public bool HasMotionInterpreter;

    /// <summary>
    /// The acceleration of the body's next quantum, m/s² (retail m_accelerationVector): gravity for a body
    /// with the Gravity state that is not standing on walkable ground, else zero (calc_acceleration).
    /// The engine recomputes it from the contact state at the start of every step, as retail recomputes it on
    /// every change of contact, walkable ground or the Gravity state.
    /// </summary>
    public Vector3 Acceleration { readonly get; internal set; }

    /// <summary>
    /// Retail's stationary-fall counter carried between quanta (transient bits STATIONARY_FALL 0x10,
    /// STATIONARY_STOP 0x20, STATIONARY_STUCK 0x40, CPhysicsObj::transition seeds the transition's
    /// frames_stationary_fall from them): 0 when the body moved normally.
    /// </summary>
    public int StationaryFall { readonly get; internal set; }

    /// <summary>
    /// Time handed to <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/> but not stepped yet, seconds: retail steps an object
    /// only once 1/30 s has gathered (<see cref="PhysicsConstants.MinQuantum"/>) and carries a short remainder
    /// after whole max quanta to the next tick (the lag of CPhysicsObj::update_time behind the clock).
    /// </summary>
    public double PendingTime { readonly get; internal set; }

    /// <summary>
    /// Where the body was when its last quantum began (cell 0 before its first quantum): with the current
    /// position and <see cref="BodyStepResult.QuantumFraction"/> it is what a renderer blends between quanta
    /// (<see cref="SmoothFrames"/>). Not read by the physics.
    /// </summary>
    public Position QuantumStart { readonly get; internal set; }

    /// <summary>
    /// A player or creature at rest: retail's default friction and elasticity, with a motion interpreter.
    /// </summary>
    public static BodyState Creature() => new()
    {
        Friction = PhysicsConstants.DefaultFriction,
        Elasticity = PhysicsConstants.DefaultElasticity,
        HasMotionInterpreter = true,
    };

    /// <summary>An object without a motion interpreter (a missile, a thrown item) moving at <paramref name="velocity"/>, with retail's default friction and elasticity.</summary>
    public static BodyState Object(Vector3 velocity) => new()
    {
        Velocity = velocity,
        Friction = PhysicsConstants.DefaultFriction,
        Elasticity = PhysicsConstants.DefaultElasticity,
    };

    /// <summary>
    /// Sets <see cref="Elasticity"/> as retail's CPhysicsObj::set_elasticity does: negative becomes 0, more
    /// than <see cref="PhysicsConstants.MaxElasticity"/> becomes 0.1 (CPhysicsObj.c:1503-1525).
    /// </summary>
    public void SetElasticity(float elasticity)
    {
        if (float.IsNaN(elasticity))
            throw new ArgumentException("elasticity: must be a number, got NaN.", nameof(elasticity));
        Elasticity = elasticity < 0f ? 0f : elasticity <= PhysicsConstants.MaxElasticity ? elasticity : PhysicsConstants.MaxElasticity;
    }
}
