namespace AcDream.Core.Physics.World;

/// <summary>
/// A cell of the world (retail CObjCell): an outdoor LandCell or an indoor
/// EnvCell. A cell exposes its own geometry (the transition collides with it); the objects in it live
/// in the ShadowObjectRegistry.
/// </summary>
public abstract class Cell
{
    /// <summary>Creates a cell.</summary>
    private protected Cell(uint id) => Id = id;

    /// <summary>The retail cell id (landblock &lt;&lt; 16 | cell).</summary>
    public uint Id { get; }

    /// <summary>
    /// How far a landblock-local point lies outside this cell, in metres (0 inside), roughly: used only to
    /// refuse positions that name a cell far from where they are (see <see cref="Validation.InputLimits.MaxDistanceFromCell"/>).
    /// </summary>
    internal abstract float DistanceOutside(System.Numerics.Vector3 point);

    /// <inheritdoc />
    public override string ToString() => $"{GetType().Name} 0x{Id:X8}";
}
