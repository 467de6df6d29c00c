using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Retail's motion interpreter (CMotionInterp, acclient-src PORTAL/canim/CMotionInterp.c): turns raw commands
/// into the interpreted state (adjust_motion, apply_run_to_command), hands them to the motion table manager,
/// and handles jumps, leaving and hitting the ground. It sees the body through <see cref="Body"/>, which the
/// owner (<see cref="ObjectMotion"/>) fills before each call and reads back after.
/// </summary>
internal sealed class MotionInterpreter
{
    /// <summary>Retail's constants (CMotionInterp): walk, run and sidestep speeds at speed 1, and the factors.</summary>
    public const float WalkAnimSpeed = 3.12f, RunAnimSpeed = 4f, SidestepAnimSpeed = 1.25f, BackwardsFactor = 0.65f,
        SidestepFactor = 0.5f, RunTurnFactor = 1.5f, MaxSidestepAnimRate = 3f;

    // The chat-emote bit of a command id (ACE CommandMasks.ChatEmote): DoMotion refuses such commands in a combat style.
    private const uint ChatEmoteMask = 0x02000000;

    private readonly MotionTableManager _manager;
    private readonly IMotionSkills? _skills;
    private readonly PendingQueue<(uint Motion, MotionError JumpError)> _pending = new();

    public InterpreterBody Body;
    public RawMotionState Raw = RawMotionState.Default;
    public InterpretedMotionState Interpreted = InterpretedMotionState.Default;
    public bool Initted;
    public bool StandingLongJump;
    public float JumpExtent;
    public float MyRunRate = 1f;
    /// <summary>CPhysicsObj::movement_is_autonomous: the last command came from the object's own controls (DoMotion/StopMotion).</summary>
    public bool Autonomous;

    // The pending motions, for a snapshot (read, and replaced whole by a load).
    internal int PendingCount => _pending.Count;
    internal (uint Motion, MotionError JumpError) PendingAt(int i) => _pending[i];
    internal void RestorePending(ReadOnlySpan<(uint Motion, MotionError JumpError)> items) => _pending.Restore(items);

    public MotionInterpreter(MotionTableManager manager, IMotionSkills? skills)
    {
        _manager = manager;
        _skills = skills;
        manager.Interpreter = this;
    }

    /// <summary>CMotionInterp::enter_default_state: default states, the table's default cycle, then LeaveGround.</summary>
    public void EnterDefaultState()
    {
        Raw = RawMotionState.Default;
        Interpreted = InterpretedMotionState.Default;
        _manager.InitializeState();
        AddToQueue(MotionCommand.Ready, MotionError.None);
        Initted = true;
        LeaveGround();
    }

    // ---- commands ----

    /// <summary>CMotionInterp::DoMotion.</summary>
    public MotionError DoMotion(uint motion, in MotionParameters p)
    {
        var adjusted = p;
        if (p.SetHoldKey)
            SetHoldKey(p.HoldKey);
        uint command = motion;
        float speed = p.Speed;
        AdjustMotion(ref command, ref speed, p.HoldKey);
        adjusted = adjusted with { Speed = speed };
        if (Interpreted.Style != MotionCommand.NonCombat)
        {
            switch (motion)
            {
                case MotionCommand.Crouch: return MotionError.CantCrouchInCombat;
                case MotionCommand.Sitting: return MotionError.CantSitInCombat;
                case MotionCommand.Sleeping: return MotionError.CantLieDownInCombat;
            }
            if ((motion & ChatEmoteMask) != 0)
                return MotionError.CantChatEmoteInCombat;
        }
        if ((motion & MotionCommandMask.Action) != 0 && _manager.State.ActionCount >= 6)
            return MotionError.TooManyActions;
        var result = DoInterpretedMotion(command, adjusted);
        if (result == MotionError.None && p.ModifyRawState)
            Raw.Apply(motion, p);
        return result;
    }

    /// <summary>CMotionInterp::StopMotion.</summary>
    public MotionError StopMotion(uint motion, in MotionParameters p)
    {
        uint command = motion;
        float speed = p.Speed;
        AdjustMotion(ref command, ref speed, p.HoldKey);
        var result = StopInterpretedMotion(command, p with { Speed = speed });
        if (result == MotionError.None && p.ModifyRawState)
            Raw.Remove(motion);
        return result;
    }

    /// <summary>CMotionInterp::StopCompletely: back to Ready with no sidestep or turn, in both states and the table.</summary>
    public MotionError StopCompletely()
    {
        var jump = MotionAllowsJump(Interpreted.ForwardCommand);
        Raw.ForwardCommand = MotionCommand.Ready;
        Raw.ForwardSpeed = 1f;
        Raw.SideStepCommand = 0;
        Raw.TurnCommand = 0;
        Interpreted.ForwardCommand = MotionCommand.Ready;
        Interpreted.ForwardSpeed = 1f;
        Interpreted.SideStepCommand = 0;
        Interpreted.TurnCommand = 0;
        _manager.StopCompletely();
        AddToQueue(MotionCommand.Ready, jump);
        return MotionError.None;
    }

    /// <summary>CMotionInterp::SetHoldKey: None and Run change the current hold key and re-apply the movement (ACE handles only None).</summary>
    public void SetHoldKey(HoldKey key)
    {
        if (key == Raw.CurrentHoldKey)
            return;
        if (key == HoldKey.None && Raw.CurrentHoldKey == HoldKey.Run || key == HoldKey.Run)
        {
            Raw.CurrentHoldKey = key;
            ApplyCurrentMovement(disallowJump: false);
        }
    }

    /// <summary>CMotionInterp::DoInterpretedMotion.</summary>
    public MotionError DoInterpretedMotion(uint motion, in MotionParameters p)
    {
        if (!ContactAllowsMove(motion))
        {
            if ((motion & MotionCommandMask.Action) != 0)
                return MotionError.CantJumpWhileInTheAir;
            if (p.ModifyInterpretedState)
                Interpreted.Apply(motion, p.Speed);
            return MotionError.None;
        }
        if (StandingLongJump && IsForwardOrSidestep(motion))
        {
            if (p.ModifyInterpretedState)
                Interpreted.Apply(motion, p.Speed);
            return MotionError.None;
        }
        if (motion == MotionCommand.Dead)
            _manager.RemoveLinkAnimations();
        if (!_manager.DoMotion(motion, p.Speed))
            return MotionError.NoMotionTableData;
        MotionError jump;
        if (p.DisableJumpDuringLink)
        {
            jump = MotionError.CantJumpFromThisPosition;
        }
        else
        {
            jump = MotionAllowsJump(motion);
            if (jump == MotionError.None && (motion & MotionCommandMask.Action) == 0)
                jump = MotionAllowsJump(Interpreted.ForwardCommand);
        }
        AddToQueue(motion, jump);
        if (p.ModifyInterpretedState)
            Interpreted.Apply(motion, p.Speed);
        return MotionError.None;
    }

    /// <summary>CMotionInterp::StopInterpretedMotion.</summary>
    public MotionError StopInterpretedMotion(uint motion, in MotionParameters p)
    {
        if (!ContactAllowsMove(motion) || StandingLongJump && IsForwardOrSidestep(motion))
        {
            if (p.ModifyInterpretedState)
                Interpreted.Remove(motion);
            return MotionError.None;
        }
        if (!_manager.StopMotion(motion))
            return MotionError.NoMotionTableData;
        AddToQueue(MotionCommand.Ready, MotionError.None);
        if (p.ModifyInterpretedState)
            Interpreted.Remove(motion);
        return MotionError.None;
    }

    private static bool IsForwardOrSidestep(uint motion) =>
        motion is MotionCommand.WalkForward or MotionCommand.RunForward or MotionCommand.SideStepRight;

    // ---- adjust ----

    /// <summary>
    /// CMotionInterp::adjust_motion: backwards becomes forward at −0.65 × speed, left becomes right at −speed;
    /// a sidestep's speed is scaled by 0.5 × 3.12 / 1.25; with the Run key (given or current) apply_run_to_command.
    /// </summary>
    public void AdjustMotion(ref uint motion, ref float speed, HoldKey holdKey)
    {
        switch (motion)
        {
            case MotionCommand.RunForward:
                return;
            case MotionCommand.WalkBackwards:
                motion = MotionCommand.WalkForward;
                speed *= -BackwardsFactor;
                break;
            case MotionCommand.TurnLeft:
                motion = MotionCommand.TurnRight;
                speed *= -1f;
                break;
            case MotionCommand.SideStepLeft:
                motion = MotionCommand.SideStepRight;
                speed *= -1f;
                break;
        }
        if (motion == MotionCommand.SideStepRight)
            speed *= SidestepFactor * (WalkAnimSpeed / SidestepAnimSpeed);
        if (holdKey == HoldKey.Invalid)
            holdKey = Raw.CurrentHoldKey;
        if (holdKey == HoldKey.Run)
            ApplyRunToCommand(ref motion, ref speed);
    }

    /// <summary>
    /// CMotionInterp::apply_run_to_command: WalkForward (forwards) becomes RunForward, its speed × the run rate;
    /// a turn × 1.5; a sidestep × the run rate, clamped to ±3.
    /// </summary>
    public void ApplyRunToCommand(ref uint motion, ref float speed)
    {
        float rate = RunRate();
        switch (motion)
        {
            case MotionCommand.WalkForward:
                if (speed > 0f)
                    motion = MotionCommand.RunForward;
                speed *= rate;
                break;
            case MotionCommand.TurnRight:
                speed *= RunTurnFactor;
                break;
            case MotionCommand.SideStepRight:
                speed *= rate;
                if (MathF.Abs(speed) > MaxSidestepAnimRate)
                    speed = speed > 0f ? MaxSidestepAnimRate : -MaxSidestepAnimRate;
                break;
        }
    }

    /// <summary>
    /// The run rate apply_run_to_command, get_state_velocity and get_max_speed use (CMotionInterp.c:163-234):
    /// 1 for an object without skills (retail: no weenie object), else the owner's InqRunRate, else
    /// <see cref="MyRunRate"/> (which apply_interpreted_movement sets from a run's forward speed).
    /// </summary>
    public float RunRate() => _skills is null ? 1f : _skills.TryRunRate(out float r) ? r : MyRunRate;

    // ---- re-applying the state ----

    /// <summary>CMotionInterp::apply_current_movement: the raw state for the object's own controls, else the interpreted one.</summary>
    public void ApplyCurrentMovement(bool disallowJump)
    {
        if (!Initted)
            return;
        if (Autonomous)
            ApplyRawMovement(disallowJump);
        else
            ApplyInterpretedMovement(disallowJump);
    }

    private void ApplyRawMovement(bool disallowJump)
    {
        Interpreted.Style = Raw.Style;
        Interpreted.ForwardCommand = Raw.ForwardCommand;
        Interpreted.ForwardSpeed = Raw.ForwardSpeed;
        Interpreted.SideStepCommand = Raw.SideStepCommand;
        Interpreted.SideStepSpeed = Raw.SideStepSpeed;
        Interpreted.TurnCommand = Raw.TurnCommand;
        Interpreted.TurnSpeed = Raw.TurnSpeed;
        AdjustMotion(ref Interpreted.ForwardCommand, ref Interpreted.ForwardSpeed, Raw.ForwardHoldKey);
        AdjustMotion(ref Interpreted.SideStepCommand, ref Interpreted.SideStepSpeed, Raw.SideStepHoldKey);
        AdjustMotion(ref Interpreted.TurnCommand, ref Interpreted.TurnSpeed, Raw.TurnHoldKey);
        ApplyInterpretedMovement(disallowJump);
    }

    // CMotionInterp::apply_interpreted_movement (acclient.c:344146): the style, then forward and sidestep (or Falling
    // off the ground), then the turn, each given to the table without changing the interpreted state.
    private void ApplyInterpretedMovement(bool disallowJump)
    {
        var p = new MotionParameters(1f, HoldKey.Invalid, SetHoldKey: false, ModifyRawState: true, ModifyInterpretedState: false,
            DisableJumpDuringLink: disallowJump);
        if (Interpreted.ForwardCommand == MotionCommand.RunForward)
            MyRunRate = Interpreted.ForwardSpeed;
        DoInterpretedMotion(Interpreted.Style, p);
        if (ContactAllowsMove(Interpreted.ForwardCommand))
        {
            if (StandingLongJump)
            {
                DoInterpretedMotion(MotionCommand.Ready, p with { Speed = 1f });
                StopInterpretedMotion(MotionCommand.SideStepRight, p with { Speed = 1f });
            }
            else
            {
                DoInterpretedMotion(Interpreted.ForwardCommand, p with { Speed = Interpreted.ForwardSpeed });
                if (Interpreted.SideStepCommand != 0)
                    DoInterpretedMotion(Interpreted.SideStepCommand, p with { Speed = Interpreted.SideStepSpeed });
                else
                    StopInterpretedMotion(MotionCommand.SideStepRight, p with { Speed = Interpreted.ForwardSpeed });
            }
        }
        else
        {
            p = p with { Speed = 1f };
            DoInterpretedMotion(MotionCommand.Falling, p);
        }
        if (Interpreted.TurnCommand != 0)
        {
            DoInterpretedMotion(Interpreted.TurnCommand, p with { Speed = Interpreted.TurnSpeed });
        }
        else if (_manager.StopMotion(MotionCommand.TurnRight))
        {
            // CPhysicsObj::StopInterpretedMotion directly (not through the interpreter's contact test).
            AddToQueue(MotionCommand.Ready, MotionError.None);
        }
    }

    // ---- ground ----

    /// <summary>CMotionInterp::contact_allows_move: turns, Falling and Dead always; other motions only on walkable ground (with gravity).</summary>
    public bool ContactAllowsMove(uint motion)
    {
        if (motion is MotionCommand.Dead or MotionCommand.Falling || motion >= MotionCommand.TurnRight && motion <= MotionCommand.TurnLeft)
            return true;
        if (!Body.Gravity)
            return true;
        return Body.Contact && Body.OnWalkable;
    }

    /// <summary>CMotionInterp::LeaveGround: the leave-ground velocity (body axes, set in world axes), the jump spent, links dropped, the movement re-applied (Falling).</summary>
    public void LeaveGround()
    {
        if (!Body.Gravity)
            return;
        var local = LeaveGroundVelocity();
        SetVelocity(new Frame(Vector3.Zero, Body.Orientation).LocalToGlobalVec(local));
        StandingLongJump = false;
        JumpExtent = 0f;
        _manager.RemoveLinkAnimations();
        ApplyCurrentMovement(disallowJump: false);
    }

    /// <summary>CMotionInterp::HitGround (acclient.c:344428): links dropped, the movement re-applied; the velocity is not touched.</summary>
    public void HitGround()
    {
        if (!Body.Gravity)
            return;
        _manager.RemoveLinkAnimations();
        ApplyCurrentMovement(disallowJump: false);
    }

    // CPhysicsObj::set_velocity: a new velocity longer than 50 m/s is scaled down to 50.
    private void SetVelocity(Vector3 v)
    {
        if (VectorMath.SameBits(v, Body.Velocity))
            return;
        float length = v.Length();
        if (length > PhysicsConstants.MaxVelocity)
            v = v / length * PhysicsConstants.MaxVelocity;
        Body.Velocity = v;
    }

    /// <summary>
    /// CMotionInterp::get_state_velocity (CMotionInterp.c:263-319): the interpreted state's speed in body axes —
    /// sidestep 1.25, walk 3.12, run 4 m/s × speed — capped at 4 × the run rate. Read only by
    /// get_leave_ground_velocity: a grounded body moves by the sequence's root motion.
    /// </summary>
    public Vector3 StateVelocity()
    {
        var v = Vector3.Zero;
        if (Interpreted.SideStepCommand == MotionCommand.SideStepRight)
            v.X = SidestepAnimSpeed * Interpreted.SideStepSpeed;
        if (Interpreted.ForwardCommand == MotionCommand.WalkForward)
            v.Y = WalkAnimSpeed * Interpreted.ForwardSpeed;
        else if (Interpreted.ForwardCommand == MotionCommand.RunForward)
            v.Y = RunAnimSpeed * Interpreted.ForwardSpeed;
        // The clamp in retail's arithmetic: the length in double, each component (float)(1/len × c × max).
        double max = RunAnimSpeed * RunRate();
        double length = Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);
        if (length > max)
        {
            double inv = 1.0 / length;
            v = new Vector3((float)(inv * v.X * max), (float)(inv * v.Y * max), (float)(inv * v.Z * max));
        }
        return v;
    }

    /// <summary>CMotionInterp::get_max_speed: 4 m/s × the run rate.</summary>
    public float MaxSpeed() => RunAnimSpeed * RunRate();

    /// <summary>CMotionInterp::get_jump_v_z: 0 below EPSILON extent; the extent capped at 1; the owner's jump velocity (10 m/s without one).</summary>
    public float JumpVz()
    {
        if (JumpExtent < PhysicsConstants.Epsilon)
            return 0f;
        float extent = JumpExtent > 1f ? 1f : JumpExtent;
        if (_skills is null)
            return 10f;
        return _skills.TryJumpVelocity(extent, out float vz) ? vz : 0f;
    }

    /// <summary>
    /// CMotionInterp::get_leave_ground_velocity (CMotionInterp.c:530-565): the state velocity with the jump's
    /// vertical speed; when that is zero, the body's own velocity in body axes.
    /// </summary>
    public Vector3 LeaveGroundVelocity()
    {
        var v = StateVelocity();
        v.Z = JumpVz();
        const float e = PhysicsConstants.Epsilon;
        if (MathF.Abs(v.X) < e && MathF.Abs(v.Y) < e && MathF.Abs(v.Z) < e)
            v = new Frame(Vector3.Zero, Body.Orientation).GlobalToLocalVec(Body.Velocity);
        return v;
    }

    // ---- jumps ----

    /// <summary>CMotionInterp::charge_jump: refused while falling or sitting; a standing jump from rest is a standing long jump.</summary>
    public MotionError ChargeJump()
    {
        var error = JumpChargeIsAllowed();
        if (error != MotionError.None)
            return error;
        if (Body.Contact && Body.OnWalkable && Interpreted.ForwardCommand == MotionCommand.Ready && Interpreted.SideStepCommand == 0
            && Interpreted.TurnCommand == 0)
            StandingLongJump = true;
        return MotionError.None;
    }

    /// <summary>CMotionInterp::jump: when allowed, the extent is kept and the body leaves walkable ground (set_on_walkable(0) → LeaveGround).</summary>
    public MotionError Jump(float extent, bool staminaOk)
    {
        var result = JumpIsAllowed(extent, staminaOk);
        if (result != MotionError.None)
        {
            StandingLongJump = false;
            return result;
        }
        JumpExtent = extent;
        SetOnWalkable(false);
        return MotionError.None;
    }

    /// <summary>CMotionInterp::jump_is_allowed: only from walkable ground (with gravity), not while a queued motion forbids it, not from a motion that forbids it, and only with the stamina.</summary>
    public MotionError JumpIsAllowed(float extent, bool staminaOk)
    {
        if (Body.Gravity && !(Body.Contact && Body.OnWalkable))
            return MotionError.CantJumpWhileInTheAir;
        // Retail reads the queue's head whenever there is one (CMotionInterp.c:646-697; ACE only with two or more).
        if (_pending.Count > 0 && _pending[0].JumpError != MotionError.None)
            return _pending[0].JumpError;
        var error = JumpChargeIsAllowed();
        if (error == MotionError.None)
        {
            error = MotionAllowsJump(Interpreted.ForwardCommand);
            if (error == MotionError.None && !staminaOk)
                error = MotionError.GeneralMovementFailure;
        }
        return error;
    }

    // CMotionInterp::jump_charge_is_allowed (acclient.c:343317): the owner's CanJump, then the position; charge_jump
    // (acclient.c:343844) makes the same two tests inline. Retail tests Fallen and Crouch..Sleeping
    // (CMotionInterp.c:569-604); ACE tests Falling and stops before Sleeping.
    private MotionError JumpChargeIsAllowed()
    {
        if (_skills is not null && !_skills.CanJump(JumpExtent))
            return MotionError.CantJumpLoadedDown;
        uint forward = Interpreted.ForwardCommand;
        if (forward == MotionCommand.Fallen || forward >= MotionCommand.Crouch && forward <= MotionCommand.Sleeping)
            return MotionError.CantJumpFromThisPosition;
        return MotionError.None;
    }

    /// <summary>
    /// CMotionInterp::motion_allows_jump (CMotionInterp.c:19-40): reloading to picking up, the power-ups, crouch to
    /// sleep, aiming to praying, and Fallen forbid a jump (ACE lists Falling in Fallen's place).
    /// </summary>
    public static MotionError MotionAllowsJump(uint substate)
    {
        bool forbidden = substate is >= 0x40000016 and <= 0x40000018 // Reload .. Pickup
            || substate is >= 0x10000128 and <= 0x10000131 // TripleThrustLow .. MagicPowerUp07Purple
            || substate is >= 0x1000006F and <= 0x10000078 // MagicPowerUp01 .. MagicPowerUp10
            || substate is >= MotionCommand.Crouch and <= MotionCommand.Sleeping
            || substate is >= 0x4000001E and <= 0x40000039 // AimLevel .. MagicPray
            || substate == MotionCommand.Fallen;
        return forbidden ? MotionError.CantJumpFromThisPosition : MotionError.None;
    }

    /// <summary>CPhysicsObj::set_on_walkable: a change of walkable ground tells the interpreter (LeaveGround / HitGround).</summary>
    public void SetOnWalkable(bool onWalkable)
    {
        bool was = Body.OnWalkable;
        Body.OnWalkable = onWalkable;
        if (was && !onWalkable)
            LeaveGround();
        else if (!was && onWalkable)
            HitGround();
    }

    // ---- the queue of motions waiting for their animations ----

    private void AddToQueue(uint motion, MotionError jumpError) => _pending.Add((motion, jumpError));

    /// <summary>CMotionInterp::MotionDone: the oldest queued motion is done.</summary>
    public void MotionDone(bool success)
    {
        // (For an action retail also drops it from both states' action lists, which are not kept here.)
        _pending.RemoveFirst();
    }
}
