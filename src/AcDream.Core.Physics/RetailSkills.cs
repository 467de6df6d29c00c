using System;

namespace AcDream.Core.Physics;

/// <summary>
/// Retail's run and jump formulas from the Run and Jump skills and the burden (see docs/architecture.md,
/// "The motion layer"; the constants are the client's, as the reference notes give them):
/// run rate = (burdenMod × Run/(Run + 200) × 11 + 4) / scale / 4, and 4.5 at a Run skill of exactly 800;
/// jump height = burdenMod × (Jump/(Jump + 1300) × 22.2 + 0.05) × extent / scale, at least 0.35 m, the
/// vertical speed √(19.6 × height); burdenMod = 1 below burden 1, 2 − burden up to 2, then 0. With no stamina
/// left both skills count as 0 (run rate 1, the 0.35 m jump), and a burden of 2 or more cannot jump
/// (CACQualities::InqRunRate / InqJumpVelocity / CanJump, CACQualitiesSkills.c:108-115, :926-1080).
/// </summary>
public sealed class RetailSkills : IMotionSkills
{
    /// <summary>Creates the formulas for one character.</summary>
    /// <param name="runSkill">Run skill, 0 or more.</param>
    /// <param name="jumpSkill">Jump skill, 0 or more.</param>
    /// <param name="burden">Burden as a fraction of capacity (0 = none, 1 = full, 2 = twice), finite, 0 or more.</param>
    /// <param name="scale">The object's scale, finite and more than 0.</param>
    /// <param name="hasStamina">False when the character's stamina is 0: its Run and Jump skills then count as 0.</param>
    /// <exception cref="ArgumentException">An argument out of range, named.</exception>
    public RetailSkills(int runSkill, int jumpSkill, float burden = 0f, float scale = 1f, bool hasStamina = true)
    {
        if (runSkill < 0 || runSkill > 100_000)
            throw new ArgumentException($"runSkill: must be 0 to 100000, got {runSkill}.", nameof(runSkill));
        if (jumpSkill < 0 || jumpSkill > 100_000)
            throw new ArgumentException($"jumpSkill: must be 0 to 100000, got {jumpSkill}.", nameof(jumpSkill));
        if (!(burden >= 0f) || !float.IsFinite(burden))
            throw new ArgumentException($"burden: must be a finite number, 0 or more, got {burden}.", nameof(burden));
        if (!(scale > 0f) || !float.IsFinite(scale))
            throw new ArgumentException($"scale: must be a finite number more than 0, got {scale}.", nameof(scale));
        RunSkill = runSkill;
        JumpSkill = jumpSkill;
        Burden = burden;
        Scale = scale;
        HasStamina = hasStamina;
    }

    /// <summary>The Run skill.</summary>
    public int RunSkill { get; }
    /// <summary>The Jump skill.</summary>
    public int JumpSkill { get; }
    /// <summary>The burden, a fraction of capacity.</summary>
    public float Burden { get; }
    /// <summary>The object's scale.</summary>
    public float Scale { get; }
    /// <summary>The character has stamina left (otherwise its Run and Jump skills count as 0).</summary>
    public bool HasStamina { get; }

    /// <summary>The burden's factor: 1 below 1, 2 − burden below 2, else 0.</summary>
    public static float BurdenMod(float burden) => burden < 1f ? 1f : burden < 2f ? 2f - burden : 0f;

    /// <summary>
    /// The run rate at a Run skill and burden (MovementSystem::GetRunRate, gameplay_misc/MovementSystem.c:19-32, in
    /// double, stored to float). Retail quirk: only a skill of exactly 800 gives 4.5; above it the formula applies
    /// again (4.5 is its value at 1600 only in the limit; ACE returns 4.5 from 800 up).
    /// </summary>
    public static float RunRate(int runSkill, float burden, float scale = 1f)
    {
        if (runSkill == 800)
            return 4.5f;
        return (float)((BurdenMod(burden) * ((double)runSkill / (runSkill + 200) * 11.0) + 4.0) / scale / 4.0);
    }

    /// <summary>The jump height at a Jump skill, extent (clamped to 0..1) and burden, m: at least 0.35.</summary>
    public static float JumpHeight(int jumpSkill, float extent, float burden, float scale = 1f) => (float)JumpHeightExact(jumpSkill, extent, burden, scale);

    // MovementSystem::GetJumpHeight (MovementSystem.c:35-56): in double with the float constants 22.2 and 0.05,
    // the 0.35 floor applied last; InqJumpVelocity takes the square root of the unrounded height.
    private static double JumpHeightExact(int jumpSkill, float extent, float burden, float scale)
    {
        extent = Math.Clamp(extent, 0f, 1f);
        float s = jumpSkill;
        double height = BurdenMod(burden) * (s / (s + 1300.0) * 22.2f + 0.05f) * extent / scale;
        return height < 0.35f ? 0.35f : height;
    }

    /// <summary>The vertical speed that reaches a height under retail gravity: √(19.6 × height), m/s.</summary>
    public static float JumpVelocity(float height) => (float)Math.Sqrt(height * 19.6);

    /// <inheritdoc/>
    public bool TryRunRate(out float rate)
    {
        rate = RunRate(HasStamina ? RunSkill : 0, Burden, Scale);
        return true;
    }

    /// <inheritdoc/>
    public bool TryJumpVelocity(float extent, out float velocity)
    {
        velocity = (float)Math.Sqrt(JumpHeightExact(HasStamina ? JumpSkill : 0, extent, Burden, Scale) * 19.6);
        return true;
    }

    /// <summary>CACQualities::CanJump (CACQualitiesSkills.c:108-115): a burden below 2.</summary>
    public bool CanJump(float extent) => Burden < 2f;
}
