using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// The interpreter's rules (CMotionInterp): adjust_motion, apply_run_to_command, get_state_velocity, jumps.
/// Expected values are hand-computed from retail's constants (walk 3.12, run 4, sidestep 1.25 m/s; backwards
/// ×0.65; sidestep ×0.5·3.12/1.25; run rate (200/400·11 + 4)/4 = 2.375 at Run 200).
/// </summary>
public class MotionInterpreterTests
{
    [Fact]
    public void WalkBackwards_IsWalkForwardAtMinus065_AndItsStateVelocityIs3_12Times065Back()
    {
        var rig = new MotionRig();
        Assert.Equal(MotionError.None, rig.Do(MotionCommand.WalkBackwards));
        var i = rig.Motion.Interpreted;
        Assert.Equal(MotionCommand.WalkForward, i.ForwardCommand);
        Assert.Equal(-0.65f, i.ForwardSpeed);
        Assert.Equal(-2.028f, rig.Motion.StateVelocity.Y, 5); // 3.12 × −0.65
        Assert.Equal(MotionCommand.WalkBackwards, rig.Motion.Raw.ForwardCommand);
    }

    [Fact]
    public void SideStep_IsScaledBy05Times3_12Over1_25_AndByTheRunRateWithTheRunKey()
    {
        var walk = new MotionRig();
        walk.Do(MotionCommand.SideStepRight);
        Assert.Equal(1.248f, walk.Motion.Interpreted.SideStepSpeed, 5);     // 0.5 × 3.12 / 1.25
        Assert.Equal(1.56f, walk.Motion.StateVelocity.X, 5);               // 1.25 × 1.248

        var left = new MotionRig();
        left.Do(MotionCommand.SideStepLeft);
        Assert.Equal(MotionCommand.SideStepRight, left.Motion.Interpreted.SideStepCommand);
        Assert.Equal(-1.248f, left.Motion.Interpreted.SideStepSpeed, 5);

        var run = new MotionRig();
        run.Do(MotionCommand.SideStepRight, HoldKey.Run);
        Assert.Equal(2.964f, run.Motion.Interpreted.SideStepSpeed, 5);      // 1.248 × 2.375 (below the 3.0 cap)
        Assert.Equal(3.705f, run.Motion.StateVelocity.X, 4);               // 1.25 × 2.964
    }

    [Fact]
    public void WithoutSkills_TheRunRateIs1_EvenAfterARunAtSpeed2()
    {
        // CMotionInterp::apply_run_to_command / get_max_speed: no weenie object → rate 1.0; my_run_rate (set from a
        // run's forward speed) is read only when the owner exists but gives no rate.
        var rig = new MotionRig();
        var motion = new ObjectMotion(MotionTables.Humanoid());
        motion.Place(rig.Mover, rig.State, ref rig.Body);
        motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(2f, HoldKey.Run), rig.Mover, ref rig.State, ref rig.Body);
        Assert.Equal(MotionCommand.RunForward, motion.Interpreted.ForwardCommand);
        Assert.Equal(2f, motion.Interpreted.ForwardSpeed);   // 2 × rate 1
        // A landing (HitGround → apply_current_movement → apply_interpreted_movement) sets my_run_rate to 2.
        motion.Place(rig.Mover, rig.State, ref rig.Body);
        Assert.Equal(4f, motion.MaxSpeed);                   // 4 m/s × rate 1, not × my_run_rate
        motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), rig.Mover, ref rig.State, ref rig.Body);
        Assert.Equal(1f, motion.Interpreted.ForwardSpeed);   // 1 × rate 1
    }

    [Fact]
    public void SideStepWithTheRunKey_IsCappedAtThree()
    {
        var rig = new MotionRig(runSkill: 800); // rate 4.5: 1.248 × 4.5 = 5.616 → 3
        rig.Do(MotionCommand.SideStepRight, HoldKey.Run);
        Assert.Equal(3f, rig.Motion.Interpreted.SideStepSpeed);
    }

    [Fact]
    public void WalkForwardWithTheRunKey_IsRunForwardAtTheRunRate_AndTheStateVelocityIsCappedAt4TimesTheRate()
    {
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Interpreted.ForwardCommand);
        Assert.Equal(2.375f, rig.Motion.Interpreted.ForwardSpeed);
        Assert.Equal(9.5f, rig.Motion.StateVelocity.Y, 5);   // 4 × 2.375
        Assert.Equal(9.5f, rig.Motion.MaxSpeed, 5);
        rig.Do(MotionCommand.SideStepRight, HoldKey.Run);
        Assert.Equal(9.5f, rig.Motion.StateVelocity.Length(), 4); // √(9.5² + 3.705²) capped at 9.5
    }

    [Fact]
    public void TurnWithTheRunKey_Is15TimesFaster()
    {
        var rig = new MotionRig();
        rig.Do(MotionCommand.TurnLeft, HoldKey.Run);
        Assert.Equal(MotionCommand.TurnRight, rig.Motion.Interpreted.TurnCommand);
        Assert.Equal(-1.5f, rig.Motion.Interpreted.TurnSpeed);
    }

    [Fact]
    public void NinetyDegreeTurn_TakesHalfPiOverOmega()
    {
        // The turn cycle's omega is π/2 rad/s: 30 frames at 30 frames/s turn by 90°, one frame (3°) per quantum.
        var rig = new MotionRig();
        rig.Do(MotionCommand.TurnRight);
        rig.Frames(15);
        Assert.Equal(-Math.PI / 4, rig.Heading, 3);
        rig.Frames(15);
        Assert.Equal(-Math.PI / 2, rig.Heading, 3);
        Assert.Equal(60f, rig.Origin.X, 4); // turning in place does not move
        Assert.Equal(60f, rig.Origin.Y, 4);
    }

    [Fact]
    public void Jump_LeavesWithTheStateVelocityAndTheJumpSpeed()
    {
        // Jump 200, extent 0.5: (200/1500·22.2 + 0.05)·0.5 = 1.505 m → √(19.6·1.505) = 5.4312 m/s; running: 9.5 m/s forward.
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        rig.Frames(5);
        Assert.Equal(MotionError.None, rig.Jump(0.5f));
        Assert.False(rig.State.OnWalkable);
        Assert.Equal(9.5f, rig.Body.Velocity.Y, 4);
        Assert.Equal(5.4312f, rig.Body.Velocity.Z, 3);
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Interpreted.ForwardCommand);
        Assert.Equal(MotionCommand.Falling, rig.Motion.Substate);
    }

    [Fact]
    public void NoJump_WhileAirborne_AndNothingChanges()
    {
        var rig = new MotionRig();
        Assert.Equal(MotionError.None, rig.Jump(0.5f));
        rig.Frames(3);
        Assert.False(rig.State.OnWalkable);
        var state = rig.State;
        var body = rig.Body;
        Assert.Equal(MotionError.CantJumpWhileInTheAir, rig.Motion.Jump(1f, true, rig.Mover, ref rig.State, ref rig.Body));
        Assert.Equal(state.Position.Frame.Origin, rig.State.Position.Frame.Origin);
        Assert.Equal(body.Velocity, rig.Body.Velocity);
    }

    [Fact]
    public void NoJump_WithoutStamina()
    {
        var rig = new MotionRig();
        Assert.Equal(MotionError.GeneralMovementFailure, rig.Jump(0.5f, staminaOk: false));
        Assert.True(rig.State.OnWalkable);
        Assert.Equal(Vector3.Zero, rig.Body.Velocity);
    }

    [Fact]
    public void LandingIntoAHeldRun_KeepsTheAirborneVelocity_WhichGroundFrictionDecays()
    {
        // CMotionInterp::HitGround (acclient.c:344428) re-applies the held run and does not touch the velocity;
        // handle_all_collisions only reflects its part into the floor; calc_friction (CPhysicsObj.c:533) then decays
        // it by 0.05^t on walkable ground until |v|² drops below 0.0625 + EPSILON (from 9.5 m/s: t ≈ ln(0.25/9.5)/ln 0.05 ≈ 1.21 s).
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        rig.Frames(5);
        rig.Jump(0.5f);
        int frames = 0;
        while (!rig.State.OnWalkable && frames < 60)
        {
            rig.Frames(1);
            frames++;
        }
        Assert.True(rig.State.OnWalkable, "landed within 2 s");
        Assert.Equal(9.5f, rig.Body.Velocity.Y, 4);          // kept through the landing
        Assert.Equal(MotionCommand.RunForward, rig.Motion.Substate); // the held run resumed
        rig.Frames(15);                                         // half a second later: decayed, not gone
        Assert.InRange(rig.Body.Velocity.Y, 0.5f, 9.5f * MathF.Pow(0.05f, 0.3f));
        rig.Frames(45);                                         // two seconds after landing: stopped
        Assert.Equal(0f, rig.Body.Velocity.Y);
    }

    [Fact]
    public void LeavingTheGroundWithNoStateVelocity_KeepsTheBodysOwnVelocity()
    {
        // get_leave_ground_velocity (CMotionInterp.c:530-565): standing still with no jump speed (extent 0), the state
        // velocity is zero, so the body's own velocity is taken (world → body axes → world again).
        var rig = new MotionRig();
        rig.Body.Velocity = new Vector3(2f, 0f, 0f);
        Assert.Equal(MotionError.None, rig.Motion.Jump(0f, true, rig.Mover, ref rig.State, ref rig.Body));
        Assert.False(rig.State.OnWalkable);
        Assert.Equal(2f, rig.Body.Velocity.X, 6);
        Assert.Equal(0f, rig.Body.Velocity.Y, 6);
        Assert.Equal(0f, rig.Body.Velocity.Z, 6);
    }

    [Fact]
    public void StopCompletely_LeavesReadyWithNoSidestepOrTurn()
    {
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        rig.Do(MotionCommand.TurnRight, HoldKey.Run);
        rig.Frames(5);
        Assert.Equal(MotionError.None, rig.Motion.StopCompletely(rig.Mover, ref rig.State, ref rig.Body));
        var i = rig.Motion.Interpreted;
        Assert.Equal(MotionCommand.Ready, i.ForwardCommand);
        Assert.Equal(0u, i.TurnCommand);
        Assert.Equal(MotionCommand.Ready, rig.Motion.Substate);
        Assert.Equal(0, rig.Motion.ModifierCount);
        Assert.Equal(Vector3.Zero, rig.Motion.SequenceVelocity);
        Assert.Equal(Vector3.Zero, rig.Motion.SequenceOmega);
    }

    [Fact]
    public void StoppingATurnWhileWalking_TakesOnlyItsOmegaAway()
    {
        // While walking, TurnRight (bitfield 2) is a modifier: it adds −π/2 rad/s about z to the walk's sequence;
        // stopping it subtracts that again (StopSequenceMotion) and the walk's 3.12 m/s stays.
        var rig = new MotionRig();
        rig.Do(MotionCommand.WalkForward);
        rig.Do(MotionCommand.TurnRight);
        Assert.Equal(MotionCommand.WalkForward, rig.Motion.Substate);
        Assert.Equal(1, rig.Motion.ModifierCount);
        Assert.Equal(-MathF.PI / 2, rig.Motion.SequenceOmega.Z, 5);
        rig.Stop(MotionCommand.TurnRight);
        Assert.Equal(0, rig.Motion.ModifierCount);
        Assert.Equal(0f, rig.Motion.SequenceOmega.Z);
        Assert.Equal(3.12f, rig.Motion.SequenceVelocity.Y);
    }
}
