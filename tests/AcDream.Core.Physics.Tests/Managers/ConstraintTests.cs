using AcDream.Core.Physics.Managers;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>Retail ConstraintManager (CConstraintManager.c): the leash, from its rule, with 0.5 m offsets.</summary>
public class ConstraintTests
{
    private static readonly Position Here = new(0xA9B40013, new Vector3(60f, 60f, 0f));

    private static float Offset(ConstraintManager c, bool contact = true)
    {
        var f = new Frame(new Vector3(0.5f, 0f, 0f));
        c.AdjustOffset(ref f, contact);
        return f.Origin.X;
    }

    [Fact]
    public void PastTheStart_OffsetsShrinkLinearly_AndThePathLengthIsCounted()
    {
        // Start 1, max 2, from the constraint position: 0.5 (0.5), 0.5 (1.0), 0.5 (1.0 is not past 1: 1.5),
        // 0.5 × (2 − 1.5)/(2 − 1) = 0.25 (1.75), 0.5 × 0.25 = 0.125 (1.875: more than 90 % of 2).
        var c = new ConstraintManager();
        c.ConstrainTo(Here, 1f, 2f, Here);
        float[] expected = [0.5f, 0.5f, 0.5f, 0.25f, 0.125f];
        float[] counted = [0.5f, 1f, 1.5f, 1.75f, 1.875f];
        for (int i = 0; i < expected.Length; i++)
        {
            Assert.Equal(expected[i], Offset(c), 6);
            Assert.Equal(counted[i], c.Offset, 6);
            Assert.Equal(i == 4, c.IsFullyConstrained);
        }
    }

    [Fact]
    public void AtTheMax_TheOffsetIsZeroed()
    {
        var c = new ConstraintManager();
        c.ConstrainTo(Here, 1f, 2f, new Position(0xA9B40013, new Vector3(62.5f, 60f, 0f))); // already 2.5 m out
        Assert.Equal(0f, Offset(c));
        Assert.Equal(2.5f, c.Offset);
    }

    [Fact]
    public void OffTheGround_NothingIsScaled_ButItIsCounted()
    {
        var c = new ConstraintManager();
        c.ConstrainTo(Here, 1f, 2f, new Position(0xA9B40013, new Vector3(62.5f, 60f, 0f)));
        Assert.Equal(0.5f, Offset(c, contact: false));
        Assert.Equal(3f, c.Offset);
    }

    [Fact]
    public void ALeashedObject_SmoothedAway_StopsShortOfTheMax_UntilTheFailedNodeBlips()
    {
        // Through the body step: interpolation's 19/30 m offsets, then the leash (start 1, max 2) on the same offset.
        // Frames 1-9 stay inside 2 m; the progress check of frame 10 finds too little progress, the (last) node fails
        // and UseTime blips to it: SetPositionSimple does not pass through adjust_offset, so the leash does not hold it.
        var rig = new ManagerRig(100f, 84f);
        rig.Manager.ConstrainTo(rig.State.Position, 1f, 2f, rig.State);
        rig.InterpolateTo(100f, 94f);
        for (int frame = 1; frame <= 9; frame++)
        {
            rig.Frame();
            Assert.InRange(rig.Origin.Y - 84f, 0.6f, 2f);
        }
        Assert.True(rig.Manager.IsFullyConstrained);
        rig.Frame();
        Assert.Equal(94f, rig.Origin.Y);
        rig.Manager.UnConstrain();
        Assert.False(rig.Manager.IsConstrained);
    }
}
