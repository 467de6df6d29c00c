namespace AcDream.Core.Physics.Dat;

/// <summary>
/// A static object as the DAT places it (a landblock's <c>LandBlockInfo.Objects</c> or an env cell's
/// <c>StaticObjects</c>, retail <c>Stab</c>): the model it shows and where. The DAT id is the model, not the
/// object: the caller gives each placement an object id of its own when it registers it, and the object's
/// state (static, ethereal, …) and scale, which come from the game, not the DAT.
/// </summary>
/// <param name="ModelId">A Setup (0x02xxxxxx) or GfxObj (0x01xxxxxx) id.</param>
/// <param name="Position">The cell and landblock-local frame.</param>
public readonly record struct DatPlacement(uint ModelId, Position Position);
