using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// Retail's MoveToManager (CMoveToManager.c) through the motion layer and the body step: the defaults, the walk/run
/// switch, the progress rule, arrival, the turn's snap, cancel, a blocked creature giving up, and bad input. Expected
/// values come from the decompile's constants, worked by hand in the comments.
/// </summary>
public class MoveToTests
{
    private static MotionRig Rig(PhysicsWorld? world = null, float x = 60f, float y = 60f)
    {
        var rig = world is null ? new MotionRig() : new MotionRig(world, x, y);
        rig.Motion.SetCylinder(0.48f, 1.835f);
        return rig;
    }

    private static int RunUntilEnded(MotionRig rig, int maxFrames)
    {
        for (int f = 0; f < maxFrames; f++)
        {
            rig.Frames(1);
            if (rig.Motion.MoveToStatus == MoveToStatus.Ended)
                return f;
        }
        return -1;
    }

    // The arrival band of a straight run at the target: HandleMoveToPosition (acclient.c:345576) tests the distance only
    // after each quantum, so a quantum's step of more than twice the arrival distance (DistanceToObject 0.6 plus the
    // mover's radius 0.48, the cylinder distance) can pass over the band. Run skill 200: run rate (0.5 × 11 + 4) / 4 =
    // 2.375 (MovementSystem::GetRunRate), so a step of RunAnimSpeed 4 × 2.375 × Speed / 30 = 0.3167 × Speed m: 1.90 m at
    // Speed 6 (within 2 × 1.08 = 2.16 m), 2.22 m at Speed 7 (beyond it).
    private static (int Arrived, float Closest, float Farthest) RunThirtyMetres(float speed, int frames)
    {
        var rig = Rig();
        var target = TestGeometry.At(60f, 90f, 0f);
        rig.Motion.MoveToPosition(target, MoveToParameters.Default with { Speed = speed }, rig.Mover, rig.State, rig.Body);
        float closest = float.MaxValue, farthest = 0f;
        for (int f = 0; f < frames; f++)
        {
            rig.Frames(1);
            float d = Vector2.Distance(new Vector2(rig.Origin.X, rig.Origin.Y), new Vector2(60f, 90f));
            closest = Math.Min(closest, d);
            if (f >= 30 * 10)
                farthest = Math.Max(farthest, d); // once past the first pass, how far it strays
            if (rig.Motion.MoveToStatus == MoveToStatus.Ended)
                return (f, closest, farthest);
        }
        return (-1, closest, farthest);
    }

    [Theory]
    [InlineData(1f)]
    [InlineData(6f)]
    public void AThirtyMetreRun_Arrives_WhileOneQuantumsStepIsWithinTheArrivalBand(float speed)
    {
        var (arrived, _, _) = RunThirtyMetres(speed, 30 * 60);
        Assert.True(arrived >= 0, $"Speed {speed}: a step of {0.3167f * speed:0.00} m a quantum is within the 2.16 m band, yet the move did not arrive in 60 s");
    }

    [Fact]
    public void RetailQuirk_AFasterRunCanPassOverTheArrivalBand_AndThenCirclesTheTarget()
    {
        // Retail's behaviour beyond the band (MoveToParameters.Speed): whether a quantum ends in the band depends on where
        // the steps fall (Speed 7 and 8 happen to land in it here); nothing catches a pass, the aim correction turns the
        // runner back (acclient.c:345576) and the client's CountOnly rule never gives up, so a runner that passed goes on
        // round the target for ever, never farther than about a step and a half from it. Speed 100: 31.7 m a quantum,
        // over the 30 m target at the first step.
        const float step = 0.3167f * 100f;
        var (arrived, closest, farthest) = RunThirtyMetres(100f, 30 * 60);
        Assert.Equal(-1, arrived);
        Assert.True(closest < step, $"the runner never came back within a step of the target (closest {closest} m)");
        Assert.True(farthest < 1.5f * step, $"the runner strayed {farthest} m from the target");
    }

    [Fact]
    public void Defaults_AreRetailsConstructor()
    {
        // MovementParameters::MovementParameters (acclient.c:339436): 0x3F19999A = 0.6, 0x7F7FFFFF = float.MaxValue,
        // 0x41700000 = 15, bitfield 0x1EE0F.
        var p = MoveToParameters.Default;
        Assert.Equal(0.6f, p.DistanceToObject);
        Assert.Equal(0f, p.MinDistance);
        Assert.Equal(float.MaxValue, p.FailDistance);
        Assert.Equal(1f, p.Speed);
        Assert.Equal(15f, p.WalkRunThreshold);
        Assert.Equal((MoveToFlags)0x1EE0F, p.Flags);
        Assert.Equal(HoldKey.Invalid, p.HoldKey);
    }

    [Theory]
    // get_command: Run when distance − 0.6 > 15, else walk (CanWalk and CanRun, no CanCharge).
    [InlineData(15.6f, HoldKey.None)]
    [InlineData(15.61f, HoldKey.Run)]
    [InlineData(10f, HoldKey.None)]
    public void WalkRunSwitch_IsAtTheThresholdBeyondTheDistanceToObject(float distance, HoldKey expected)
    {
        MoveToParameters.Default.GetCommand(distance, out uint command, out var key, out bool away);
        Assert.Equal(MotionCommand.WalkForward, command);
        Assert.False(away);
        Assert.Equal(expected, key);
    }

    [Fact]
    public void AMoveOfTenMetres_Walks_AndOfTwentyRuns()
    {
        // Facing the target already (heading 0, target straight ahead): the turn node ends at once and the move begins.
        var walker = Rig();
        walker.Motion.MoveToPosition(TestGeometry.At(60f, 70f, 0f), MoveToParameters.Default, walker.Mover, walker.State, walker.Body);
        Assert.Equal(MotionCommand.WalkForward, walker.Motion.Interpreted.ForwardCommand); // 10 − 0.48 − 0.6 < 15: walk
        var runner = Rig();
        runner.Motion.MoveToPosition(TestGeometry.At(60f, 90f, 0f), MoveToParameters.Default, runner.Mover, runner.State, runner.Body);
        Assert.Equal(MotionCommand.RunForward, runner.Motion.Interpreted.ForwardCommand); // 30 − 0.48 − 0.6 > 15: run
    }

    [Fact]
    public void ProgressRule_FailsBelowAQuarterMetrePerSecondOverMoreThanOneSecond()
    {
        var motion = new ObjectMotion(MotionTables.Humanoid());
        var m = new MoveToManager(motion.Interpreter, motion.Manager)
        {
            PreviousDistance = 10f, PreviousDistanceTime = 0.0, OriginalDistance = 10f, OriginalDistanceTime = 0.0,
        };
        m.Now = 1.0;
        Assert.True(m.CheckProgressMade(10f)); // not more than 1 s yet: no judgement
        m.Now = 1.25;
        Assert.False(m.CheckProgressMade(9.75f)); // 0.25 m in 1.25 s = 0.2 m/s < 0.25
        Assert.Equal(10f, m.PreviousDistance);      // the sample is kept after a failure
        Assert.True(m.CheckProgressMade(9.6f));     // 0.4 m in 1.25 s = 0.32 m/s; overall the same
        Assert.Equal(9.6f, m.PreviousDistance);
        Assert.Equal(1.25, m.PreviousDistanceTime);
    }

    [Fact]
    public void AMoveArrives_AtTheDistanceToObject()
    {
        // Origins' distance (no UseSpheres), 10 m ahead, walking 3.12 m/s = 0.104 m a quantum: it stops at the first
        // quantum whose distance is at most 0.6, so between 0.6 − 0.104 and 0.6.
        var rig = Rig();
        var p = MoveToParameters.Default with { Flags = MoveToFlags.RetailDefault & ~MoveToFlags.UseSpheres };
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 70f, 0f), p, rig.Mover, rig.State, rig.Body);
        int ended = RunUntilEnded(rig, 200);
        Assert.InRange(ended, 80, 100);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        float distance = Vector2.Distance(new Vector2(rig.Origin.X, rig.Origin.Y), new Vector2(60f, 70f));
        Assert.InRange(distance, 0.6f - 0.11f, 0.6f);
        Assert.Equal(MotionCommand.Ready, rig.Motion.Interpreted.ForwardCommand);
    }

    /// <summary>
    /// HandleMoveToPosition (acclient.c:345576) turns while moving only for an aim error above 20° either way: the
    /// error is taken in 0..360, so a body facing 10° right of its target (error 350) does not turn, one facing 30°
    /// right of it (error 330) turns left, and the mirror cases. The target is due north (heading 0).
    /// </summary>
    // The interpreted turn is TurnRight with a negative speed for a left turn (adjust_motion), so the sign tells them apart.
    [Theory]
    [InlineData(10f, 0)]
    [InlineData(30f, -1)]
    [InlineData(350f, 0)]
    [InlineData(330f, 1)]
    public void WhileMoving_AnAimErrorWithin20DegreesEitherWay_DoesNotTurn(float heading, int expectedTurn)
    {
        var rig = Rig();
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 90f, 0f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        rig.Frames(40); // any first turn done, running north
        Assert.Equal(0u, rig.Motion.Interpreted.TurnCommand);
        rig.State.Position.Frame = new Frame(rig.State.Position.Frame.Origin, Headings.Facing(heading));
        rig.Frames(1);
        var interpreted = rig.Motion.Interpreted;
        int turn = interpreted.TurnCommand == 0 ? 0 : Math.Sign(interpreted.TurnSpeed);
        Assert.True(interpreted.TurnCommand is 0 or MotionCommand.TurnRight, $"turn command 0x{interpreted.TurnCommand:X8}");
        Assert.Equal(expectedTurn, turn);
    }

    [Fact]
    public void TurnToHeading_TurnsThreeDegreesAQuantum_ThenSnapsExactly()
    {
        // TurnRight at speed 1: π/2 rad/s = 3° per 1/30 s quantum; 90° is passed on the 31st quantum's check
        // (heading_greater), which sets the heading to 90 exactly (set_heading).
        var rig = Rig();
        rig.Motion.TurnToHeading(MoveToParameters.Default with { DesiredHeading = 90f }, rig.Mover, rig.State, rig.Body);
        Assert.Equal(MotionCommand.TurnRight, rig.Motion.Interpreted.TurnCommand);
        int ended = RunUntilEnded(rig, 100);
        Assert.InRange(ended, 29, 31);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        Assert.Equal(Headings.Facing(90f), rig.State.Position.Frame.Orientation);
        Assert.Equal(0u, rig.Motion.Interpreted.TurnCommand);
    }

    [Fact]
    public void Cancel_EndsTheMove_AndStopsTheCreature()
    {
        var rig = Rig();
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 90f, 0f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        rig.Frames(10);
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        rig.Motion.CancelMoveTo(rig.Mover, rig.State, rig.Body);
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.ActionCancelled, rig.Motion.MoveToResult);
        Assert.Equal(MotionCommand.Ready, rig.Motion.Interpreted.ForwardCommand);
        Assert.Equal(MoveToKind.Invalid, rig.Motion.MoveToKind);
    }

    [Fact]
    public void AStuckCreature_UnderTheServerRule_GivesUpWithinRetailsTime_ThenCostsNoTransitions()
    {
        // GiveUp is opt-in (the server's cancel of a creature that makes no progress, not the client's manager).
        // Running at the door's slab from 12 m away (9.5 m/s): blocked after about 1.2 s (frame 35). CheckProgressMade
        // judges windows longer than 1 s, so the first window wholly spent against the slab fails at most two windows
        // (2 × 31 quanta) after the stop; the give-up rule waits one more window of failing checks: the move ends with
        // CantGetThere by frame 35 + 3 × 31 = 128.
        var rig = Rig(Bench.DoorScene.Create().World, 100f, 88f);
        rig.Motion.MoveToProgressRule = MoveToProgressRule.GiveUp;
        rig.Motion.MoveToPosition(TestGeometry.At(100f, 104f, 0f), MoveToParameters.Default with { WalkRunThreshold = 1f }, rig.Mover, rig.State, rig.Body);
        int ended = RunUntilEnded(rig, 300);
        Assert.InRange(ended, 40, 128);
        Assert.Equal(MoveToError.CantGetThere, rig.Motion.MoveToResult);
        var at = rig.Origin;
        int transitions = 0;
        for (int i = 0; i < 60; i++)
        {
            var r = rig.Engine.Step(rig.Mover, rig.State, rig.Body, rig.Motion, 1.0 / 30.0);
            rig.State = r.Next;
            rig.Body = r.Body;
            transitions += r.Transitions;
        }
        Assert.Equal(0, transitions);
        Assert.Equal(at, rig.Origin);
    }

    [Fact]
    public void TheDefault_IsTheClientsCountOnly_AndABlockedMoveKeepsRunningInPlace()
    {
        // Retail's CMoveToManager adds one to fail_progress_count per failed check (acclient.c:345659) and never reads
        // it, so nothing in the client ends a blocked move. Same run as the give-up test, default rule: blocked by frame
        // 35, its first failed check at most two windows later (35 + 2 × 31 = 97), then one more failure per quantum
        // (the run motion is no longer pending): by frame 200 at least 200 - 97 = 103 failures, the move still on.
        var rig = Rig(Bench.DoorScene.Create().World, 100f, 88f);
        Assert.Equal(MoveToProgressRule.CountOnly, rig.Motion.MoveToProgressRule);
        Assert.Equal(MoveToProgressRule.CountOnly, default(MoveToProgressRule));
        rig.Motion.MoveToPosition(TestGeometry.At(100f, 104f, 0f), MoveToParameters.Default with { WalkRunThreshold = 1f }, rig.Mover, rig.State, rig.Body);
        rig.Frames(150);
        var stuckAt = rig.Origin;
        int countAt150 = rig.Motion.MoveToFailProgressCount;
        rig.Frames(50);
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Interpreted.ForwardCommand); // still running into the slab
        Assert.True(rig.Motion.MoveToFailProgressCount >= 103, $"fail count {rig.Motion.MoveToFailProgressCount}");
        Assert.Equal(countAt150 + 50, rig.Motion.MoveToFailProgressCount); // one per quantum, never reset
        Assert.Equal(stuckAt.Y, rig.Origin.Y, 3); // in place against the slab
    }

    [Fact]
    public void AnObjectUpdate_KeepsTwoPositions_TheTurnAimsAtTheInterpolatedOne_TheDistanceIsToTheTarget()
    {
        // MoveToObject_Internal (acclient.c:345858) and HandleUpdateTarget (346050): sought_position is the update's
        // interpolated position, current_target_position the target's own. The first turn is aimed at the interpolated
        // (64, 72): from (60, 60) that is compass atan2(4, 12) = 18.435°; the move's distance is GetCurrentDistance to the
        // target (60, 72): a cylinder gap of 12 − 0.48 − 0.48 = 11.04 m (to the interpolated one it would be 11.689 m).
        var rig = Rig();
        var target = TestGeometry.At(60f, 72f, 0f);
        var interpolated = TestGeometry.At(64f, 72f, 0f);
        rig.Motion.MoveToObject(0x50000002, 0.48f, 1.835f, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.True(rig.Motion.UpdateMoveToTarget(0x50000002, target, interpolated, rig.Mover, rig.State, rig.Body));
        var m = rig.Motion.MoveToManagerState!;
        Assert.Equal(interpolated.Frame.Origin, m.SoughtPosition.Frame.Origin);
        Assert.Equal(target.Frame.Origin, m.CurrentTargetPosition.Frame.Origin);
        for (int f = 0; f < 60 && m.CurrentCommand != MotionCommand.WalkForward; f++)
            rig.Frames(1);
        Assert.Equal(MotionCommand.WalkForward, m.CurrentCommand); // the turn ended, the walk began (BeginMoveForward)
        Assert.Equal(18.435, Headings.Of(rig.State.Position.Frame), 2);
        Assert.Equal(11.04f, m.OriginalDistance, 3);
    }

    [Fact]
    public void AFailedProgressCheck_IsNotCountedWhileInterpolating()
    {
        // HandleMoveToPosition (acclient.c:345659): ++fail_progress_count only when !IsInterpolating && !motions_pending.
        // The blocked run of the count-only test; at frame 150 a position behind the slab is queued for interpolation:
        // while the queue holds it (its node fails its own checks until the interpolation blips, CInterpolationManager)
        // the move's failing checks add nothing; before, one a quantum.
        var rig = Rig(Bench.DoorScene.Create().World, 100f, 88f);
        rig.Motion.MoveToPosition(TestGeometry.At(100f, 104f, 0f), MoveToParameters.Default with { WalkRunThreshold = 1f }, rig.Mover, rig.State, rig.Body);
        rig.Frames(150);
        int before = rig.Motion.MoveToFailProgressCount;
        Assert.True(before > 0, "the blocked move fails its checks before the interpolation");
        rig.Motion.PositionManager.InterpolateTo(TestGeometry.At(100f, 101.5f, 0f), keepHeading: true, rig.Mover, ref rig.State);
        int interpolatingFrames = 0;
        while (rig.Motion.PositionManager.IsInterpolating && interpolatingFrames < 100)
        {
            int count = rig.Motion.MoveToFailProgressCount;
            rig.Frames(1);
            if (rig.Motion.PositionManager.IsInterpolating)
                Assert.Equal(count, rig.Motion.MoveToFailProgressCount);
            interpolatingFrames++;
        }
        Assert.True(interpolatingFrames >= 5, $"interpolated for {interpolatingFrames} frames");
        // The last quantum counts once: its failed node leaves the queue in adjust_offset (NodeCompleted, before
        // MoveToManager::UseTime), and UseTime's blip follows (acclient.c:388881, 389277). Without the rule: one a quantum.
        Assert.Equal(before + 1, rig.Motion.MoveToFailProgressCount);
    }

    [Theory]
    // A MoveToObject re-aimed by target updates (HandleUpdateTarget, acclient.c:346050, sets previous_distance_time and
    // original_distance_time to now): CheckProgressMade (344832) judges only after more than 1 s since the last sample,
    // so updates every 0.5 s never let it judge: a mover blocked by the slab never counts a failure. With updates every
    // 2 s the checks run between them and fail.
    [InlineData(15, false)]
    [InlineData(60, true)]
    public void UpdatesMoreOftenThanOnceASecond_NeverLetTheProgressCheckJudge(int framesBetweenUpdates, bool expectFailures)
    {
        var rig = Rig(Bench.DoorScene.Create().World, 100f, 88f);
        var behindTheSlab = TestGeometry.At(100f, 104f, 0f);
        rig.Motion.MoveToObject(0x50000002, 0.48f, 1.835f, MoveToParameters.Default with { WalkRunThreshold = 1f }, rig.Mover, rig.State, rig.Body);
        int most = 0, judged = 0;
        for (int f = 0; f < 300; f++)
        {
            if (f % framesBetweenUpdates == 0)
                rig.Motion.UpdateMoveToTarget(0x50000002, behindTheSlab, rig.Mover, rig.State, rig.Body);
            rig.Frames(1);
            most = Math.Max(most, rig.Motion.MoveToFailProgressCount);
            // A judgement takes a new sample (previous_distance = the distance); an update leaves float.MaxValue there.
            if (f > framesBetweenUpdates && rig.Motion.MoveToManagerState!.PreviousDistance != float.MaxValue)
                judged++;
        }
        Assert.True(rig.Origin.Y < 99.6f, $"blocked by the slab, at {rig.Origin}");
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        if (expectFailures)
        {
            Assert.True(most > 0, "updates every 2 s: the checks between them fail");
        }
        else
        {
            Assert.Equal(0, most);
            Assert.Equal(0, judged); // never judged at all, not judged and passed
        }
    }

    [Fact]
    public void BadTargets_AreRefusedByName_AndChangeNothing()
    {
        var rig = Rig();
        var nan = new Position(rig.State.Position.CellId, new Vector3(float.NaN, 60f, 0f));
        var ex = Assert.Throws<ArgumentException>(() => rig.Motion.MoveToPosition(nan, MoveToParameters.Default, rig.Mover, rig.State, rig.Body));
        Assert.Contains("target", ex.Message);
        var outside = new Position(0xFFFF0001, new Vector3(10f, 10f, 0f));
        Assert.Throws<ArgumentException>(() => rig.Motion.MoveToPosition(outside, MoveToParameters.Default, rig.Mover, rig.State, rig.Body));
        var bad = MoveToParameters.Default with { Speed = float.NaN };
        ex = Assert.Throws<ArgumentException>(() => rig.Motion.MoveToPosition(TestGeometry.At(60f, 70f, 0f), bad, rig.Mover, rig.State, rig.Body));
        Assert.Contains("Speed", ex.Message);
        Assert.Equal(MoveToStatus.Idle, rig.Motion.MoveToStatus);
    }

    [Fact]
    public void AFarTarget_IsWalkedTowards_UntilTheFailDistance()
    {
        // 50 km away is a valid place; with FailDistance 5 m the move ends with YouChargedTooFar once 5 m from the start.
        var rig = Rig();
        var far = new Position(0x7F7F0001, new Vector3(10f, 10f, 0f));
        rig.Motion.MoveToPosition(far, MoveToParameters.Default with { FailDistance = 5f }, rig.Mover, rig.State, rig.Body);
        int ended = RunUntilEnded(rig, 300);
        Assert.True(ended > 0);
        Assert.Equal(MoveToError.YouChargedTooFar, rig.Motion.MoveToResult);
        Assert.True(float.IsFinite(rig.Origin.X) && float.IsFinite(rig.Origin.Y));
    }

    [Fact]
    public void AnUnknownTarget_EndsWithNoObject_ALostOneWithObjectGone()
    {
        var rig = Rig();
        rig.Motion.MoveToObject(0x50000002, 0.48f, 1.835f, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.Equal(MoveToStatus.WaitingForTarget, rig.Motion.MoveToStatus);
        rig.Frames(5); // nothing moves before the first update
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
        Assert.True(rig.Motion.MoveToTargetGone(0x50000002, rig.Mover, rig.State, rig.Body));
        Assert.Equal(MoveToError.NoObject, rig.Motion.MoveToResult);

        rig.Motion.MoveToObject(0x50000002, 0.48f, 1.835f, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.True(rig.Motion.UpdateMoveToTarget(0x50000002, TestGeometry.At(60f, 80f, 0f), rig.Mover, rig.State, rig.Body));
        rig.Frames(5);
        Assert.True(rig.Motion.MoveToTargetGone(0x50000002, rig.Mover, rig.State, rig.Body));
        Assert.Equal(MoveToError.ObjectGone, rig.Motion.MoveToResult);
    }

    [Fact]
    public void TheMoverAsItsOwnTarget_EndsAtOnce_WithNoMove()
    {
        var rig = Rig();
        rig.Motion.MoveToObject(rig.Mover.ObjectId, 0.48f, 1.835f, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.Equal(MoveToStatus.Ended, rig.Motion.MoveToStatus);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        rig.Frames(10);
        Assert.Equal(new Vector3(60f, 60f, 0f), rig.Origin);
    }

    [Fact]
    public void AFloodOfUpdates_KeepsOnlyTheNewest_AndAllocatesNothing()
    {
        // Updates out of time order are applied as they arrive (retail's HandleUpdateTarget has no clock): the last wins.
        var rig = Rig();
        rig.Motion.MoveToObject(0x50000002, 0.48f, 1.835f, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        rig.Motion.UpdateMoveToTarget(0x50000002, TestGeometry.At(60f, 80f, 0f), rig.Mover, rig.State, rig.Body);
        Assert.False(rig.Motion.UpdateMoveToTarget(0x50000009, TestGeometry.At(70f, 80f, 0f), rig.Mover, rig.State, rig.Body));
        var target = TestGeometry.At(60f, 80f, 0f);
        void Flood()
        {
            for (int i = 0; i < 10_000; i++)
                rig.Motion.UpdateMoveToTarget(0x50000002, target, rig.Mover, rig.State, rig.Body);
        }
        Assert.Equal(0, Allocations.PerRound(Flood, Flood));
        Assert.Equal(MoveToStatus.Moving, rig.Motion.MoveToStatus);
        Assert.Equal(1, rig.Motion.MoveToNodeCount); // the move (facing it already, the turn ended at once): no growth
    }

    [Fact]
    public void TheStepWithAMoveToActive_AllocatesNothingOnceWarm()
    {
        var rig = Rig();
        void Round()
        {
            rig.Motion.MoveToPosition(TestGeometry.At(rig.Origin.X + 5f, rig.Origin.Y + 8f, 0f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
            rig.Frames(40);
        }
        Assert.Equal(0, Allocations.PerRound(Round, Round));
    }

    [Fact]
    public void TurnToObject_FacesTheObjectOnceItsPositionArrives()
    {
        // Heading from (60, 60) to (70, 60): east, 90 (Position::heading); TurnRight, then snapped to it.
        var rig = Rig();
        rig.Motion.TurnToObject(0x50000002, MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        Assert.Equal(MoveToStatus.WaitingForTarget, rig.Motion.MoveToStatus);
        rig.Motion.UpdateMoveToTarget(0x50000002, TestGeometry.At(70f, 60f, 0f), rig.Mover, rig.State, rig.Body);
        Assert.Equal(MotionCommand.TurnRight, rig.Motion.MoveToCommand);
        RunUntilEnded(rig, 100);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        Assert.Equal(Headings.Facing(90f), rig.State.Position.Frame.Orientation);
    }

    [Fact]
    public void MoveAway_WalksUntilTheMinDistance()
    {
        // MoveAway alone: WalkForward while closer than MinDistance (get_command), aiming 180° from the point
        // (get_desired_heading), so it turns about while walking; done once the cylinder distance is at least 5 m.
        // Under the opt-in GiveUp rule too: the checks failing while it turns about are a passing dip, not a give-up
        // (the client's default never gives up at all).
        var rig = Rig();
        rig.Motion.MoveToProgressRule = MoveToProgressRule.GiveUp;
        var p = MoveToParameters.Default with { Flags = (MoveToFlags.RetailDefault & ~MoveToFlags.MoveTowards) | MoveToFlags.MoveAway, MinDistance = 5f };
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 62f, 0f), p, rig.Mover, rig.State, rig.Body);
        int ended = RunUntilEnded(rig, 600);
        Assert.True(ended > 0);
        Assert.True(rig.Motion.MoveToResult == MoveToError.None, $"{rig.Motion.MoveToResult} at frame {ended}, at {rig.Origin}");
        float centre = Vector2.Distance(new Vector2(rig.Origin.X, rig.Origin.Y), new Vector2(60f, 62f));
        Assert.True(centre >= 5f + 0.48f - 1e-3f, $"centre distance {centre}");
    }

    [Fact]
    public void UseFinalHeading_TurnsToItAfterArriving()
    {
        var rig = Rig();
        var p = MoveToParameters.Default with { Flags = MoveToFlags.RetailDefault | MoveToFlags.UseFinalHeading, DesiredHeading = 180f };
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 66f, 0f), p, rig.Mover, rig.State, rig.Body);
        Assert.Equal(2, rig.Motion.MoveToNodeCount); // the move (facing it already) and the final turn
        RunUntilEnded(rig, 400);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        Assert.Equal(Headings.Facing(180f), rig.State.Position.Frame.Orientation);
    }

    [Fact]
    public void ACreatureInTheAir_WaitsForContact_ThenMoves()
    {
        // UseTime runs only with contact (transient_state & 1); landing restarts the head node (HitGround). A fall of
        // 10 m takes √(2·10/9.8) = 1.43 s (43 quanta); the move is worked once it stands.
        var rig = Rig();
        rig.State = MoverState.Airborne(TestGeometry.At(60f, 60f, 10f));
        rig.Motion.MoveToPosition(TestGeometry.At(60f, 70f, 0f), MoveToParameters.Default, rig.Mover, rig.State, rig.Body);
        rig.Frames(38);
        Assert.False(rig.State.Contact);
        Assert.Equal(60f, rig.Origin.Y); // no root motion off the ground
        int ended = RunUntilEnded(rig, 300);
        Assert.True(ended > 0);
        Assert.Equal(MoveToError.None, rig.Motion.MoveToResult);
        Assert.InRange(rig.Origin.Y, 70f - 1.08f, 70f);
    }
}
