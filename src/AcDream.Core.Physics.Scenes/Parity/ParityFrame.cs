using System.Numerics;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// One frame of a parity file: the requested offset and the reference implementation's outcome.
/// <see cref="HasContactPlane"/> is set when the file records the contact plane for this frame (the
/// real-cell files do, and it is compared only when the frame ends in contact).
/// </summary>
internal readonly record struct ParityFrame(
    Vector3 Offset,
    Vector3 Position,
    uint Cell,
    bool Contact,
    bool Walkable,
    bool Sliding,
    bool Accepted,
    uint[] Hits,
    bool HasContactPlane,
    Plane ContactPlane,
    uint ContactPlaneCell);
