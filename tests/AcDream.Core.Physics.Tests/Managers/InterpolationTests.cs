using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>
/// Retail InterpolationManager (CInterpolationManager.c) from its constants: a remote player (Run 200: run rate
/// 2.375, adjusted max speed 9.5 m/s) smoothed towards reported positions through the motion body step, and the
/// manager's rules on their own. Expected values are worked out from the constants in the comments.
/// </summary>
public class InterpolationTests
{
    private const float Q = (float)(1.0 / 30.0); // the quantum as the body step passes it

    private static ObjectView Still(float x, float y, float adjustedMaxSpeed = 0f, uint cell = 0xA9B40013, bool player = false) =>
        new(new Position(cell, new Vector3(x, y, 0f)), true, 0.48f, adjustedMaxSpeed / 2f, adjustedMaxSpeed, player);

    private static Position At(float x, float y) => new(0xA9B40013, new Vector3(x, y, 0f));

    [Fact]
    public void SpeedCap_IsTwiceTheAdjustedMaxSpeed_19MetresPerSecondForRun200()
    {
        // adjust_offset: my_max_speed = get_adjusted_max_speed × 2 = 4 × 2.375 × 2 = 19 m/s; one quantum moves 19/30 m.
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 94f);
        rig.Frame();
        Assert.Equal(84f + 19f * Q, rig.Origin.Y, 4);
        Assert.Equal(100f, rig.Origin.X, 4);
        rig.Frame();
        Assert.Equal(84f + 2 * 19f * Q, rig.Origin.Y, 4);
    }

    [Fact]
    public void SpeedCap_WithoutAMaxSpeed_IsMaxInterpolatedVelocity_7_5()
    {
        // my_max_speed below EPSILON falls back to MAX_INTERPOLATED_VELOCITY: 7.5 m/s × 1/30 s = 0.25 m.
        var m = new InterpolationManager();
        m.InterpolateTo(At(100f, 94f), false, Still(100f, 84f), out _);
        var offset = Frame.Identity;
        m.AdjustOffset(ref offset, Q, Still(100f, 84f), sticky: false);
        Assert.Equal(7.5f * Q, offset.Origin.Length(), 5);
        Assert.Equal(7.5f * Q, offset.Origin.Y, 5);
    }

    [Fact]
    public void APositionWithin5cmOfTheLastQueued_ReplacesIt()
    {
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 90f);
        rig.InterpolateTo(100f, 90.04f); // 0.04 m from the tail: the tail is removed, the new one queued
        Assert.Equal(1, rig.Manager.QueuedPositions);
        Assert.Equal(90.04f, rig.Manager.QueuedPosition(0).Frame.Origin.Y);
        rig.InterpolateTo(100f, 90.1f); // 0.06 m: a new node
        Assert.Equal(2, rig.Manager.QueuedPositions);
    }

    [Fact]
    public void APositionWithin5cmOfTheObject_StopsAndTakesItsHeading()
    {
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 90f);
        var here = ManagerRig.At(100.03f, 84f);
        here.Frame.Orientation = Headings.Facing(90f);
        rig.Manager.InterpolateTo(here, false, rig.Mover, ref rig.State);
        Assert.False(rig.Manager.IsInterpolating);
        Assert.Equal(90f, rig.Heading, 3);
        Assert.Equal(100f, rig.Origin.X); // only the heading is set
    }

    [Fact]
    public void TheQueue_HoldsAtMost20_TheOldestDropped()
    {
        var rig = new ManagerRig(100f, 84f);
        for (int i = 1; i <= 25; i++)
            rig.InterpolateTo(100f, 84f + i);
        Assert.Equal(20, rig.Manager.QueuedPositions);
        Assert.Equal(90f, rig.Manager.QueuedPosition(0).Frame.Origin.Y); // nodes 1..5 dropped
        Assert.Equal(109f, rig.Manager.QueuedPosition(19).Frame.Origin.Y);
    }

    [Fact]
    public void AFloodOfUpdates_StaysBounded()
    {
        var rig = new ManagerRig(100f, 84f);
        for (int i = 0; i < 10000; i++)
            rig.InterpolateTo(100f + (i % 7), 86f + (i % 13) * 0.5f);
        Assert.InRange(rig.Manager.QueuedPositions, 1, InterpolationManager.MaxNodes);
        for (int i = 0; i < 1000; i++) // far updates (each blips) do not grow it either
            rig.InterpolateTo(100f, i % 2 == 0 ? 84f : 190f, i % 2 == 0 ? ManagerRig.Block : ManagerRig.NorthBlock);
        Assert.InRange(rig.Manager.QueuedPositions, 1, InterpolationManager.MaxNodes);
    }

    [Fact]
    public void Progress_IsCheckedEvery5Frames_AgainstBigDistanceFirst_ThenTheLastDistance()
    {
        // An object that never moves: the check at frame 5 passes (original_distance starts at BIG_DISTANCE) and
        // stores 10 m; the check at frame 10 finds no progress and fails the node.
        var m = new InterpolationManager();
        var view = Still(100f, 84f);
        m.InterpolateTo(At(100f, 94f), false, view, out _);
        var offset = Frame.Identity;
        for (int frame = 1; frame <= 9; frame++)
            m.AdjustOffset(ref offset, Q, view, sticky: false);
        Assert.Equal(0, m.NodeFailCounter);
        Assert.Equal(10f, m.OriginalDistance, 4);
        m.AdjustOffset(ref offset, Q, view, sticky: false);
        Assert.Equal(1, m.NodeFailCounter);
        Assert.Equal(0, m.Count);
        // The last node failed: UseTime blips to it (retail NodeCompleted saves it in blipto_position).
        Assert.True(m.BlipTarget(out var target));
        Assert.Equal(94f, target.Frame.Origin.Y);
    }

    [Theory]
    [InlineData(0.38f, 0)] // 0.38 m in 5 quanta at 7.5 m/s: 0.38 / (5/30) / 7.5 = 0.304 ≥ 0.3, passes
    [InlineData(0.37f, 1)] // 0.296 < 0.3: the node fails
    public void Progress_MustBe30PercentOfTheMaxSpeed(float moved, int failed)
    {
        var m = new InterpolationManager();
        m.InterpolateTo(At(100f, 94f), false, Still(100f, 84f), out _);
        m.InterpolateTo(At(100f, 95f), false, Still(100f, 84f), out _);
        var offset = Frame.Identity;
        for (int frame = 1; frame <= 5; frame++)
            m.AdjustOffset(ref offset, Q, Still(100f, 84f), sticky: false);
        for (int frame = 6; frame <= 10; frame++)
            m.AdjustOffset(ref offset, Q, Still(100f, 84f + moved * (frame - 5) / 5f), sticky: false);
        Assert.Equal(failed, m.NodeFailCounter);
        Assert.Equal(2 - failed, m.Count);
    }

    [Fact]
    public void ANodeThatStopsProgressingWithin20cm_CountsAsReached_NoBlip()
    {
        // 0.15 m from the node (more than 0.05, so not reached) and not moving: the check of frame 10 fails the progress
        // rule, but curr_distance < 0.2 completes the node as a success: the queue ends, nothing to blip.
        var m = new InterpolationManager();
        var view = Still(100f, 93.85f);
        m.InterpolateTo(At(100f, 94f), false, view, out _);
        var offset = Frame.Identity;
        for (int frame = 1; frame <= 10; frame++)
            m.AdjustOffset(ref offset, Q, view, sticky: false);
        Assert.Equal(0, m.Count);
        Assert.Equal(0, m.NodeFailCounter);
        Assert.False(m.BlipTarget(out _));
    }

    [Fact]
    public void WhileSticky_TheProgressCheckAlwaysPasses()
    {
        var m = new InterpolationManager();
        m.InterpolateTo(At(100f, 94f), false, Still(100f, 84f), out _);
        var offset = Frame.Identity;
        for (int frame = 1; frame <= 20; frame++)
            m.AdjustOffset(ref offset, Q, Still(100f, 84f), sticky: true);
        Assert.Equal(0, m.NodeFailCounter);
    }

    [Fact]
    public void Blip_ComesAfterTheFourthFailedNode_ToTheNewest()
    {
        // Six nodes 1 m apart, an object that never moves: node 1 fails at frame 10 (the check at 5 passes on
        // BIG_DISTANCE), then each next node at its own 5th frame (original_distance = the distance to it):
        // 15, 20, 25. After 3 failures no blip; after the fourth (node_fail_counter 4 > 3) the blip goes to the tail.
        var m = new InterpolationManager();
        var view = Still(100f, 84f);
        for (int i = 0; i < 6; i++)
            m.InterpolateTo(At(100f, 90f + i), false, view, out _);
        var offset = Frame.Identity;
        for (int frame = 1; frame <= 24; frame++)
        {
            m.AdjustOffset(ref offset, Q, view, sticky: false);
            Assert.False(m.BlipTarget(out _), $"frame {frame}");
        }
        Assert.Equal(3, m.NodeFailCounter);
        m.AdjustOffset(ref offset, Q, view, sticky: false);
        Assert.Equal(4, m.NodeFailCounter);
        Assert.True(m.BlipTarget(out var target));
        Assert.Equal(95f, target.Frame.Origin.Y);
    }

    [Theory]
    [InlineData(0xA9B40013u, false, 100f)]
    [InlineData(0xA9B40013u, true, 100f)]
    [InlineData(0xA9B40100u, true, 25f)]
    [InlineData(0xA9B40100u, false, 20f)]
    public void AutonomyBlipDistance_Outdoors100_Indoors25ForThePlayer20ForOthers(uint cell, bool player, float expected) =>
        Assert.Equal(expected, Still(10f, 10f, 0f, cell, player).AutonomyBlipDistance);

    [Theory]
    [InlineData(99.5f, 0)]
    [InlineData(100.5f, 4)]
    public void AnUpdateBeyondTheBlipDistance_FailsAtOnce(float distance, int failed)
    {
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 84f + distance);
        Assert.Equal(failed, rig.Manager.FailedNodes);
        Assert.Equal(1, rig.Manager.QueuedPositions);
    }

    [Fact]
    public void ATeleport150mAway_IsPlacedThereAtTheNextStep_InTheNeighbourLandblock()
    {
        // From (100, 101.5) in 0xA9B4 to 0xA9B5 (100, 59.5): 192 − 101.5 + 59.5 = 150 m > 100 m.
        var rig = new ManagerRig(100f, 101.5f);
        rig.InterpolateTo(100f, 59.5f, ManagerRig.NorthBlock);
        rig.Frame();
        Assert.Equal(ManagerRig.NorthBlock, rig.State.Position.CellId >> 16);
        AssertPlacedAt(100f, 59.5f, rig);
        Assert.False(rig.Manager.IsInterpolating);
    }

    [Fact]
    public void SmoothingAcrossALandblockEdge_MovesThroughTheTransition()
    {
        // 0xA9B4 (100, 189) to 0xA9B5 (100, 2): 5 m, 19/30 m a quantum, 8 quanta.
        var rig = new ManagerRig(100f, 189f);
        rig.InterpolateTo(100f, 2f, ManagerRig.NorthBlock);
        rig.Frames(10);
        Assert.Equal(ManagerRig.NorthBlock, rig.State.Position.CellId >> 16);
        Assert.Equal(2f, rig.Origin.Y, 3);
        Assert.False(rig.Manager.IsInterpolating);
    }

    [Fact]
    public void AnUpdateBehindAWall_StopsAtTheWall_ThenBlipsWhenTheNodeFails()
    {
        // The door slab's −Y face is at y 99.991; the player's radius 0.48. From y 96 at 19/30 m a quantum the object
        // reaches the slab in frame 6 and stays (the transition), the progress check of frame 10 finds 0.26 m made
        // since frame 5 (< 30 % of 19 m/s × 5/30 s = 0.95 m), the node (the last) fails and UseTime blips to it.
        var rig = new ManagerRig(100f, 96f);
        rig.InterpolateTo(100f, 101.5f);
        for (int frame = 1; frame <= 9; frame++)
        {
            rig.Frame();
            Assert.True(rig.Origin.Y < 99.991f - 0.48f + 0.01f, $"frame {frame}: y {rig.Origin.Y} is in the door");
        }
        Assert.True(rig.Origin.Y > 99.4f, $"stopped short at y {rig.Origin.Y}");
        rig.Frame();
        AssertPlacedAt(100f, 101.5f, rig);
        Assert.False(rig.Manager.IsInterpolating);
    }

    [Fact]
    public void KeepHeading_QueuesTheNodeWithTheObjectsHeading_AndTheOffsetDoesNotTurn()
    {
        var rig = new ManagerRig(100f, 84f);
        var p = ManagerRig.At(104f, 84f);
        p.Frame.Orientation = Headings.Facing(200f);
        rig.Manager.InterpolateTo(p, true, rig.Mover, ref rig.State);
        AssertHeading(0f, Headings.Of(rig.Manager.QueuedPosition(0).Frame));
        rig.Frames(3);
        AssertHeading(0f, rig.Heading);
        var other = new ManagerRig(100f, 84f);
        other.Manager.InterpolateTo(p, false, other.Mover, ref other.State);
        other.Frame(); // without keep-heading the offset carries the node's rotation: the object turns at once
        AssertHeading(200f, other.Heading);
    }

    // Retail's placement (SetPositionSimple) settles the object 0.005 m above the floor, as the ACE recordings show.
    internal static void AssertPlacedAt(float x, float y, ManagerRig rig)
    {
        Assert.Equal(x, rig.Origin.X);
        Assert.Equal(y, rig.Origin.Y);
        Assert.InRange(rig.Origin.Z, 0f, 0.01f);
    }

    internal static void AssertHeading(float expected, float actual)
    {
        float d = MathF.Abs(expected - actual) % 360f;
        Assert.True(MathF.Min(d, 360f - d) < 0.01f, $"heading {actual}, expected {expected}");
    }

    [Fact]
    public void StopInterpolating_EmptiesTheQueue_AndTheObjectStays()
    {
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 94f);
        rig.Frame();
        rig.Manager.StopInterpolating();
        var y = rig.Origin.Y;
        rig.Frames(5);
        Assert.Equal(y, rig.Origin.Y);
        Assert.Equal(0, rig.Manager.QueuedPositions);
    }

    [Fact]
    public void OutOfOrderUpdates_AreQueuedAsGiven()
    {
        // Retail discards stale updates before InterpolateTo (MoveOrTeleport's timestamps); the manager follows the order given.
        var rig = new ManagerRig(100f, 84f);
        rig.InterpolateTo(100f, 88f);
        rig.InterpolateTo(100f, 86f);
        Assert.Equal(86f, rig.Manager.QueuedPosition(1).Frame.Origin.Y);
        rig.Frames(30);
        Assert.Equal(86f, rig.Origin.Y, 3);
    }

    [Fact]
    public void SmoothingSteps_AllocateNothingOnceWarm()
    {
        var rig = new ManagerRig(100f, 60f);
        int i = 0;
        void Round()
        {
            for (int k = 0; k < 30; k++)
            {
                if (k % 6 == 0)
                    rig.InterpolateTo(100f + (i++ % 3) * 0.3f, 60f + (i % 5) * 0.8f);
                rig.Frame();
            }
        }
        Assert.Equal(0, Allocations.PerRound(Round, Round));
    }
}
