namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>Retail's run rate and jump formulas, hand-computed from the constants (retail-facts, "The motion layer").</summary>
public class RetailSkillsTests
{
    // (burdenMod × Run/(Run + 200) × 11 + 4) / 4; burdenMod 1 at burden 0, 0.5 at 1.5, 0 at 2; 4.5 from Run 800.
    [Theory]
    [InlineData(0, 0f, 1.0)]
    [InlineData(0, 1.5f, 1.0)]
    [InlineData(0, 2f, 1.0)]
    [InlineData(100, 0f, 1.9166667)]       // (100/300·11 + 4)/4 = (3.6666667 + 4)/4
    [InlineData(100, 1.5f, 1.4583333)]     // (0.5·3.6666667 + 4)/4
    [InlineData(100, 2f, 1.0)]
    [InlineData(300, 0f, 2.65)]            // (300/500·11 + 4)/4 = 10.6/4
    [InlineData(300, 1.5f, 1.825)]         // (0.5·6.6 + 4)/4
    [InlineData(300, 2f, 1.0)]
    [InlineData(799, 0f, 3.1994494)]       // (799/999·11 + 4)/4 = (8.7977978 + 4)/4
    [InlineData(799, 1.5f, 2.0997247)]     // (0.5·8.7977978 + 4)/4
    [InlineData(799, 2f, 1.0)]
    [InlineData(800, 0f, 4.5)]             // the cap: 18/4 whatever the burden
    [InlineData(800, 1.5f, 4.5)]
    [InlineData(800, 2f, 4.5)]
    [InlineData(801, 0f, 3.2005495)]       // retail quirk: only exactly 800 is capped (MovementSystem.c:19-32); (801/1001·11 + 4)/4
    public void RunRate_FollowsTheRunSkillAndBurden(int run, float burden, double expected) =>
        Assert.Equal(expected, RetailSkills.RunRate(run, burden), 5);

    // height = (Jump/(Jump + 1300) × 22.2 + 0.05) × extent, at least 0.35 m; speed = √(19.6 × height).
    [Theory]
    [InlineData(100, 0f, 0.35, 2.6191602)]        // floor: √6.86
    [InlineData(100, 0.5f, 0.8178571, 4.0037482)] // (100/1400·22.2 + 0.05)·0.5 = 1.6357143·0.5
    [InlineData(100, 1f, 1.6357143, 5.6621550)]
    [InlineData(300, 0f, 0.35, 2.6191602)]
    [InlineData(300, 0.5f, 2.10625, 6.4251459)]   // (300/1600·22.2 + 0.05)·0.5 = 4.2125·0.5
    [InlineData(300, 1f, 4.2125, 9.0865285)]
    public void JumpHeight_FollowsTheJumpSkillAndExtent_WithTheFloor(int jump, float extent, double height, double speed)
    {
        float h = RetailSkills.JumpHeight(jump, extent, 0f);
        Assert.Equal(height, h, 5);
        Assert.Equal(speed, RetailSkills.JumpVelocity(h), 4);
    }

    [Fact]
    public void JumpHeight_ClampsTheExtentToOne() =>
        Assert.Equal(RetailSkills.JumpHeight(300, 1f, 0f), RetailSkills.JumpHeight(300, 3f, 0f));

    [Theory]
    [InlineData(-1, 0, 0f, "runSkill")]
    [InlineData(0, -1, 0f, "jumpSkill")]
    [InlineData(0, 0, float.NaN, "burden")]
    [InlineData(0, 0, float.PositiveInfinity, "burden")]
    public void BadSkills_AreRefusedNamingTheField(int run, int jump, float burden, string field)
    {
        var ex = Assert.Throws<ArgumentException>(() => new RetailSkills(run, jump, burden));
        Assert.StartsWith(field + ":", ex.Message);
    }

    [Fact]
    public void WithNoStamina_BothSkillsCountAsZero()
    {
        // CACQualities::InqRunRate / InqJumpVelocity: stamina 0 → skill 0: run rate (0 + 4)/4 = 1, the 0.35 m floor jump √6.86.
        var tired = new RetailSkills(300, 300, hasStamina: false);
        Assert.True(tired.TryRunRate(out float rate));
        Assert.Equal(1f, rate);
        Assert.True(tired.TryJumpVelocity(1f, out float vz));
        Assert.Equal(2.6191602, vz, 5);
    }

    [Theory]
    [InlineData(1.99f, true)]
    [InlineData(2f, false)]
    public void LoadedDown_CannotJump(float burden, bool canJump) =>
        Assert.Equal(canJump, new RetailSkills(100, 100, burden).CanJump(0.5f)); // CACQualities::CanJump: load < 2
}
