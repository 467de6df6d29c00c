namespace AcDream.Core.Physics.Dat;

/// <summary>Describes static object <paramref name="index"/> of a landblock (its LandBlockInfo's objects first, then each env cell's, in order).</summary>
/// <param name="landblock">The landblock (0xXXYY).</param>
/// <param name="index">The object's index among the landblock's static objects.</param>
/// <param name="owner">The DAT object that places it: the LandBlockInfo (0xXXYYFFFE) or an EnvCell (0xXXYY0100 and up).</param>
/// <param name="ownerIndex">Its index in the owner's list (<c>Objects</c> or <c>StaticObjects</c>).</param>
/// <param name="placement">The model and position the DAT gives it.</param>
public delegate DatObjectDescription DatObjectDescriber(uint landblock, int index, uint owner, int ownerIndex, DatPlacement placement);
