using AcDream.Core.Physics.World;

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

/// <summary>Describes static object <paramref name="index"/> of a landblock (its LandBlockInfo's objects first, then each env cell's, in order).</summary>
/// <param name="landblock">The landblock (0xXXYY).</param>
/// <param name="index">The object's index among the landblock's static objects.</param>
/// <param name="owner">The DAT object that places it: the LandBlockInfo (0xXXYYFFFE) or an EnvCell (0xXXYY0100 and up).</param>
/// <param name="ownerIndex">Its index in the owner's list (<c>Objects</c> or <c>StaticObjects</c>).</param>
/// <param name="placement">The model and position the DAT gives it.</param>
public delegate DatObjectDescription DatObjectDescriber(uint landblock, int index, uint owner, int ownerIndex, DatPlacement placement);
