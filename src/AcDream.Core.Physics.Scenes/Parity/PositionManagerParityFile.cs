using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

/// <summary>A position managers' parity file read (format "ace-manager-parity", files sticky* and interpolate*).</summary>
internal sealed record PositionManagerParityFile(
    string Name,
    PhysicsWorld World,
    MoverDescription Mover,
    MotionTable Table,
    RetailSkills Skills,
    MoverState Start,
    Position TargetStart,
    double FrameSeconds,
    PositionFrame[] Frames);
