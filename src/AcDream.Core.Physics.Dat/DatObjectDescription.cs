namespace AcDream.Core.Physics.Dat;

/// <summary>
/// What the game, not the DAT, says of a static object the DAT places: the id it is registered under, its scale,
/// its state and its shadow flags. A host that knows its objects (a server's weenie descriptions) supplies them
/// through a <see cref="DatObjectDescriber"/>; <see cref="DatWorld.DefaultDescription"/> is used otherwise.
/// </summary>
/// <param name="Id">The registry id (unique in the world).</param>
/// <param name="Scale">The object's scale (1 for the DAT's statics).</param>
/// <param name="State">Its physics state.</param>
/// <param name="Flags">Its shadow flags.</param>
public readonly record struct DatObjectDescription(uint Id, float Scale, PhysicsState State, ShadowFlags Flags);
