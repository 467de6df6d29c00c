using System.Numerics;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Motion;

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

/// <summary>One call: what, the motion, speed, hold key, the jump's extent and stamina, and the reference's result ("None" or an error name).</summary>
internal readonly record struct MotionCall(MotionCallKind Kind, uint Motion, float Speed, HoldKey Hold, float Extent, int Stamina, string Expected);

/// <summary>
/// The motion table manager's state and the sequence as the reference logs them after a frame: style, substate and
/// its speed, the modifiers (newest first); the sequence's velocity and omega, the animation playing, its
/// framerate and frame number, and the animation list ("id@framerate", the first cyclic one marked).
/// </summary>
internal sealed record MotionSequenceState(uint Style, uint Substate, float SubstateSpeed, MotionAndSpeed[] Modifiers,
    Vector3 Velocity, Vector3 Omega, uint CurrentAnimation, float CurrentFramerate, double FrameNumber, (uint Id, float Framerate)[] Anims,
    int FirstCyclic);

/// <summary>One frame of a motion parity file: the calls made, then the reference's state after the frame.</summary>
internal readonly record struct MotionParityFrame(
    MotionCall[] Calls,
    bool QuantumRan,
    Vector3 Position,
    uint Cell,
    bool Contact,
    bool Walkable,
    InterpretedMotionState Interpreted,
    MotionSequenceState? Sequence);

/// <summary>A motion parity file read (format "ace-motion-parity"): the world, the mover, its skills and start, the table, the frames.</summary>
internal sealed record MotionParityFile(
    string Name,
    PhysicsWorld World,
    MoverDescription Mover,
    MotionTable Table,
    RetailSkills Skills,
    MoverState Start,
    BodyState StartBody,
    double FrameSeconds,
    MotionParityFrame[] Frames);
