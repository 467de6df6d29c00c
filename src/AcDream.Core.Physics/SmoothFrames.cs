using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Drawing a body between quanta (not retail: retail draws the physics pose as it is). <c>PhysicsEngine.Step</c>
/// moves a body in quanta of at least 1/30 s, so at 144 Hz only about one frame in five sees a new position. A
/// renderer instead draws, every frame, the pose <see cref="BodyStepResult.QuantumFraction"/> of the way from
/// where the last quantum began (<see cref="BodyState.QuantumStart"/>) to where it ended: one quantum behind the
/// physics, never ahead of it, and moving every frame.
/// </summary>
public static class SmoothFrames
{
    /// <summary>
    /// The pose <paramref name="fraction"/> (0..1, clamped) of the way from <paramref name="before"/> to
    /// <paramref name="after"/>, in <paramref name="after"/>'s landblock space (a pose across a landblock border
    /// is first moved into that space): the origin by a linear blend, the orientation by <see cref="Nlerp"/>.
    /// A <paramref name="before"/> with cell 0 (no quantum yet) gives <paramref name="after"/>'s frame.
    /// </summary>
    public static Frame Blend(in Position before, in Position after, float fraction)
    {
        if (before.CellId == 0)
            return after.Frame;
        float t = fraction >= 0f ? MathF.Min(fraction, 1f) : 0f;
        var from = before.Frame.Origin + LandDefs.BlockOffset(after.CellId, before.CellId);
        var origin = from + (after.Frame.Origin - from) * t;
        return new Frame(origin, Nlerp(before.Frame.Orientation, after.Frame.Orientation, t));
    }

    /// <summary>
    /// Normalized linear blend of two rotations along the shorter arc (<paramref name="b"/> is negated when the
    /// two lie in opposite hemispheres), without trigonometry, so the same on every platform. It follows the
    /// same path as a spherical blend (slerp), ahead of or behind it by under 0.1° for turns up to 30° (a body
    /// spinning at 15 rad/s turns 29° in a 1/30 s quantum; a player turns under 5°). A zero blend returns
    /// <paramref name="a"/>; a one returns <paramref name="b"/> (or its negation, the same rotation).
    /// </summary>
    public static Quaternion Nlerp(Quaternion a, Quaternion b, float t)
    {
        if (t <= 0f)
            return a;
        float dot = a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
        if (dot < 0f)
            b = -b;
        if (t >= 1f)
            return b;
        var q = a + (b - a) * t;
        return q.LengthSquared() > 0f ? Quaternion.Normalize(q) : a;
    }
}
