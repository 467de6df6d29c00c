using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Bsp;

/// <summary>One node of a physics BSP tree, as given by a caller or a compiler (see <see cref="BspTree.Create"/>).</summary>
public sealed class BspNodeData
{
    /// <summary>True for a leaf; false for an internal node with a split plane.</summary>
    public bool IsLeaf { get; init; }
    /// <summary>Internal nodes: the split plane (front = positive side). The normal is normalized on load.</summary>
    public Plane SplitPlane { get; init; }
    /// <summary>Internal nodes: the index of the front (positive) child, or -1 for none.</summary>
    public int Front { get; init; } = -1;
    /// <summary>Internal nodes: the index of the back (negative) child, or -1 for none.</summary>
    public int Back { get; init; } = -1;
    /// <summary>Leaves: the leaf is inside the solid.</summary>
    public bool Solid { get; init; }
    /// <summary>The polygons (indices into the tree's polygon list) stored at this node; physics trees keep them in leaves.</summary>
    public IReadOnlyList<int> Polygons { get; init; } = Array.Empty<int>();
    /// <summary>The node's bounding sphere; when null it is computed from the polygons below the node.</summary>
    public Sphere? Bounds { get; init; }
}
