using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Dat;

/// <summary>One static object of a <see cref="DatLandblock"/>: how the game describes it, its setup and where the DAT puts it.</summary>
/// <param name="Description">Its id, scale, state and flags.</param>
/// <param name="ModelId">The DAT model (Setup or GfxObj id) it was made from.</param>
/// <param name="Setup">Its setup (shared by every object of that model).</param>
/// <param name="Position">Its cell and landblock-local frame.</param>
public sealed record DatStaticObject(DatObjectDescription Description, uint ModelId, PhysicsSetup Setup, Position Position);
