using System.Numerics;

namespace AcDream.Core.Physics.Queries;

/// <summary>
/// The first surface a cast, a ray or a floor query met. Coordinates are in the landblock frame of the
/// query's start position (the frame of its cell id), like every position the engine takes.
/// </summary>
public readonly struct SurfaceHit
{
    internal SurfaceHit(float fraction, Vector3 center, Vector3 point, Vector3 normal, uint cellId, uint objectId, SurfaceKind kind)
    {
        Fraction = fraction;
        Center = center;
        Point = point;
        Normal = normal;
        CellId = cellId;
        ObjectId = objectId;
        Kind = kind;
    }

    /// <summary>How far along the cast the contact happened, 0 (at the start) to 1 (at the end).</summary>
    public float Fraction { get; }
    /// <summary>Where the swept sphere's centre is at contact (for a ray, the same as <see cref="Point"/>).</summary>
    public Vector3 Center { get; }
    /// <summary>The contact point on the surface.</summary>
    public Vector3 Point { get; }
    /// <summary>The unit contact normal, pointing from the surface towards the cast's centre (a face's normal for a face hit).</summary>
    public Vector3 Normal { get; }
    /// <summary>
    /// The cell whose geometry was hit (the land cell under the point for terrain, the indoor cell, the
    /// land cell a building stands in), or for an object the cell of its position.
    /// </summary>
    public uint CellId { get; }
    /// <summary>The object hit, or 0 for the environment.</summary>
    public uint ObjectId { get; }
    /// <summary>What was hit.</summary>
    public SurfaceKind Kind { get; }

    /// <inheritdoc />
    public override string ToString() =>
        $"{Kind} cell 0x{CellId:X8}{(ObjectId != 0 ? $" object 0x{ObjectId:X8}" : "")} at {Point} n={Normal} fraction {Fraction}";
}
