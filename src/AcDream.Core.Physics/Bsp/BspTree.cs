using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Bsp;

/// <summary>
/// A physics BSP tree (retail BSPTREE of a GfxObj or a cell) in a flat layout: nodes in one array, root
/// at index 0, children by index, each node's polygons as a range of <see cref="PolygonIndices"/>.
/// Immutable and validated on creation, so queries never meet a broken index.
/// Queries live in <see cref="BspQuery"/>.
/// </summary>
public sealed class BspTree
{
    private readonly BspNode[] _nodes;
    private readonly Polygon[] _polygons;
    private readonly int[] _polygonIndices;

    private BspTree(BspNode[] nodes, Polygon[] polygons, int[] polygonIndices)
    {
        _nodes = nodes;
        _polygons = polygons;
        _polygonIndices = polygonIndices;
        // No vertices: an empty box (min above max), which nothing touches.
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        var upMin = min;
        var upMax = max;
        foreach (var polygon in polygons)
        {
            bool facesUp = polygon.Plane.Normal.Z > UpFacingZ;
            foreach (var vertex in polygon.Vertices)
            {
                min = Vector3.Min(min, vertex);
                max = Vector3.Max(max, vertex);
                if (facesUp)
                {
                    upMin = Vector3.Min(upMin, vertex);
                    upMax = Vector3.Max(upMax, vertex);
                }
            }
        }
        PolygonsMin = min;
        PolygonsMax = max;
        UpFacingMin = upMin;
        UpFacingMax = upMax;
    }

    /// <summary>The normal's Z above which a polygon counts as facing up (see <see cref="UpFacingMin"/>).</summary>
    internal const float UpFacingZ = 1e-3f;

    /// <summary>
    /// The box of every polygon's vertices, in the tree's space (not retail). A sphere that does not reach
    /// it touches no polygon, and every polygon test of a move (not the solid tests of placement) then
    /// misses: see the part test that uses it (<c>PartCollision.MayTouchPolygons</c>).
    /// </summary>
    internal Vector3 PolygonsMin { get; }
    /// <summary>See <see cref="PolygonsMin"/>.</summary>
    internal Vector3 PolygonsMax { get; }
    /// <summary>
    /// The box of the polygons whose normal's Z is above <see cref="UpFacingZ"/>, in the tree's space: for a
    /// part standing upright, the only polygons the walkable searches can take when the walkable allowance
    /// is at least twice that (their normal must face the world's up more than the allowance).
    /// </summary>
    internal Vector3 UpFacingMin { get; }
    /// <summary>See <see cref="UpFacingMin"/>.</summary>
    internal Vector3 UpFacingMax { get; }

    /// <summary>The nodes; index 0 is the root.</summary>
    internal ReadOnlySpan<BspNode> Nodes => _nodes;
    /// <summary>The polygons the nodes refer to.</summary>
    public ReadOnlySpan<Polygon> Polygons => _polygons;
    /// <summary>The polygon index lists of all nodes, concatenated.</summary>
    internal ReadOnlySpan<int> PolygonIndices => _polygonIndices;
    /// <summary>The root's bounding sphere (retail BSPTREE::GetSphere).</summary>
    public Sphere Bounds => _nodes[0].Bounds;

    internal BspNode[] NodeArray => _nodes;
    internal Polygon[] PolygonArray => _polygons;
    internal int[] IndexArray => _polygonIndices;

    /// <summary>
    /// Builds a tree from explicit nodes (retail trees come prebuilt and their order matters, so the
    /// order is kept as given). Validates everything: the root is node 0, every child index is in range,
    /// no node is reached twice (no cycles, no sharing), every node is reachable, polygon indices are in
    /// range, planes and bounds are finite, and no leaf is deeper than <see cref="InputLimits.MaxBspDepth"/>
    /// levels (so a query is safe on a thread with a 256 KB stack). Errors name the node and field.
    /// </summary>
    public static BspTree Create(IReadOnlyList<Polygon> polygons, IReadOnlyList<BspNodeData> nodes, string name = "bsp")
    {
        ArgumentNullException.ThrowIfNull(polygons);
        ArgumentNullException.ThrowIfNull(nodes);
        if (nodes.Count == 0)
            throw new ArgumentException($"{name}.nodes: a BSP tree needs at least one node.", nameof(nodes));
        for (int p = 0; p < polygons.Count; p++)
            if (polygons[p] is null)
                throw new ArgumentException($"{name}.polygons[{p}]: is null.", nameof(polygons));

        var parent = new int[nodes.Count];
        Array.Fill(parent, -2);
        parent[0] = -1;
        var order = new Stack<(int Node, int Depth)>();
        order.Push((0, 1));
        int visited = 0;
        while (order.Count > 0)
        {
            var (i, depth) = order.Pop();
            visited++;
            // The queries recurse once per level: a depth limit keeps them within any thread's stack.
            if (depth > InputLimits.MaxBspDepth)
                throw new ArgumentException($"{name}.nodes[{i}]: the tree is deeper than {InputLimits.MaxBspDepth} levels (InputLimits.MaxBspDepth); node {i} is at depth {depth}.", nameof(nodes));
            var node = nodes[i] ?? throw new ArgumentException($"{name}.nodes[{i}]: is null.", nameof(nodes));
            if (node.IsLeaf)
                continue;
            if (!PlaneOk(node.SplitPlane))
                CheckPlane(node.SplitPlane, $"{name}.nodes[{i}].splitPlane");
            // Front then back, without an array per node.
            for (int side = 0; side < 2; side++)
            {
                int child = side == 0 ? node.Front : node.Back;
                string field = side == 0 ? "front" : "back";
                if (child == -1)
                    continue;
                if (child < 0 || child >= nodes.Count)
                    throw new ArgumentException($"{name}.nodes[{i}].{field}: child index {child} is out of range 0..{nodes.Count - 1}.", nameof(nodes));
                if (parent[child] != -2)
                    throw new ArgumentException($"{name}.nodes[{i}].{field}: node {child} is referenced more than once (a cycle or a shared subtree).", nameof(nodes));
                parent[child] = i;
                order.Push((child, depth + 1));
            }
        }
        if (visited != nodes.Count)
        {
            int orphan = Array.IndexOf(parent, -2);
            throw new ArgumentException($"{name}.nodes[{orphan}]: is not reachable from the root (node 0).", nameof(nodes));
        }

        var flat = new BspNode[nodes.Count];
        var indices = new List<int>();
        var polygonArray = new Polygon[polygons.Count];
        for (int p = 0; p < polygons.Count; p++)
            polygonArray[p] = polygons[p];

        // Children before parents, so computed bounds can use the children's.
        var postOrder = PostOrder(nodes);
        var starts = new int[nodes.Count];
        for (int i = 0; i < nodes.Count; i++)
        {
            starts[i] = indices.Count;
            var list = nodes[i].Polygons ?? Array.Empty<int>();
            for (int k = 0; k < list.Count; k++)
            {
                int p = list[k];
                if (p < 0 || p >= polygons.Count)
                    throw new ArgumentException($"{name}.nodes[{i}].polygons[{k}]: polygon index {p} is out of range 0..{polygons.Count - 1}.", nameof(nodes));
                indices.Add(p);
            }
        }
        foreach (int i in postOrder)
        {
            var node = nodes[i];
            int count = (node.Polygons ?? Array.Empty<int>()).Count;
            Sphere bounds;
            if (node.Bounds is { } given)
            {
                // The field names are built only for a message (a DAT load checks every node).
                if (!Guard.IsCoordinate(given.Center))
                    Guard.Finite(given.Center, $"{name}.nodes[{i}].bounds.center");
                if (!(given.Radius >= 0f) || !float.IsFinite(given.Radius))
                    Guard.NonNegative(given.Radius, $"{name}.nodes[{i}].bounds.radius");
                bounds = given;
            }
            else
            {
                bounds = ComputeBounds(node, count, starts[i], indices, polygonArray, flat);
            }
            var plane = node.IsLeaf ? default : Plane.Normalize(node.SplitPlane);
            flat[i] = new BspNode(plane, bounds, node.IsLeaf ? -1 : node.Front, node.IsLeaf ? -1 : node.Back,
                starts[i], count, node.IsLeaf, node.IsLeaf && node.Solid);
        }
        return new BspTree(flat, polygonArray, indices.ToArray());
    }

    /// <summary>
    /// Wraps arrays that a converter built in this class's flat layout and checked as <see cref="Create"/> would
    /// (<see cref="PlaneOk"/>, <see cref="BoundsOk"/>, children and polygon indices in range, every node reached
    /// once, no leaf deeper than <see cref="InputLimits.MaxBspDepth"/>): the DAT package's one-pass conversion.
    /// Takes ownership of the arrays.
    /// </summary>
    internal static BspTree FromChecked(BspNode[] nodes, Polygon[] polygons, int[] polygonIndices) =>
        new(nodes, polygons, polygonIndices);

    /// <summary>Whether <see cref="Create"/> keeps a given bounding sphere without a refusal (no allocation).</summary>
    internal static bool BoundsOk(Sphere bounds) =>
        Guard.IsCoordinate(bounds.Center) && bounds.Radius >= 0f && float.IsFinite(bounds.Radius);

    // What CheckPlane accepts, tested first so that its field name is built only for the message.
    internal static bool PlaneOk(Plane plane) =>
        Guard.IsCoordinate(plane.Normal) && MathF.Abs(plane.D) <= InputLimits.MaxCoordinate && !(plane.Normal.LengthSquared() < 1e-12f);

    private static void CheckPlane(Plane plane, string field)
    {
        Guard.Finite(plane.Normal, field, ".normal");
        // A distance is a coordinate: within ±InputLimits.MaxCoordinate, so products inside a query stay finite.
        Guard.Coordinate(plane.D, field, ".d");
        if (plane.Normal.LengthSquared() < 1e-12f)
            throw new ArgumentException($"{field}.normal: has zero length.", field);
    }

    private static List<int> PostOrder(IReadOnlyList<BspNodeData> nodes)
    {
        var result = new List<int>(nodes.Count);
        var stack = new Stack<(int Node, bool Expanded)>();
        stack.Push((0, false));
        while (stack.Count > 0)
        {
            var (i, expanded) = stack.Pop();
            if (expanded || nodes[i].IsLeaf)
            {
                result.Add(i);
                continue;
            }
            stack.Push((i, true));
            if (nodes[i].Front >= 0) stack.Push((nodes[i].Front, false));
            if (nodes[i].Back >= 0) stack.Push((nodes[i].Back, false));
        }
        return result;
    }

    /// <summary>A sphere around the node's own polygons and its children's bounds (centre of their box).</summary>
    private static Sphere ComputeBounds(BspNodeData node, int count, int start, List<int> indices, Polygon[] polygons, BspNode[] built)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        bool any = false;
        for (int k = 0; k < count; k++)
            foreach (var v in polygons[indices[start + k]].Vertices)
            {
                min = Vector3.Min(min, v);
                max = Vector3.Max(max, v);
                any = true;
            }
        if (!node.IsLeaf)
            foreach (int child in new[] { node.Front, node.Back })
            {
                if (child < 0) continue;
                var b = built[child].Bounds;
                if (b.Radius <= 0 && b.Center == Vector3.Zero) continue;
                min = Vector3.Min(min, b.Center - new Vector3(b.Radius));
                max = Vector3.Max(max, b.Center + new Vector3(b.Radius));
                any = true;
            }
        if (!any)
            return new Sphere(Vector3.Zero, 0f);
        var center = (min + max) * 0.5f;
        float radius = 0f;
        for (int k = 0; k < count; k++)
            foreach (var v in polygons[indices[start + k]].Vertices)
                radius = MathF.Max(radius, Vector3.Distance(center, v));
        if (!node.IsLeaf)
            foreach (int child in new[] { node.Front, node.Back })
            {
                if (child < 0) continue;
                var b = built[child].Bounds;
                if (b.Radius <= 0 && b.Center == Vector3.Zero) continue;
                radius = MathF.Max(radius, Vector3.Distance(center, b.Center) + b.Radius);
            }
        return new Sphere(center, radius);
    }
}
