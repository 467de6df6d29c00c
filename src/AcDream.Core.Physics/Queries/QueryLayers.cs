using System;

namespace AcDream.Core.Physics.Queries;

/// <summary>What a world query looks at.</summary>
[Flags]
public enum QueryLayers
{
    /// <summary>Nothing.</summary>
    None = 0,
    /// <summary>The cells' own geometry: terrain, indoor cells' physics BSPs and buildings' shells.</summary>
    Environment = 0x1,
    /// <summary>Registered objects that are not ethereal.</summary>
    Objects = 0x2,
    /// <summary>Registered objects with <see cref="PhysicsState.Ethereal"/> (a mover passes through them; a pick may want them).</summary>
    EtherealObjects = 0x4,
    /// <summary>The environment and solid objects: what a mover collides with (the default).</summary>
    Solid = Environment | Objects,
    /// <summary>Everything.</summary>
    All = Environment | Objects | EtherealObjects,
}
