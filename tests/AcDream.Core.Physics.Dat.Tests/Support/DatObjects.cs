using AcDream.Core.Physics.Bsp;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatPolygon = DatReaderWriter.Types.Polygon;
using DatSphere = DatReaderWriter.Types.Sphere;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>
/// Test-side writers of the runtime's geometry as DatReaderWriter objects, field for field and bit for bit:
/// vertices in order, sidedness, the tree node by node with its spheres and solid flags. The inverse of the
/// adapter, written independently of it, so a round trip through a DAT file checks both.
/// </summary>
internal static class DatObjects
{
    /// <summary>Adds the polygon's vertices to <paramref name="vertices"/> (new ids each) and returns it as a DAT polygon.</summary>
    public static DatPolygon Polygon(Polygon polygon, VertexArray vertices)
    {
        var result = new DatPolygon
        {
            // No UV lists are stored with these flags.
            Stippling = StipplingType.NoPos | StipplingType.NoNeg,
            SidesType = polygon.Sides switch
            {
                PolygonSides.Single => CullMode.Landblock,
                PolygonSides.Double => CullMode.None,
                _ => CullMode.Clockwise,
            },
        };
        foreach (var v in polygon.Vertices)
        {
            ushort id = (ushort)vertices.Vertices.Count;
            vertices.Vertices.Add(id, new SWVertex { Origin = v, Normal = polygon.Plane.Normal });
            result.VertexIds.Add((short)id);
        }
        return result;
    }

    public static VertexArray NewVertexArray() => new() { VertexType = VertexType.CSWVertexType };

    /// <summary>The tree's polygons (keyed by their index plus <paramref name="firstId"/>) and nodes.</summary>
    public static PhysicsBSPTree PhysicsTree(BspTree tree, VertexArray vertices, Dictionary<ushort, DatPolygon> polygons, ushort firstId = 0)
    {
        var source = tree.PolygonArray;
        for (int i = 0; i < source.Length; i++)
            polygons.Add((ushort)(firstId + i), Polygon(source[i], vertices));
        return new PhysicsBSPTree { Root = PhysicsNode(tree, 0, firstId) };
    }

    private static PhysicsBSPNode PhysicsNode(BspTree tree, int index, ushort firstId)
    {
        var node = tree.NodeArray[index];
        var result = new PhysicsBSPNode { BoundingSphere = new DatSphere { Origin = node.Bounds.Center, Radius = node.Bounds.Radius } };
        if (node.IsLeaf)
        {
            result.Type = BSPNodeType.Leaf;
            result.LeafIndex = index;
            SetSolid(result, node.Solid ? 1 : 0);
            for (int k = 0; k < node.PolygonCount; k++)
                result.Polygons.Add((ushort)(firstId + tree.IndexArray[node.FirstPolygon + k]));
            return result;
        }
        if (node.PolygonCount != 0)
            throw new InvalidOperationException($"node {index} is internal and holds polygons: a DAT physics tree keeps them in leaves.");
        result.SplittingPlane = node.SplitPlane;
        result.Type = InternalType(node.Front >= 0, node.Back >= 0);
        if (node.Front >= 0) result.PosNode = PhysicsNode(tree, node.Front, firstId);
        if (node.Back >= 0) result.NegNode = PhysicsNode(tree, node.Back, firstId);
        return result;
    }

    public static CellBSPTree CellTree(BspTree tree) => new() { Root = CellNode(tree, 0) };

    private static CellBSPNode CellNode(BspTree tree, int index)
    {
        var node = tree.NodeArray[index];
        if (node.IsLeaf)
            return new CellBSPNode { Type = BSPNodeType.Leaf, LeafIndex = index };
        var result = new CellBSPNode { SplittingPlane = node.SplitPlane, Type = InternalType(node.Front >= 0, node.Back >= 0) };
        if (node.Front >= 0) result.PosNode = CellNode(tree, node.Front);
        if (node.Back >= 0) result.NegNode = CellNode(tree, node.Back);
        return result;
    }

    /// <summary>
    /// The node tag that makes the reader read the children present: 'BPIN' both, 'BPIn' front only, 'BpIN'
    /// back only, 'Bpnn' neither (not in DatReaderWriter's enum; its reader reads no child for it).
    /// </summary>
    public static BSPNodeType InternalType(bool front, bool back) =>
        (front, back) switch
        {
            (true, true) => BSPNodeType.BPIN,
            (true, false) => BSPNodeType.BPIn,
            (false, true) => BSPNodeType.BpIN,
            _ => (BSPNodeType)0x42706E6E,
        };

    /// <summary>PhysicsBSPNode.Solid has a private setter in DatReaderWriter 2.1.4.</summary>
    public static void SetSolid(PhysicsBSPNode node, int solid) =>
        typeof(PhysicsBSPNode).GetProperty(nameof(PhysicsBSPNode.Solid))!.SetValue(node, solid);

    /// <summary>A GfxObj holding a physics tree (or, for null, one without physics).</summary>
    public static GfxObj GfxObj(uint id, BspTree? tree)
    {
        var vertices = NewVertexArray();
        var gfx = new GfxObj { Id = id, VertexArray = vertices, Flags = tree is null ? 0 : GfxObjFlags.HasPhysics };
        if (tree is not null)
            gfx.PhysicsBSP = PhysicsTree(tree, vertices, gfx.PhysicsPolygons);
        return gfx;
    }
}
