using System.Numerics;

namespace AcDream.Core.Physics.Parity;

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
