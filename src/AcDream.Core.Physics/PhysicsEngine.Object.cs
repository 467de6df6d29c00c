using System;
using System.Numerics;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// Advances a body by <paramref name="elapsed"/> seconds and keeps the outcome in it: a body with a motion layer as
    /// <see cref="Step(MoverDescription, in MoverState, in BodyState, ObjectMotion, double)"/> steps it, one without
    /// as <see cref="Step(MoverDescription, in MoverState, in BodyState, double, Vector3, float)"/> with no desired velocity
    /// (it moves by its velocity and gravity: a thrown item, a falling body). Then <see cref="PhysicsObject.State"/> and
    /// <see cref="PhysicsObject.Body"/> hold the step's <see cref="BodyStepResult.Next"/> and <see cref="BodyStepResult.Body"/>.
    /// </summary>
    /// <param name="body">The body.</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <returns>The step's result, the same bit for bit as the struct-level step's; <see cref="BodyStepResult.Speed"/> is its speed.</returns>
    /// <exception cref="ArgumentException">A non-finite, negative or out-of-range argument or body field, named in the message; the body is not changed.</exception>
    public BodyStepResult Step(PhysicsObject body, double elapsed)
    {
        ArgumentNullException.ThrowIfNull(body);
        var step = body.Motion is { } motion
            ? Step(body.Description, body.State, body.Body, motion, elapsed)
            : Step(body.Description, body.State, body.Body, elapsed, Vector3.Zero);
        Keep(body, step);
        return step;
    }

    /// <summary>
    /// <see cref="Step(PhysicsObject, double, Vector3, float)"/> without a jump: a body without a motion layer moved
    /// by a desired velocity the caller gives, the outcome kept in it.
    /// </summary>
    /// <param name="body">The body; it has no <see cref="PhysicsObject.Motion"/>.</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <param name="desiredVelocity">The motion the caller's input asks for, world axes, m/s.</param>
    /// <returns>The step's result, the same bit for bit as the struct-level step's.</returns>
    /// <exception cref="ArgumentException">As <see cref="Step(PhysicsObject, double, Vector3, float)"/>; the body is not changed.</exception>
    public BodyStepResult Step(PhysicsObject body, double elapsed, Vector3 desiredVelocity) => Step(body, elapsed, desiredVelocity, 0f);

    /// <summary>
    /// Advances a body without a motion layer by <paramref name="elapsed"/> seconds, moved by a desired velocity the
    /// caller gives (not retail: see <see cref="Step(MoverDescription, in MoverState, in BodyState, double, Vector3, float)"/>),
    /// and keeps the outcome in it.
    /// </summary>
    /// <param name="body">The body; it has no <see cref="PhysicsObject.Motion"/>.</param>
    /// <param name="elapsed">Seconds since the last call, zero or more.</param>
    /// <param name="desiredVelocity">The motion the caller's input asks for, world axes, m/s.</param>
    /// <param name="jumpVelocity">0 for no jump, else the jump's vertical speed, m/s.</param>
    /// <returns>The step's result, the same bit for bit as the struct-level step's.</returns>
    /// <exception cref="ArgumentException">
    /// A body with a motion layer (it moves by its motion commands: <see cref="Step(PhysicsObject, double)"/>), or a
    /// non-finite, negative or out-of-range argument or body field, named in the message; the body is not changed.
    /// </exception>
    public BodyStepResult Step(PhysicsObject body, double elapsed, Vector3 desiredVelocity, float jumpVelocity)
    {
        ArgumentNullException.ThrowIfNull(body);
        if (body.Motion is not null)
            throw new ArgumentException("body.motion: a body with a motion layer is moved by its motion commands; step it with Step(body, elapsed).", nameof(body));
        var step = Step(body.Description, body.State, body.Body, elapsed, desiredVelocity, jumpVelocity);
        Keep(body, step);
        return step;
    }

    private static void Keep(PhysicsObject body, in BodyStepResult step)
    {
        body.State = step.Next;
        body.Body = step.Body;
    }
}
