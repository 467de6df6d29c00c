using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// The motion table manager's state and the sequence as the reference logs them after a frame: style, substate and
/// its speed, the modifiers (newest first); the sequence's velocity and omega, the animation playing, its
/// framerate and frame number, and the animation list ("id@framerate", the first cyclic one marked).
/// </summary>
internal sealed record MotionSequenceState(uint Style, uint Substate, float SubstateSpeed, MotionAndSpeed[] Modifiers,
    Vector3 Velocity, Vector3 Omega, uint CurrentAnimation, float CurrentFramerate, double FrameNumber, (uint Id, float Framerate)[] Anims,
    int FirstCyclic);
