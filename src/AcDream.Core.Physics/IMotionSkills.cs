namespace AcDream.Core.Physics;

/// <summary>
/// What the motion interpreter asks of the object's owner (retail CWeenieObject's InqRunRate,
/// InqJumpVelocity and CanJump): the run rate and the jump's vertical speed. <see cref="RetailSkills"/> is
/// retail's formulas; a server may answer from its own character data.
/// </summary>
public interface IMotionSkills
{
    /// <summary>The run rate (the RunForward speed the Run hold key gives WalkForward), or false to keep the interpreter's own.</summary>
    bool TryRunRate(out float rate);

    /// <summary>The vertical speed of a jump at <paramref name="extent"/> (0..1), m/s, or false for none.</summary>
    bool TryJumpVelocity(float extent, out float velocity);

    /// <summary>Whether the object may charge a jump at <paramref name="extent"/> (false when loaded down).</summary>
    bool CanJump(float extent);
}
