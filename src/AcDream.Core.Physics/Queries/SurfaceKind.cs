namespace AcDream.Core.Physics.Queries;

/// <summary>What a cast or a floor query hit.</summary>
public enum SurfaceKind : byte
{
    /// <summary>Nothing.</summary>
    None = 0,
    /// <summary>The terrain of an outdoor land cell.</summary>
    Terrain,
    /// <summary>An indoor cell's physics BSP (walls, floors, stairs).</summary>
    EnvCell,
    /// <summary>A building's shell.</summary>
    Building,
    /// <summary>A registered object (see <see cref="SurfaceHit.ObjectId"/>).</summary>
    Object,
}
