using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

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
