using AcDream.Core.Physics.Managers;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>
/// Retail StickyManager (CStickyManager.c) from its constants: a retail player (radius 0.48, Run 200: max speed
/// 9.5 m/s) stuck to a target of radius 0.48 through the motion body step.
/// </summary>
public class StickyTests
{
    private const uint Target = 0x50000002;

    private static ManagerRig Stuck(float tx, float ty)
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Manager.UpdateTarget(Target, ManagerRig.At(tx, ty));
        return rig;
    }

    [Fact]
    public void StickyRadius_KeepsA30cmGapBetweenTheCylinders()
    {
        // Centres 1.6 m apart, radii 0.48 + 0.48: the gap 0.64 m closes to 0.3 m in one quantum (0.34 m < 47.5/30 m).
        var rig = Stuck(60f, 61.6f);
        rig.Frame();
        Assert.Equal(60.34f, rig.Origin.Y, 4);
        rig.Frames(5);
        Assert.Equal(60.34f, rig.Origin.Y, 4); // and stays
    }

    [Fact]
    public void ATargetTooClose_PushesTheObjectBackToTheGap()
    {
        var rig = Stuck(60f, 61.0f); // gap 0.04 m: backs away 0.26 m
        rig.Frame();
        Assert.Equal(61.0f - 1.26f, rig.Origin.Y, 4);
    }

    [Fact]
    public void TheCatchUpSpeed_IsFiveTimesTheMaxSpeed()
    {
        // get_max_speed × 5 = 9.5 × 5 = 47.5 m/s: 47.5/30 m a quantum towards a target 10 m away.
        var rig = Stuck(60f, 70f);
        rig.Frame();
        Assert.Equal(60f + 47.5f / 30f, rig.Origin.Y, 3);
    }

    [Fact]
    public void TheObject_TurnsToFaceTheTarget()
    {
        var rig = Stuck(61.6f, 60f); // due east: heading 90
        rig.Frame();
        InterpolationTests.AssertHeading(90f, rig.Heading);
        Assert.Equal(60.34f, rig.Origin.X, 4);
    }

    [Fact]
    public void WithoutATargetUpdate_TheStickWaits()
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Frames(3);
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
        Assert.False(rig.Manager.StickyTargetKnown);
        Assert.Equal(Target, rig.Manager.StickyTargetId);
    }

    [Fact]
    public void TheStick_EndsOneSecondAfterStickTo_TargetUpdatesDoNotExtendIt()
    {
        // StickTo at clock 0: timeout 1.0. The clock adds each quantum, (float)(1/30) = 0.0333333351: after 29 quanta
        // 0.967, after 30 quanta 1.0000000522 > 1.0, so UseTime ends the stick in quantum 30, target updates or not.
        var rig = Stuck(60f, 61.6f);
        for (int frame = 1; frame <= 29; frame++)
        {
            rig.Manager.UpdateTarget(Target, ManagerRig.At(60f + frame * 0.02f, 61.6f));
            rig.Frame();
            Assert.Equal(Target, rig.Manager.StickyTargetId);
        }
        rig.Manager.UpdateTarget(Target, ManagerRig.At(60.6f, 61.6f));
        rig.Frame();
        Assert.Equal(0u, rig.Manager.StickyTargetId);
        var stopped = rig.Origin;
        rig.Frames(3);
        Assert.Equal(stopped, rig.Origin);
    }

    [Fact]
    public void StickingAgain_RestartsTheSecond()
    {
        var rig = Stuck(60f, 61.6f);
        rig.Frames(20);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover); // timeout = 20 quanta + 1 s
        rig.Manager.UpdateTarget(Target, ManagerRig.At(60f, 61.6f));
        rig.Frames(29);
        Assert.Equal(Target, rig.Manager.StickyTargetId);
        rig.Frame();
        Assert.Equal(0u, rig.Manager.StickyTargetId);
    }

    [Theory]
    [InlineData(TargetStatus.ExitWorld)]
    [InlineData(TargetStatus.Teleported)]
    [InlineData(TargetStatus.TimedOut)]
    public void ALostTarget_EndsTheStick(TargetStatus status)
    {
        var rig = Stuck(60f, 61.6f);
        rig.Manager.LoseTarget(Target, status);
        Assert.Equal(0u, rig.Manager.StickyTargetId);
    }

    [Fact]
    public void UpdatesForAnotherObject_AreIgnored()
    {
        var rig = new ManagerRig(60f, 60f);
        rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
        rig.Manager.UpdateTarget(0x50000009, ManagerRig.At(60f, 61.6f));
        rig.Manager.LoseTarget(0x50000009, TargetStatus.ExitWorld);
        Assert.False(rig.Manager.StickyTargetKnown);
        Assert.Equal(Target, rig.Manager.StickyTargetId);
        rig.Frame();
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
    }

    [Fact]
    public void UnStick_EndsTheStick()
    {
        var rig = Stuck(60f, 61.6f);
        rig.Manager.UnStick();
        rig.Frame();
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
    }

    [Fact]
    public void StickySteps_AllocateNothingOnceWarm()
    {
        var rig = new ManagerRig(60f, 60f);
        int i = 0;
        void Round()
        {
            for (int k = 0; k < 30; k++, i++)
            {
                if (k == 0)
                    rig.Manager.StickTo(Target, 0.48f, 1.835f, rig.Mover);
                rig.Manager.UpdateTarget(Target, ManagerRig.At(60f + (i % 40) * 0.05f, 61.6f));
                rig.Frame();
            }
        }
        Assert.Equal(0, Support.Allocations.PerRound(Round, Round));
    }
}
