using System;

namespace AcDream.Core.Physics;

/// <summary>What an object is, as far as the PvP, creature and missile rules of collision care.</summary>
[Flags]
public enum ShadowFlags : byte
{
    /// <summary>Nothing special.</summary>
    None = 0,
    /// <summary>The object is a player.</summary>
    IsPlayer = 0x1,
    /// <summary>The object is a creature (players and monsters).</summary>
    IsCreature = 0x2,
    /// <summary>The object cannot be passed by players.</summary>
    IsImpenetrable = 0x4,
    /// <summary>The object is a player killer.</summary>
    IsPK = 0x8,
    /// <summary>The object is a PK-lite player.</summary>
    IsPKLite = 0x10,
    /// <summary>
    /// The object is a game object with a weenie (anything a server spawns), as opposed to static scenery
    /// from the landblock's data. Retail's missile rules only ignore weenie objects.
    /// </summary>
    HasWeenie = 0x20,
}
