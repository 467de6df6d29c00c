using System;
using System.Numerics;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// Advances a missile by <paramref name="elapsed"/> seconds the retail way: the body step of
    /// <see cref="Step(MoverDescription, in MoverState, in BodyState, double, Vector3, float)"/> (quanta of 1/30 to
    /// 1/5 s, velocity and gravity, the transition) with the missile's rules (see <see cref="Missile"/>): no
    /// step-down, the path clipped at the first collision, the missile-ignore rules of the object dispatch, and
    /// after each quantum the hit reported once (objects first, then the environment). A quantum after the hit
    /// moves the object as a plain body, without the Missile, AlignPath and PathClipped states.
    /// Updates <paramref name="missile"/>'s state and body; allocates nothing once warm.
    /// </summary>
    /// <param name="missile">The missile.</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <exception cref="ArgumentException">A non-finite or negative time, or a missile whose position is not in this world, named in the message; the missile is not changed.</exception>
    public MissileStepResult Step(Missile missile, double elapsed)
    {
        ArgumentNullException.ThrowIfNull(missile);
        bool inFlight = missile.InFlight;
        var mover = missile.Description;
        BeginVelocityStep(mover, missile.State, missile.Body, elapsed, Vector3.Zero, 0f, out var s, out var b);
        var step = Advance(mover, s, b, elapsed, false, new MissileMode(missile));
        missile.State = step.Next;
        missile.Body = step.Body;
        return new MissileStepResult(step, inFlight ? missile.Hit : default);
    }
}
