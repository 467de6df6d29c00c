using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Validation;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatPolygon = DatReaderWriter.Types.Polygon;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// The one-pass conversion of a DAT BSP tree into the runtime's flat layout, with scratch kept per thread and
/// reused from tree to tree, so a landblock's load makes only the arrays the trees keep. It accepts exactly what
/// <see cref="DatGeometry"/>'s checked conversion (DAT walk, then <see cref="BspTree.Create"/>) accepts and builds
/// the same nodes bit for bit; on anything that conversion would refuse it gives up (null), and the checked
/// conversion runs to refuse it with its message. A load refuses nothing, so the refusals pay twice, not the load.
/// </summary>
internal sealed class DatBspBuilder
{
    [ThreadStatic]
    private static DatBspBuilder? t_current;

    /// <summary>This thread's builder (not reentrant; the conversions never nest).</summary>
    internal static DatBspBuilder Current => t_current ??= new DatBspBuilder();

    // The walk's stack, and per node in the runtime's order (root, front subtree, back subtree): the DAT node,
    // its children's positions, its first entry in the polygon index list and how many entries it has.
    private WalkEntry[] _stack = new WalkEntry[64];
    private BSPNode[] _order = new BSPNode[64];
    private int[] _front = new int[64];
    private int[] _back = new int[64];
    private int[] _first = new int[64];
    private int[] _count = new int[64];
    private int[] _indices = new int[256];
    private readonly HashSet<BSPNode> _seen = new(ReferenceEqualityComparer.Instance);
    private readonly Dictionary<ushort, int> _positions = new();

    private struct WalkEntry
    {
        public BSPNode Node;
        public int Depth;
        public int Parent;
        public bool IsBack;
    }

    /// <summary>
    /// The physics tree over <paramref name="polygons"/> (converted here, in stored order; a refused polygon
    /// throws as <see cref="DatGeometry.ToPhysicsBsp"/> does, which converts them first too), or null when the
    /// tree would be refused.
    /// </summary>
    internal BspTree? TryPhysics(uint objectId, string field, PhysicsBSPTree? tree, Dictionary<ushort, DatPolygon> polygons, VertexArray vertexArray)
    {
        var converted = polygons.Count == 0 ? Array.Empty<Polygon>() : new Polygon[polygons.Count];
        // DAT polygon ids are nearly always 0..n-1 in stored order: then an id is its own position.
        bool dense = true;
        int at = 0;
        foreach (var (id, polygon) in polygons)
        {
            dense &= id == at;
            converted[at++] = DatGeometry.ConvertPolygon(objectId, field, id, polygon, vertexArray);
        }
        _positions.Clear();
        if (!dense)
        {
            at = 0;
            foreach (var id in polygons.Keys)
                _positions.Add(id, at++);
        }
        int count = Walk(tree?.Root, static n => ((PhysicsBSPNode)n).PosNode, static n => ((PhysicsBSPNode)n).NegNode);
        if (count < 0)
            return null;
        int total = 0;
        for (int i = 0; i < count; i++)
        {
            var node = (PhysicsBSPNode)_order[i];
            if (node.BoundingSphere is not { } sphere || !BspTree.BoundsOk(new Sphere(sphere.Origin, sphere.Radius)))
                return Abandon(count);
            _first[i] = total;
            _count[i] = 0;
            if (node.Type == BSPNodeType.Leaf)
            {
                var ids = node.Polygons;
                int n = ids?.Count ?? 0;
                if (total + n > _indices.Length)
                    Array.Resize(ref _indices, Math.Max(total + n, _indices.Length * 2));
                for (int k = 0; k < n; k++)
                {
                    int position = PositionOf(ids![k], converted.Length, dense);
                    if (position < 0)
                        return Abandon(count);
                    _indices[total + k] = position;
                }
                _count[i] = n;
                total += n;
            }
            else if (!BspTree.PlaneOk(node.SplittingPlane))
            {
                return Abandon(count);
            }
        }
        var nodes = new BspNode[count];
        for (int i = 0; i < count; i++)
        {
            var node = (PhysicsBSPNode)_order[i];
            var bounds = new Sphere(node.BoundingSphere!.Origin, node.BoundingSphere.Radius);
            nodes[i] = node.Type == BSPNodeType.Leaf
                ? new BspNode(default, bounds, -1, -1, _first[i], _count[i], isLeaf: true, solid: node.Solid != 0)
                : new BspNode(Plane.Normalize(node.SplittingPlane), bounds, _front[i], _back[i], _first[i], 0, isLeaf: false, solid: false);
        }
        var indices = total == 0 ? Array.Empty<int>() : _indices.AsSpan(0, total).ToArray();
        Release(count);
        return BspTree.FromChecked(nodes, converted, indices);
    }

    /// <summary>The containment tree (split planes and leaves, every sphere empty), or null when it would be refused.</summary>
    internal BspTree? TryCell(CellBSPTree? tree)
    {
        int count = Walk(tree?.Root, static n => ((CellBSPNode)n).PosNode, static n => ((CellBSPNode)n).NegNode);
        if (count < 0)
            return null;
        // The checked conversion gives no spheres and no polygons, so it computes every node's sphere from nothing.
        var empty = new Sphere(Vector3.Zero, 0f);
        var nodes = new BspNode[count];
        for (int i = 0; i < count; i++)
        {
            var node = _order[i];
            if (node.Type == BSPNodeType.Leaf)
            {
                nodes[i] = new BspNode(default, empty, -1, -1, 0, 0, isLeaf: true, solid: false);
                continue;
            }
            if (!BspTree.PlaneOk(node.SplittingPlane))
                return Abandon(count);
            nodes[i] = new BspNode(Plane.Normalize(node.SplittingPlane), empty, _front[i], _back[i], 0, 0, isLeaf: false, solid: false);
        }
        Release(count);
        return BspTree.FromChecked(nodes, Array.Empty<Polygon>(), Array.Empty<int>());
    }

    private int PositionOf(ushort id, int polygonCount, bool dense)
    {
        if (dense)
            return id < polygonCount ? id : -1;
        return _positions.TryGetValue(id, out int position) ? position : -1;
    }

    /// <summary>
    /// Numbers the tree's nodes root first, then each node's front subtree before its back subtree, recording
    /// each node's children by position; -1 on whatever the checked walk refuses (no root, a node reached twice,
    /// too many nodes, too deep, a portal node).
    /// </summary>
    private int Walk(BSPNode? root, Func<BSPNode, BSPNode?> front, Func<BSPNode, BSPNode?> back)
    {
        if (root is null)
            return -1;
        int count = 0;
        int top = 0;
        _stack[top++] = new WalkEntry { Node = root, Depth = 1, Parent = -1 };
        while (top > 0)
        {
            var entry = _stack[--top];
            _stack[top] = default;
            var node = entry.Node;
            if (count == DatGeometry.MaxBspNodes || entry.Depth > InputLimits.MaxBspDepth
                || node.Type == BSPNodeType.Portal || !_seen.Add(node))
            {
                Array.Clear(_stack, 0, top);
                Release(count);
                return -1;
            }
            if (count == _order.Length)
                Grow();
            _order[count] = node;
            _front[count] = -1;
            _back[count] = -1;
            if (entry.Parent >= 0)
                (entry.IsBack ? _back : _front)[entry.Parent] = count;
            int at = count++;
            if (node.Type == BSPNodeType.Leaf)
                continue;
            if (top + 2 > _stack.Length)
                Array.Resize(ref _stack, _stack.Length * 2);
            // Back pushed first so the front subtree is numbered first.
            if (back(node) is { } b)
                _stack[top++] = new WalkEntry { Node = b, Depth = entry.Depth + 1, Parent = at, IsBack = true };
            if (front(node) is { } f)
                _stack[top++] = new WalkEntry { Node = f, Depth = entry.Depth + 1, Parent = at, IsBack = false };
        }
        return count;
    }

    private void Grow()
    {
        int size = _order.Length * 2;
        Array.Resize(ref _order, size);
        Array.Resize(ref _front, size);
        Array.Resize(ref _back, size);
        Array.Resize(ref _first, size);
        Array.Resize(ref _count, size);
    }

    /// <summary>Drops the references to the DAT nodes, so the scratch keeps no read object alive.</summary>
    private void Release(int count)
    {
        Array.Clear(_order, 0, count);
        _seen.Clear();
    }

    private BspTree? Abandon(int count)
    {
        Release(count);
        return null;
    }
}
