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
/// DAT polygons and BSP trees (retail CPolygon, BSPTREE of a GfxObj or a CellStruct) to the runtime's, keeping
/// retail's order and bits (docs/dat-mapping.md): vertices in <c>VertexIds</c> order, the sidedness as stored,
/// the polygon list in stored order, the tree node by node with every node's bounding sphere and every leaf's
/// solid flag and polygon order. Any refusal is a <see cref="DatObjectException"/> naming the owning object
/// and the field.
/// </summary>
public static class DatGeometry
{
    /// <summary>
    /// The most nodes a DAT BSP tree may have (a guard against a damaged or hand-made cyclic object: retail's
    /// largest trees hold a few thousand; leaf polygon ids are 16-bit).
    /// </summary>
    public const int MaxBspNodes = 65_536;

    private const string Unnamed = "polygon";

    /// <summary>
    /// Converts one DAT polygon: its vertices looked up in <paramref name="vertexArray"/> in <c>VertexIds</c>
    /// order, and its <c>SidesType</c> (retail <c>sides_type</c>): 0 single-sided, 2 both sides, any other
    /// value double (retail only asks whether it is 0, <c>CPolygon::polygon_hits_ray</c>).
    /// </summary>
    /// <param name="objectId">The owning DAT object (for messages).</param>
    /// <param name="field">The polygon's path inside the object, e.g. <c>physicsPolygons[17]</c>.</param>
    /// <param name="polygon">The DAT polygon.</param>
    /// <param name="vertexArray">The owner's vertex array.</param>
    /// <exception cref="DatObjectException">A vertex id is not in the array, or our <see cref="Polygon"/> rejects it (fewer than 3 or more than <see cref="InputLimits.MaxPolygonVertices"/> vertices, not planar, not convex, a repeated vertex).</exception>
    public static Polygon ToPolygon(uint objectId, string field, DatPolygon polygon, VertexArray vertexArray) =>
        ConvertPolygon(objectId, field, -1, polygon, vertexArray);

    // The polygon's field is <owner>.polygons[<key>] when the key is not -1. That string and the polygon's name are
    // built only for a message: a landblock's load converts hundreds of polygons and refuses none.
    private static string FieldOf(string owner, int key) => key < 0 ? owner : $"{owner}.polygons[{key}]";

    internal static Polygon ConvertPolygon(uint objectId, string owner, int key, DatPolygon polygon, VertexArray vertexArray)
    {
        if (polygon is null)
            throw new DatObjectException(objectId, $"{FieldOf(owner, key)}: is null.");
        if (vertexArray?.Vertices is null)
            throw new DatObjectException(objectId, $"{FieldOf(owner, key)}: the vertex array is missing.");
        var ids = polygon.VertexIds;
        int count = ids?.Count ?? 0;
        if (count < 3 || count > InputLimits.MaxPolygonVertices)
            throw new DatObjectException(objectId, $"{FieldOf(owner, key)}.vertexIds: a polygon has 3 to {InputLimits.MaxPolygonVertices} vertices (InputLimits.MaxPolygonVertices), got {count}.");
        // The polygon copies its vertices: gathered on the stack (at most 127 of them).
        Span<Vector3> vertices = stackalloc Vector3[count];
        for (int i = 0; i < count; i++)
        {
            short id = ids![i];
            if (id < 0 || !vertexArray.Vertices.TryGetValue((ushort)id, out var vertex) || vertex is null)
                throw new DatObjectException(objectId, $"{FieldOf(owner, key)}.vertexIds[{i}]: vertex {id} is not in the vertex array.");
            vertices[i] = vertex.Origin;
        }
        var sides = polygon.SidesType switch
        {
            CullMode.Landblock => PolygonSides.Single,
            CullMode.Clockwise => PolygonSides.Both,
            _ => PolygonSides.Double,
        };
        try
        {
            return new Polygon(vertices, sides, Unnamed);
        }
        catch (ArgumentException)
        {
        }
        // Refused: converted again under its full name, which refuses it the same way, for the message.
        try
        {
            return new Polygon(vertices, sides, $"{DatObjectException.KindOf(objectId)} 0x{objectId:X8} {FieldOf(owner, key)}");
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(objectId, $"{FieldOf(owner, key)}: {ex.Message}", ex);
        }
    }

    /// <summary>
    /// Converts a physics BSP (<c>GfxObj.PhysicsBSP</c> or <c>CellStruct.PhysicsBSP</c>) and the polygons its
    /// leaves name. The tree's polygon list is <paramref name="polygons"/> in stored order; the nodes are
    /// numbered root first, then each node's front (<c>PosNode</c>) subtree before its back (<c>NegNode</c>)
    /// subtree; every node keeps its <c>BoundingSphere</c> (retail <c>sphere</c>), every leaf its <c>Solid</c>
    /// flag and its polygon ids in stored order.
    /// </summary>
    /// <param name="objectId">The owning DAT object (for messages).</param>
    /// <param name="field">The tree's path inside the object, e.g. <c>physicsBSP</c>.</param>
    /// <param name="tree">The DAT tree; its root must be set.</param>
    /// <param name="polygons">The physics polygons by id, in stored order.</param>
    /// <param name="vertexArray">The owner's vertex array.</param>
    /// <exception cref="DatObjectException">A polygon is refused (see <see cref="ToPolygon"/>), a node is reached twice (a cycle or a shared subtree), the tree has more than <see cref="MaxBspNodes"/> nodes or is deeper than <see cref="InputLimits.MaxBspDepth"/>, a leaf names a polygon that is not in the list, a node lacks its sphere, a node is a portal node, or the runtime refuses a plane or a sphere.</exception>
    public static BspTree ToPhysicsBsp(uint objectId, string field, PhysicsBSPTree tree, Dictionary<ushort, DatPolygon> polygons, VertexArray vertexArray)
    {
        if (polygons is null)
            throw new DatObjectException(objectId, $"{field}: the polygon list is missing.");
        return DatBspBuilder.Current.TryPhysics(objectId, field, tree, polygons, vertexArray)
            ?? CheckedPhysicsBsp(objectId, field, tree, polygons, vertexArray);
    }

    // The conversion the one-pass builder mirrors, run when the builder gives up: it refuses with the message.
    private static BspTree CheckedPhysicsBsp(uint objectId, string field, PhysicsBSPTree tree, Dictionary<ushort, DatPolygon> polygons, VertexArray vertexArray)
    {
        var list = new List<Polygon>(polygons.Count);
        var index = new Dictionary<ushort, int>(polygons.Count);
        foreach (var (id, polygon) in polygons)
        {
            index.Add(id, list.Count);
            list.Add(ConvertPolygon(objectId, field, id, polygon, vertexArray));
        }
        var order = Flatten(objectId, field, tree?.Root, n => n.PosNode, n => n.NegNode);
        var nodes = new BspNodeData[order.Count];
        var position = IndexOf(order);
        for (int i = 0; i < order.Count; i++)
        {
            var node = order[i];
            var sphere = node.BoundingSphere ?? throw new DatObjectException(objectId, $"{field}.nodes[{i}].boundingSphere: is missing.");
            var bounds = new Sphere(sphere.Origin, sphere.Radius);
            if (node.Type == BSPNodeType.Leaf)
            {
                var ids = node.Polygons ?? new List<ushort>();
                var leafPolygons = new int[ids.Count];
                for (int k = 0; k < ids.Count; k++)
                    leafPolygons[k] = index.TryGetValue(ids[k], out int p)
                        ? p
                        : throw new DatObjectException(objectId, $"{field}.nodes[{i}].polygons[{k}]: polygon {ids[k]} is not among the tree's polygons.");
                nodes[i] = new BspNodeData { IsLeaf = true, Solid = node.Solid != 0, Polygons = leafPolygons, Bounds = bounds };
            }
            else
            {
                nodes[i] = new BspNodeData
                {
                    SplitPlane = node.SplittingPlane,
                    Front = node.PosNode is null ? -1 : position[node.PosNode],
                    Back = node.NegNode is null ? -1 : position[node.NegNode],
                    Bounds = bounds,
                };
            }
        }
        return Create(objectId, field, list, nodes);
    }

    /// <summary>
    /// Converts a containment tree (<c>CellStruct.CellBSP</c>, retail <c>cell_bsp</c>): split planes and leaves,
    /// no polygons and no spheres, numbered as in <see cref="ToPhysicsBsp"/>. The containment queries follow the
    /// chain of front children as retail's <c>BSPNODE::point_inside_cell_bsp</c> does.
    /// </summary>
    /// <param name="objectId">The owning DAT object (for messages).</param>
    /// <param name="field">The tree's path inside the object, e.g. <c>cells[2].cellBSP</c>.</param>
    /// <param name="tree">The DAT tree; its root must be set.</param>
    /// <exception cref="DatObjectException">A node is reached twice, the tree is too large or too deep, a node is a portal node, or the runtime refuses a plane.</exception>
    public static BspTree ToCellBsp(uint objectId, string field, CellBSPTree tree) =>
        DatBspBuilder.Current.TryCell(tree) ?? CheckedCellBsp(objectId, field, tree);

    private static BspTree CheckedCellBsp(uint objectId, string field, CellBSPTree tree)
    {
        var order = Flatten(objectId, field, tree?.Root, n => n.PosNode, n => n.NegNode);
        var position = IndexOf(order);
        var nodes = new BspNodeData[order.Count];
        for (int i = 0; i < order.Count; i++)
        {
            var node = order[i];
            nodes[i] = node.Type == BSPNodeType.Leaf
                ? new BspNodeData { IsLeaf = true }
                : new BspNodeData
                {
                    SplitPlane = node.SplittingPlane,
                    Front = node.PosNode is null ? -1 : position[node.PosNode],
                    Back = node.NegNode is null ? -1 : position[node.NegNode],
                };
        }
        return Create(objectId, field, Array.Empty<Polygon>(), nodes);
    }

    private static BspTree Create(uint objectId, string field, IReadOnlyList<Polygon> polygons, BspNodeData[] nodes)
    {
        try
        {
            return BspTree.Create(polygons, nodes, $"{DatObjectException.KindOf(objectId)} 0x{objectId:X8} {field}");
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(objectId, $"{field}: {ex.Message}", ex);
        }
    }

    private static Dictionary<T, int> IndexOf<T>(List<T> order) where T : class
    {
        var position = new Dictionary<T, int>(order.Count, ReferenceEqualityComparer.Instance);
        for (int i = 0; i < order.Count; i++)
            position.Add(order[i], i);
        return position;
    }

    /// <summary>
    /// The nodes in the order the runtime numbers them: root first, each node's front subtree, then its back
    /// subtree (the order the DAT stores them). Walked with an explicit stack, so a cyclic or very deep
    /// in-memory tree is refused instead of overflowing.
    /// </summary>
    private static List<T> Flatten<T>(uint objectId, string field, T? root, Func<T, T?> front, Func<T, T?> back) where T : BSPNode
    {
        if (root is null)
            throw new DatObjectException(objectId, $"{field}: has no root node.");
        var order = new List<T>();
        var seen = new HashSet<T>(ReferenceEqualityComparer.Instance);
        var stack = new Stack<(T Node, int Depth)>();
        stack.Push((root, 1));
        while (stack.Count > 0)
        {
            var (node, depth) = stack.Pop();
            int at = order.Count;
            if (!seen.Add(node))
                throw new DatObjectException(objectId, $"{field}.nodes[{at}]: the node is reached twice (a cycle or a shared subtree).");
            if (at == MaxBspNodes)
                throw new DatObjectException(objectId, $"{field}: has more than {MaxBspNodes} nodes (DatGeometry.MaxBspNodes).");
            if (depth > InputLimits.MaxBspDepth)
                throw new DatObjectException(objectId, $"{field}.nodes[{at}]: the tree is deeper than {InputLimits.MaxBspDepth} levels (InputLimits.MaxBspDepth).");
            if (node.Type == BSPNodeType.Portal)
                throw new DatObjectException(objectId, $"{field}.nodes[{at}]: a portal node (BSPPORTAL) has no place in a physics or cell tree.");
            order.Add(node);
            if (node.Type == BSPNodeType.Leaf)
                continue;
            // Back pushed first so the front subtree is numbered first.
            if (back(node) is { } b)
                stack.Push((b, depth + 1));
            if (front(node) is { } f)
                stack.Push((f, depth + 1));
        }
        return order;
    }
}
