using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Tests.Bsp;

public class BspTreeValidationTests
{
    private static readonly Plane Up = new(Vector3.UnitZ, 0f);

    private static Polygon Quad() => BspShapes.FloorPolygon(Vector3.Zero, new Vector2(2, 2));

    private static BspNodeData Leaf(params int[] polygons) => new() { IsLeaf = true, Polygons = polygons };

    private static BspNodeData Split(int front, int back) => new() { SplitPlane = Up, Front = front, Back = back };

    private static ArgumentException Refused(IReadOnlyList<BspNodeData> nodes, int polygonCount = 1)
    {
        var polygons = Enumerable.Range(0, polygonCount).Select(_ => Quad()).ToList();
        return Assert.ThrowsAny<ArgumentException>(() => BspTree.Create(polygons, nodes, "gfx"));
    }

    [Fact]
    public void ValidTree_IsKeptInOrderAndComputesMissingBounds()
    {
        var tree = BspTree.Create([Quad()], [Split(1, 2), Leaf(), Leaf(0)]);
        Assert.Equal(3, tree.Nodes.Length);
        Assert.Equal(2, tree.Nodes[0].Back);
        Assert.Equal(1, tree.Nodes[2].PolygonCount);
        foreach (var v in tree.Polygons[0].Vertices)
            Assert.True(Vector3.Distance(tree.Bounds.Center, v) <= tree.Bounds.Radius + 1e-5f);
    }

    [Fact]
    public void NullArguments_Throw()
    {
        Assert.Equal("polygons", Assert.Throws<ArgumentNullException>(() => BspTree.Create(null!, [Leaf()])).ParamName);
        Assert.Equal("nodes", Assert.Throws<ArgumentNullException>(() => BspTree.Create([Quad()], null!)).ParamName);
    }

    [Fact]
    public void EmptyNodeList_Throws()
    {
        var e = Refused([]);
        Assert.Contains("gfx.nodes", e.Message);
        Assert.Contains("at least one node", e.Message);
    }

    [Fact]
    public void NullNode_ThrowsNamingIt()
        => Assert.StartsWith("gfx.nodes[2]: is null", Refused([Split(1, 2), Leaf(), null!]).Message);

    [Fact]
    public void NullPolygon_ThrowsNamingIt()
    {
        var e = Assert.Throws<ArgumentException>(() => BspTree.Create([Quad(), null!], [Leaf(0)], "gfx"));
        Assert.StartsWith("gfx.polygons[1]", e.Message);
    }

    [Theory]
    [InlineData(3, "front")]
    [InlineData(-2, "front")]
    [InlineData(100, "back")]
    public void ChildIndexOutOfRange_ThrowsNamingNodeAndField(int bad, string field)
    {
        var nodes = field == "front" ? new[] { Split(bad, 1), Leaf(), Leaf() } : new[] { Split(1, bad), Leaf(), Leaf() };
        var e = Refused(nodes);
        Assert.StartsWith($"gfx.nodes[0].{field}", e.Message);
        Assert.Contains($"child index {bad} is out of range 0..2", e.Message);
    }

    [Fact]
    public void Cycle_ThrowsNamingTheNodePointingBack()
    {
        // 0 -> 1 -> 2 -> back to 1 (an ancestor)
        var e = Refused([Split(1, 3), Split(2, 4), Split(1, 5), Leaf(), Leaf(), Leaf()]);
        Assert.StartsWith("gfx.nodes[2].front", e.Message);
        Assert.Contains("node 1 is referenced more than once", e.Message);
    }

    [Fact]
    public void PointingAtTheRoot_Throws()
    {
        var e = Refused([Split(1, 0), Leaf()]);
        Assert.StartsWith("gfx.nodes[0].back", e.Message);
        Assert.Contains("node 0", e.Message);
    }

    [Fact]
    public void SharedSubtree_ThrowsNamingTheSecondReference()
    {
        var e = Refused([Split(1, 1), Leaf()]);
        Assert.Contains("referenced more than once", e.Message);
        Assert.Contains("node 1", e.Message);
        Assert.Matches(@"^gfx\.nodes\[0\]\.(front|back)", e.Message);

        e = Refused([Split(1, 2), Split(3, 4), Split(3, 5), Leaf(), Leaf(), Leaf()]);
        Assert.Contains("node 3 is referenced more than once", e.Message);
    }

    [Fact]
    public void UnreachableNode_ThrowsNamingIt()
    {
        var e = Refused([Split(1, 2), Leaf(), Leaf(), Leaf(0)]);
        Assert.StartsWith("gfx.nodes[3]: is not reachable", e.Message);
    }

    [Fact]
    public void ChildrenOfALeaf_AreIgnored_SoTheirTargetsAreUnreachable()
    {
        var e = Refused([new BspNodeData { IsLeaf = true, Front = 1 }, Leaf()]);
        Assert.StartsWith("gfx.nodes[1]: is not reachable", e.Message);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(-1)]
    public void PolygonIndexOutOfRange_ThrowsNamingNodeAndEntry(int bad)
    {
        var e = Refused([Split(1, 2), Leaf(), Leaf(0, bad)]);
        Assert.StartsWith("gfx.nodes[2].polygons[1]", e.Message);
        Assert.Contains($"polygon index {bad} is out of range 0..0", e.Message);
    }

    [Fact]
    public void PolygonIndexOnAnInternalNode_IsCheckedToo()
    {
        var e = Refused([new BspNodeData { SplitPlane = Up, Front = 1, Back = 2, Polygons = [5] }, Leaf(), Leaf()]);
        Assert.StartsWith("gfx.nodes[0].polygons[0]", e.Message);
    }

    public static TheoryData<Plane, string> BadPlanes => new()
    {
        { new Plane(new Vector3(float.NaN, 0, 1), 0), "gfx.nodes[1].splitPlane.normal" },
        { new Plane(new Vector3(0, float.PositiveInfinity, 1), 0), "gfx.nodes[1].splitPlane.normal" },
        { new Plane(Vector3.UnitZ, float.NaN), "gfx.nodes[1].splitPlane.d" },
        { new Plane(Vector3.UnitZ, float.NegativeInfinity), "gfx.nodes[1].splitPlane.d" },
        { new Plane(Vector3.Zero, 1), "gfx.nodes[1].splitPlane.normal: has zero length" },
        { new Plane(new Vector3(1e-7f, 0, 0), 1), "gfx.nodes[1].splitPlane.normal: has zero length" },
    };

    [Theory]
    [MemberData(nameof(BadPlanes))]
    public void BadSplitPlane_ThrowsNamingNodeAndField(Plane plane, string expected)
    {
        var e = Refused([Split(1, 2), new BspNodeData { SplitPlane = plane, Front = 3, Back = 4 }, Leaf(), Leaf(), Leaf()]);
        Assert.StartsWith(expected, e.Message);
    }

    [Fact]
    public void SplitPlane_IsNormalizedOnLoad()
    {
        var tree = BspTree.Create([Quad()], [new BspNodeData { SplitPlane = new Plane(new Vector3(0, 0, 2), -4), Front = 1, Back = 2 }, Leaf(), Leaf(0)]);
        Assert.Equal(new Plane(Vector3.UnitZ, -2), tree.Nodes[0].SplitPlane);
    }

    [Theory]
    [InlineData(float.NaN, 1f, "gfx.nodes[1].bounds.center")]
    [InlineData(0f, -1f, "gfx.nodes[1].bounds.radius")]
    [InlineData(0f, float.PositiveInfinity, "gfx.nodes[1].bounds.radius")]
    public void BadGivenBounds_ThrowNamingNodeAndField(float x, float radius, string expected)
    {
        var e = Refused([Split(1, 2), new BspNodeData { IsLeaf = true, Bounds = new Sphere(new Vector3(x, 0, 0), radius) }, Leaf()]);
        Assert.StartsWith(expected, e.Message);
    }

    // ---------- polygons (refused by Polygon's constructor, before a tree can be built) ----------

    [Theory]
    [InlineData(0)]
    [InlineData(2)]
    public void PolygonWithFewerThanThreeVertices_ThrowsNamingIt(int count)
    {
        var vertices = new[] { Vector3.Zero, Vector3.UnitX }.Take(count).ToArray();
        var e = Assert.Throws<ArgumentException>(() => new Polygon(vertices, name: "gfx.polygons[7]"));
        Assert.StartsWith("gfx.polygons[7]", e.Message);
        Assert.Contains($"at least 3 vertices, got {count}", e.Message);
    }

    [Fact]
    public void CollinearPolygon_ThrowsNamingIt()
    {
        var e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.Zero, new(1, 1, 1), new(2, 2, 2), new(3, 3, 3)], name: "gfx.polygons[3]"));
        Assert.StartsWith("gfx.polygons[3]: degenerate", e.Message);
    }

    [Fact]
    public void RepeatedVertexPolygon_ThrowsAsDegenerate()
    {
        var e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.UnitX, Vector3.UnitX, Vector3.UnitX], name: "p"));
        Assert.Contains("degenerate", e.Message);
    }

    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    [InlineData(float.NegativeInfinity)]
    public void NonFiniteVertex_ThrowsNamingTheVertex(float bad)
    {
        var e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.Zero, Vector3.UnitX, new(0, 1, bad)], name: "gfx.polygons[0]"));
        Assert.StartsWith("gfx.polygons[0].vertices[2]", e.Message);
    }

    [Fact]
    public void UnknownSidedness_ThrowsNamingIt()
    {
        var e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.Zero, Vector3.UnitX, Vector3.UnitY], (PolygonSides)7, "gfx.polygons[0]"));
        Assert.StartsWith("gfx.polygons[0].sides", e.Message);
    }
}
