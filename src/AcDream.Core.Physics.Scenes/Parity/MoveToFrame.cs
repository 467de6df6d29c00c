using System.Numerics;

namespace AcDream.Core.Physics.Parity;

/// <summary>One frame of a manager parity file: the calls, the target update delivered (the target's position and the interpolated one), and ACE's state after it.</summary>
internal readonly record struct MoveToFrame(
    MoveToCall[] Calls,
    Position? TargetUpdate,
    Position? InterpolatedUpdate,
    Vector3 Origin,
    uint Cell,
    float Heading,
    bool Contact,
    bool Walkable,
    uint ForwardCommand,
    float ForwardSpeed,
    uint TurnCommand,
    float TurnSpeed,
    MoveToKind Kind,
    uint Command,
    uint AuxCommand,
    int FailProgressCount,
    string? Completed);
