using System.Numerics;

namespace AcDream.Core.Physics.Bsp;

/// <summary>A node of a <see cref="BspTree"/> in its flat, validated form.</summary>
internal readonly struct BspNode
{
    /// <summary>Internal nodes: the unit split plane.</summary>
    public readonly Plane SplitPlane;
    /// <summary>The bounding sphere of everything below the node.</summary>
    public readonly Sphere Bounds;
    /// <summary>Front child index or -1.</summary>
    public readonly int Front;
    /// <summary>Back child index or -1.</summary>
    public readonly int Back;
    /// <summary>First entry of this node's polygons in <see cref="BspTree.PolygonIndices"/>.</summary>
    public readonly int FirstPolygon;
    /// <summary>How many polygons this node holds.</summary>
    public readonly int PolygonCount;
    /// <summary>True for a leaf.</summary>
    public readonly bool IsLeaf;
    /// <summary>Leaves: inside the solid.</summary>
    public readonly bool Solid;

    internal BspNode(Plane plane, Sphere bounds, int front, int back, int firstPolygon, int polygonCount, bool isLeaf, bool solid)
    {
        SplitPlane = plane;
        Bounds = bounds;
        Front = front;
        Back = back;
        FirstPolygon = firstPolygon;
        PolygonCount = polygonCount;
        IsLeaf = isLeaf;
        Solid = solid;
    }
}
