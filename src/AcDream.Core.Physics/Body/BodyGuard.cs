using System;
using System.Numerics;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// The checks of <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>'s body arguments, each naming its field. Messages are
/// built only on failure, so the success path allocates nothing.
/// </summary>
internal static class BodyGuard
{
    /// <summary>
    /// The largest speed component accepted, m/s: the library's size limit per second (retail caps a body's
    /// speed at 50), so one 0.2 s quantum moves at most 200 m and its target stays a valid coordinate.
    /// </summary>
    public const float MaxSpeed = InputLimits.MaxExtent;

    public static void Check(in BodyState body, double elapsed, Vector3 desiredVelocity, float jumpVelocity)
    {
        if (!(elapsed >= 0.0) || !double.IsFinite(elapsed))
            throw new ArgumentException($"elapsed: must be a finite number of seconds, zero or more, got {elapsed}.", nameof(elapsed));
        Velocity(desiredVelocity, "desiredVelocity");
        if (!(jumpVelocity >= 0f) || !(jumpVelocity <= MaxSpeed))
            throw new ArgumentException($"jumpVelocity: must be a finite speed, zero or more and at most {MaxSpeed} m/s, got {jumpVelocity}.", nameof(jumpVelocity));
        Velocity(body.Velocity, "body.velocity");
        Velocity(body.Omega, "body.omega");
        Fraction(body.Friction, "body.friction");
        Fraction(body.Elasticity, "body.elasticity");
    }

    /// <summary>
    /// A velocity (or omega) finite and within <see cref="MaxSpeed"/> on each axis; the exception names
    /// <paramref name="field"/> and, as its parameter, <paramref name="paramName"/> (default: the field).
    /// </summary>
    public static void Velocity(Vector3 v, string field, string? paramName = null)
    {
        if (!(MathF.Abs(v.X) <= MaxSpeed) || !(MathF.Abs(v.Y) <= MaxSpeed) || !(MathF.Abs(v.Z) <= MaxSpeed))
            throw new ArgumentException($"{field}: must be finite and within ±{MaxSpeed} per second on each axis, got {v}.", paramName ?? field);
    }

    private static void Fraction(float value, string field)
    {
        if (!(value >= 0f) || !(value <= 1f))
            throw new ArgumentException($"{field}: must be a number from 0 to 1, got {value}.", field);
    }
}
