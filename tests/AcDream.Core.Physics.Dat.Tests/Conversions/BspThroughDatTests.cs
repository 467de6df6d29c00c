using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Dat.Tests.Support;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Lib.IO;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests.Conversions;

/// <summary>
/// Multi-node physics trees written as DAT GfxObjs, read back from a DAT file and converted: the tree is the
/// given one node for node, and it answers every collision query as the given tree does.
/// </summary>
public class BspThroughDatTests
{
    private static BspTree ThroughFile(BspTree tree, uint id = 0x0100_0010)
    {
        using var files = WrittenDats.Write([DatObjects.GfxObj(id, tree)], Array.Empty<IDBObj>());
        var model = DatModels.ToPhysicsModel(files.Get<GfxObj>(files.Portal, id));
        Assert.NotNull(model);
        Assert.Equal(model!.Bsp.Bounds, model.BoundingSphere);
        return model.Bsp;
    }

    /// <summary>The same answers to point and sphere queries over a grid around the tree.</summary>
    private static void SameCollisions(BspTree expected, BspTree actual)
    {
        int solid = 0;
        for (float x = -3f; x <= 3f; x += 0.37f)
            for (float y = -3f; y <= 3f; y += 0.41f)
                for (float z = -1f; z <= 4f; z += 0.43f)
                {
                    var p = new Vector3(x, y, z);
                    bool hit = BspQuery.PointIntersectsSolid(expected, p);
                    Assert.Equal(hit, BspQuery.PointIntersectsSolid(actual, p));
                    var sphere = new Sphere(p, 0.48f);
                    Assert.Equal(BspQuery.SphereIntersectsSolid(expected, sphere), BspQuery.SphereIntersectsSolid(actual, sphere));
                    Assert.Equal(BspQuery.SphereIntersectsSolid(expected, sphere, centerCheck: false), BspQuery.SphereIntersectsSolid(actual, sphere, centerCheck: false));
                    if (hit) solid++;
                }
        Assert.True(solid > 0, "the grid never met the solid: the comparison would prove nothing");
    }

    [Fact]
    public void ACompiledTree_ThroughADatFile_IsTheSameTree()
    {
        var polygons = BspShapes.BoxPolygons(new Vector3(-1, -1, 0), new Vector3(1, 1, 2))
            .Concat(BspShapes.SlabPolygons(new Vector3(0, 1.8f, 0.5f), new Vector3(1, 0.5f, 0.4f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f)))
            .ToArray();
        var tree = BspCompiler.Compile(polygons, "box and slab");
        Assert.True(tree.NodeArray.Length > 3, "the compiled tree should have several nodes");

        var read = ThroughFile(tree);

        TreeAssert.Same(tree, read, "compiled");
        SameCollisions(tree, read);
    }

    [Fact]
    public void AHandMadeTree_WithEmptyChildrenAndSolidLeaves_ThroughADatFile_IsTheSameTree()
    {
        var box = BspShapes.BoxPolygons(new Vector3(-1, -1, 0), new Vector3(1, 1, 2), PolygonSides.Double);
        var bounds = new Sphere(new Vector3(0, 0, 1), 1.8f);
        // Numbered as the DAT stores a tree (root, front subtree, back subtree), which is the order the adapter gives.
        var nodes = new List<BspNodeData>
        {
            // 0: split at x = 0.
            new() { SplitPlane = new Plane(Vector3.UnitX, 0), Front = 1, Back = 3, Bounds = bounds },
            // 1: only a back child (above z = 3 is empty space).
            new() { SplitPlane = new Plane(Vector3.UnitZ, -3), Front = -1, Back = 2, Bounds = bounds },
            // 2: a solid leaf with the +X face and the top, in that order.
            new() { IsLeaf = true, Solid = true, Polygons = [0, 4], Bounds = bounds },
            // 3: both children.
            new() { SplitPlane = new Plane(-Vector3.UnitZ, 3), Front = 4, Back = 6, Bounds = bounds },
            // 4: only a front child.
            new() { SplitPlane = new Plane(Vector3.UnitY, 0.5f), Front = 5, Back = -1, Bounds = bounds },
            // 5: a solid leaf, its polygons out of index order.
            new() { IsLeaf = true, Solid = true, Polygons = [5, 1, 2, 3], Bounds = bounds },
            // 6: an internal node with no child at all.
            new() { SplitPlane = new Plane(Vector3.UnitY, -2.5f), Front = -1, Back = -1, Bounds = new Sphere(new Vector3(0, 2.5f, 1), 0.5f) },
        };
        var tree = BspTree.Create(box, nodes, "hand-made");

        var read = ThroughFile(tree);

        TreeAssert.Same(tree, read, "hand-made");
        SameCollisions(tree, read);
    }

    [Fact]
    public void ASideIsKept_AndVerticesStayInStoredOrder()
    {
        var polygons = new[]
        {
            new Polygon([new(0, 0, 0), new(1, 0, 0), new(1, 1, 0), new(0, 1, 0)], PolygonSides.Single),
            new Polygon([new(0, 0, 1), new(0, 1, 1), new(1, 1, 1), new(1, 0, 1)], PolygonSides.Double),
            new Polygon([new(0, 0, 2), new(1, 0, 2), new(1, 1, 2)], PolygonSides.Both),
        };
        var tree = BspTree.Create(polygons, [new BspNodeData { IsLeaf = true, Polygons = [2, 0, 1] }], "sides");

        var read = ThroughFile(tree);

        Assert.Equal([PolygonSides.Single, PolygonSides.Double, PolygonSides.Both], read.PolygonArray.Select(p => p.Sides));
        Assert.Equal(new Vector3(0, 1, 1), read.PolygonArray[1].Vertices[1]);
        Assert.Equal(-Vector3.UnitZ, read.PolygonArray[1].Plane.Normal);
        Assert.Equal([2, 0, 1], read.IndexArray);
    }

    /// <summary>
    /// Polygon ids that are not their positions (a DAT may number them as it likes): the tree's polygons stay in
    /// stored order and each leaf's ids become positions in that order.
    /// </summary>
    [Fact]
    public void PolygonIdsThatAreNotTheirPositions_BecomePositionsInStoredOrder()
    {
        var faces = BspShapes.BoxPolygons(Vector3.Zero, Vector3.One);
        var vertices = DatObjects.NewVertexArray();
        var polygons = new Dictionary<ushort, DatReaderWriter.Types.Polygon>
        {
            [9] = DatObjects.Polygon(faces[0], vertices),
            [2] = DatObjects.Polygon(faces[1], vertices),
            [40] = DatObjects.Polygon(faces[2], vertices),
        };
        var leaf = new DatReaderWriter.Types.PhysicsBSPNode
        {
            Type = DatReaderWriter.Enums.BSPNodeType.Leaf,
            BoundingSphere = new DatReaderWriter.Types.Sphere { Origin = new Vector3(0.5f), Radius = 1f },
            Polygons = [40, 9, 2, 40],
        };

        var tree = DatGeometry.ToPhysicsBsp(0x0100_0011, "physicsBSP", new DatReaderWriter.Types.PhysicsBSPTree { Root = leaf }, polygons, vertices);

        Assert.Equal([2, 0, 1, 2], tree.IndexArray);
        Assert.Equal(faces[0].Vertices.ToArray(), tree.PolygonArray[0].Vertices.ToArray());
        Assert.Equal(faces[1].Vertices.ToArray(), tree.PolygonArray[1].Vertices.ToArray());
        Assert.Equal(faces[2].Vertices.ToArray(), tree.PolygonArray[2].Vertices.ToArray());
        var again = DatGeometry.ToPhysicsBsp(0x0100_0011, "physicsBSP", new DatReaderWriter.Types.PhysicsBSPTree { Root = leaf }, polygons, vertices);
        Assert.Equal([2, 0, 1, 2], again.IndexArray);
    }

    /// <summary>
    /// A valid tree is built by the one-pass builder itself (its checked fallback is for refusals only) and is the
    /// given tree; a containment tree gets the empty spheres the checked conversion computes for it.
    /// </summary>
    [Fact]
    public void AValidTree_IsBuiltInOnePass_AsTheSameTree()
    {
        var box = BspShapes.Box(new Vector3(-1, -2, 0), new Vector3(2, 1, 3));
        var gfx = DatObjects.GfxObj(0x0100_0012, box);
        var built = DatBspBuilder.Current.TryPhysics(gfx.Id, "physicsBSP", gfx.PhysicsBSP, gfx.PhysicsPolygons, gfx.VertexArray);
        Assert.NotNull(built);
        TreeAssert.Same(box, built!, "box");

        var room = BspShapes.CellBox(new Vector3(-1, -2, 0), new Vector3(2, 1, 3));
        var cell = DatBspBuilder.Current.TryCell(DatObjects.CellTree(room));
        Assert.NotNull(cell);
        TreeAssert.Same(room, cell!, "room", bounds: false);
        foreach (var node in cell!.NodeArray)
            Assert.True(node.Bounds.Center == Vector3.Zero && node.Bounds.Radius == 0f, $"room: a containment node's sphere is {node.Bounds}");
    }
}
