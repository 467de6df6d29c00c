using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>The outcome of one <see cref="PhysicsEngine.Step(Missile, double)"/>.</summary>
public readonly struct MissileStepResult
{
    internal MissileStepResult(BodyStepResult step, MissileHit hit)
    {
        Step = step;
        Hit = hit;
    }

    /// <summary>The body step: the move, the body and the quanta (as <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, double, Vector3, float)"/> reports them).</summary>
    public BodyStepResult Step { get; }

    /// <summary>The hit reported in this step, or <see cref="MissileHitKind.None"/>: a flight reports one hit, in the step it happens.</summary>
    public MissileHit Hit { get; }
}
