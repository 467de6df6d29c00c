namespace AcDream.Core.Physics.Viewer;

/// <summary>What a <see cref="ViewShape"/> belongs to, as the viewer colours it.</summary>
internal enum ViewSource : byte
{
    /// <summary>One of a land cell's two terrain triangles.</summary>
    Terrain,
    /// <summary>An indoor cell's physics BSP polygon (walls, floors, stairs).</summary>
    EnvCell,
    /// <summary>An indoor cell's portal polygon (not collided with; where the cell opens onto another).</summary>
    Portal,
    /// <summary>A building shell's polygon.</summary>
    Building,
    /// <summary>An object's collision shape.</summary>
    Object,
}
