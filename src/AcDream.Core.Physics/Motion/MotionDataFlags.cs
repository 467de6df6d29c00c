using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>Which of a <see cref="MotionData"/>'s physics vectors are present (the DAT's MotionData flags byte).</summary>
[Flags]
public enum MotionDataFlags : byte
{
    /// <summary>Neither vector.</summary>
    None = 0,
    /// <summary>The velocity is present (otherwise zero).</summary>
    HasVelocity = 1,
    /// <summary>The omega is present (otherwise zero).</summary>
    HasOmega = 2,
}
