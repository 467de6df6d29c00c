using System.Numerics;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// One frame of a position managers' parity file: the InterpolateTo or stick_to_object call made before the frame's
/// time passes, the sticky target's position after the frame (the driver moves it after the mover's quantum), ACE's
/// state after it, and whether ACE's quantum threw and whether ACE's stick is still held.
/// </summary>
internal readonly record struct PositionFrame(
    Position? InterpolateTo,
    uint StickTo,
    Position? Target,
    Vector3 Origin,
    uint Cell,
    float Heading,
    bool AceThrew,
    bool AceStuck);
