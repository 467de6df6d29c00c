namespace AcDream.Core.Physics;

/// <summary>
/// How retail treats the back of a polygon (the DAT's SidesType / CullMode). A single-sided polygon
/// collides only from its front; the others collide from both sides.
/// </summary>
public enum PolygonSides : byte
{
    /// <summary>Front face only (SidesType 0).</summary>
    Single = 0,
    /// <summary>Both faces, same surface (SidesType 1).</summary>
    Double = 1,
    /// <summary>Both faces, separate surfaces (SidesType 2).</summary>
    Both = 2,  // the last value: Polygon's constructor accepts Single to Both by a range check
}
