using System;

namespace AcDream.Core.Physics;

/// <summary>Retail OBJECTINFO state bits: what the mover is and how it stands (ACE ObjectInfo.cs).</summary>
[Flags]
public enum ObjectInfoState : uint
{
    /// <summary>No bit set.</summary>
    None = 0,
    /// <summary>The mover touches a contact plane.</summary>
    Contact = 0x1,
    /// <summary>The contact plane is walkable.</summary>
    OnWalkable = 0x2,
    /// <summary>The mover is the camera.</summary>
    IsViewer = 0x4,
    /// <summary>Stop at the first collision.</summary>
    PathClipped = 0x8,
    /// <summary>Orientation is not interpolated along the path.</summary>
    FreeRotate = 0x10,
    /// <summary>PERFECT_CLIP.</summary>
    PerfectClip = 0x40,
    /// <summary>The mover cannot be passed by players.</summary>
    IsImpenetrable = 0x80,
    /// <summary>The mover is a player.</summary>
    IsPlayer = 0x100,
    /// <summary>The mover slides along edges instead of walking off them.</summary>
    EdgeSlide = 0x200,
    /// <summary>The mover ignores creatures.</summary>
    IgnoreCreatures = 0x400,
    /// <summary>The mover is a player killer.</summary>
    IsPK = 0x800,
    /// <summary>The mover is a PK-lite player.</summary>
    IsPKLite = 0x1000,
}
