namespace AcDream.Core.Physics.Parity;

/// <summary>A call a motion parity file makes in one frame (before the frame's time passes).</summary>
internal enum MotionCallKind
{
    /// <summary>The raw hold key becomes Run (the recording's stand-in for retail's SetHoldKey(Run)).</summary>
    HoldRun,
    DoMotion,
    StopMotion,
    /// <summary>charge_jump then jump(extent, stamina).</summary>
    Jump,
    /// <summary>PhysicsObj.StopCompletely(false): the interpreter's StopCompletely (Ready, no sidestep, no turn).</summary>
    StopCompletely,
}
