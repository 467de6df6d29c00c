using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

/// <summary>A manager parity file read (format "ace-manager-parity"): the motion world and table, the mover's start, the frames.</summary>
internal sealed record MoveToParityFile(
    string Name,
    string Description,
    PhysicsWorld World,
    MoverDescription Mover,
    MotionTable Table,
    RetailSkills Skills,
    MoverState Start,
    double FrameSeconds,
    MoveToFrame[] Frames);
