using AcDream.Core.Physics.Scenes;
using static AcDream.Core.Physics.Tests.Bsp.BspTestKit;
using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Tests.Bsp;

public class BspCompilerTests
{
    private static readonly Vector3 BoxMin = new(-1f, -2f, 0f);
    private static readonly Vector3 BoxMax = new(3f, 1f, 2.5f);

    // ---------- shape of the tree ----------

    [Fact]
    public void Box_CompilesToRetailClosedSolidForm()
    {
        var tree = BspShapes.Box(BoxMin, BoxMax);
        // 6 split nodes, 6 empty front leaves, 1 solid leaf holding the 6 faces.
        Assert.Equal(13, tree.Nodes.Length);
        int i = 0;
        for (int face = 0; face < 6; face++)
        {
            var node = tree.Nodes[i];
            Assert.False(node.IsLeaf);
            Assert.Equal(tree.Polygons[face].Plane.Normal, node.SplitPlane.Normal);
            var front = tree.Nodes[node.Front];
            Assert.True(front.IsLeaf);
            Assert.False(front.Solid);
            Assert.Equal(0, front.PolygonCount);
            Assert.Equal(0f, front.Bounds.Radius);
            Assert.Equal(node.Bounds.Center, front.Bounds.Center);
            i = node.Back;
        }
        var solid = tree.Nodes[i];
        Assert.True(solid.IsLeaf);
        Assert.True(solid.Solid);
        Assert.Equal(6, solid.PolygonCount);
        Assert.Equal(Enumerable.Range(0, 6), tree.PolygonIndices.Slice(solid.FirstPolygon, 6).ToArray());
    }

    [Fact]
    public void Box_PolygonsFaceOutwardAndKeepTheirInstances()
    {
        var polygons = BspShapes.BoxPolygons(BoxMin, BoxMax, PolygonSides.Double);
        var centre = (BoxMin + BoxMax) * 0.5f;
        var expected = new[] { Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitZ };
        Assert.Equal(6, polygons.Length);
        for (int k = 0; k < 6; k++)
        {
            Assert.Equal(PolygonSides.Double, polygons[k].Sides);
            Assert.True(Vector3.Distance(expected[k], polygons[k].Plane.Normal) < 1e-6f, $"face {k} normal {polygons[k].Plane.Normal}");
            Assert.True(Dist(polygons[k].Plane, centre) < 0, $"face {k} must have the centre behind it");
            Assert.Equal(4, polygons[k].VertexCount);
        }
        var tree = BspCompiler.Compile(polygons);
        for (int k = 0; k < 6; k++)
            Assert.Same(polygons[k], tree.Polygons[k]);
    }

    [Fact]
    public void Floor_IsOneSplitWithANonSolidLeafHoldingTheQuad()
    {
        var tree = BspShapes.Floor(new Vector3(5, 5, 1), new Vector2(4, 2));
        Assert.Equal(3, tree.Nodes.Length);
        Assert.Single(tree.Polygons.ToArray());
        Assert.Equal(Vector3.UnitZ, tree.Polygons[0].Plane.Normal);
        Assert.Equal(8f, Area(tree.Polygons[0]), 4);
        Assert.DoesNotContain(Leaves(tree), l => tree.Nodes[l].Solid);
        var back = tree.Nodes[tree.Nodes[0].Back];
        Assert.Equal(1, back.PolygonCount);
        Assert.False(InSolid(tree, new Vector3(5, 5, 0.5f)));
    }

    [Fact]
    public void InternalNodesAlwaysHaveBothChildren()
    {
        foreach (var tree in SampleTrees())
            foreach (var node in tree.Nodes)
                if (!node.IsLeaf)
                {
                    Assert.True(node.Front >= 0);
                    Assert.True(node.Back >= 0);
                }
    }

    // ---------- classification ----------

    [Fact]
    public void Box_RandomPointsClassify()
    {
        var tree = BspShapes.Box(BoxMin, BoxMax);
        AssertClassifies(tree, p => Inside(p, BoxMin, BoxMax), BoxMin - new Vector3(2), BoxMax + new Vector3(2), seed: 1);
    }

    [Fact]
    public void Slab_RotatedRandomPointsClassify()
    {
        var rotation = Quaternion.CreateFromYawPitchRoll(0.7f, 0.3f, -0.4f);
        var centre = new Vector3(10, -4, 2);
        var size = new Vector3(2, 0.5f, 1);
        var tree = BspShapes.Slab(centre, size, rotation);
        var inverse = Quaternion.Inverse(rotation);
        AssertClassifies(tree, p => Inside(Vector3.Transform(p - centre, inverse), -size / 2, size / 2),
            centre - new Vector3(2), centre + new Vector3(2), seed: 2);
    }

    [Fact]
    public void TwoSeparateBoxes_RandomPointsClassify()
    {
        Vector3 aMin = new(0, 0, 0), aMax = new(1, 1, 1), bMin = new(3, 0.5f, -1), bMax = new(4, 2, 0.5f);
        var tree = BspCompiler.Compile(BoxFaces(aMin, aMax).Concat(BoxFaces(bMin, bMax)).ToList());
        Assert.Equal(2, Leaves(tree).Count(l => tree.Nodes[l].Solid));
        AssertClassifies(tree, p => Inside(p, aMin, aMax) || Inside(p, bMin, bMax), new Vector3(-1, -1, -2), new Vector3(5, 3, 2), seed: 3);
    }

    [Fact]
    public void TouchingBoxes_RandomPointsClassify()
    {
        Vector3 aMin = new(0, 0, 0), aMax = new(1, 1, 1), bMin = new(1, 0, 0), bMax = new(2, 1, 1);
        var tree = BspCompiler.Compile(BoxFaces(aMin, aMax).Concat(BoxFaces(bMin, bMax)).ToList());
        AssertClassifies(tree, p => Inside(p, aMin, aMax) || Inside(p, bMin, bMax), new Vector3(-1), new Vector3(3, 2, 2), seed: 4);
    }

    [Fact]
    public void ConcaveLPrism_RandomPointsClassify()
    {
        var tree = BspCompiler.Compile(LPrism());
        AssertClassifies(tree, InsideL, new Vector3(-1), new Vector3(3, 3, 2), seed: 5);
    }

    [Fact]
    public void ManyRotatedSlabs_RandomPointsClassify()
    {
        var r = new Random(8);
        var slabs = new List<(Vector3 Centre, Vector3 Size, Quaternion Rotation)>();
        for (int k = 0; k < 9; k++)
            slabs.Add((new Vector3(k % 3 * 5f, k / 3 * 5f, (float)r.NextDouble()),
                new Vector3(1.5f + (float)r.NextDouble(), 1 + (float)r.NextDouble(), 0.8f + 0.8f * (float)r.NextDouble()),
                Quaternion.CreateFromYawPitchRoll((float)r.NextDouble() * 3, (float)r.NextDouble(), (float)r.NextDouble())));
        var tree = BspCompiler.Compile(slabs.SelectMany(s => BspShapes.SlabPolygons(s.Centre, s.Size, s.Rotation)).ToList());
        Assert.Equal(9, Leaves(tree).Count(l => tree.Nodes[l].Solid));
        AssertClassifies(tree, p => slabs.Any(s => Inside(Vector3.Transform(p - s.Centre, Quaternion.Inverse(s.Rotation)), -s.Size / 2, s.Size / 2)),
            new Vector3(-2, -2, -1.5f), new Vector3(12, 12, 2.5f), seed: 9);
    }

    [Fact]
    public void BoxMissingAFace_HasNoSolidLeaf()
    {
        var faces = BoxFaces(BoxMin, BoxMax);
        faces.RemoveAt(4);
        var tree = BspCompiler.Compile(faces);
        Assert.DoesNotContain(Leaves(tree), l => tree.Nodes[l].Solid);
        Assert.False(InSolid(tree, (BoxMin + BoxMax) / 2));
    }

    [Fact]
    public void Stair_OpenGeometry_NoSolidLeafAndAllAreaKept()
    {
        var steps = new List<Polygon>();
        for (int k = 0; k < 4; k++)
        {
            float x = k * 0.5f, z = k * 0.25f;
            steps.Add(Rect(new Vector3(x, 0, z), new Vector3(x, 1, z + 0.25f), -Vector3.UnitX));     // riser
            steps.Add(Rect(new Vector3(x, 0, z + 0.25f), new Vector3(x + 0.5f, 1, z + 0.25f), Vector3.UnitZ)); // tread
        }
        var tree = BspCompiler.Compile(steps);
        Assert.DoesNotContain(Leaves(tree), l => tree.Nodes[l].Solid);
        Assert.Equal(steps.Sum(Area), tree.Polygons.ToArray().Sum(Area), 4);
    }

    [Fact]
    public void InwardFacingRoom_CompilesToAFrontChainForCellQueries()
    {
        Vector3 min = new(0, 0, 0), max = new(4, 3, 2.5f);
        var walls = BoxFaces(min, max).Select(f => new Polygon(f.Vertices.ToArray().Reverse().ToArray())).ToList();
        var tree = BspCompiler.Compile(walls);
        var r = new Random(6);
        for (int k = 0; k < 500; k++)
        {
            var p = RandomIn(r, min - new Vector3(2), max + new Vector3(2));
            if (NearBoxSurface(p, min, max)) continue;
            Assert.Equal(Inside(p, min, max), InsideCell(tree, p));
        }
        Assert.DoesNotContain(Leaves(tree), l => tree.Nodes[l].Solid);
    }

    // ---------- splitting ----------

    [Fact]
    public void CrossingPolygons_AreSplitIntoConvexPiecesThatStayOnTheirSide()
    {
        var floor = Rect(new Vector3(-2, -2, 0), new Vector3(2, 2, 0), Vector3.UnitZ);
        var wall = Rect(new Vector3(0, -1, -1), new Vector3(0, 1, 1), Vector3.UnitX);
        var input = new List<Polygon> { floor, wall };
        var tree = BspCompiler.Compile(input);
        Assert.True(tree.Polygons.Length > 2, "one of the crossing polygons must be split");
        Assert.Equal(input.Sum(Area), tree.Polygons.ToArray().Sum(Area), 4);
        foreach (var p in tree.Polygons)
        {
            Assert.True(Vector3.Dot(p.Plane.Normal, Vector3.UnitZ) > 0.9999f || Vector3.Dot(p.Plane.Normal, Vector3.UnitX) > 0.9999f,
                $"split piece keeps an input orientation: {p}");
            Assert.True(p.VertexCount >= 3);
        }
    }

    [Fact]
    public void EveryLeafPolygonLiesOnItsLeafsSideOfEverySplitAbove()
    {
        foreach (var tree in SampleTrees())
            Walk(tree, 0, new List<(Plane Plane, bool Front)>());

        static void Walk(BspTree tree, int i, List<(Plane Plane, bool Front)> path)
        {
            var node = tree.Nodes[i];
            if (node.IsLeaf)
            {
                for (int k = 0; k < node.PolygonCount; k++)
                    foreach (var v in tree.Polygons[tree.PolygonIndices[node.FirstPolygon + k]].Vertices)
                        foreach (var (plane, front) in path)
                        {
                            float d = Dist(plane, v);
                            Assert.True(front ? d >= -2e-4f : d <= 2e-4f, $"leaf {i}: vertex {v} is on the wrong side ({d}) of {plane}");
                        }
                return;
            }
            Walk(tree, node.Front, [.. path, (node.SplitPlane, true)]);
            Walk(tree, node.Back, [.. path, (node.SplitPlane, false)]);
        }
    }

    // ---------- bounds ----------

    [Fact]
    public void EveryNodesBoundsContainItsPolygons()
    {
        foreach (var tree in SampleTrees())
            for (int i = 0; i < tree.Nodes.Length; i++)
            {
                var b = tree.Nodes[i].Bounds;
                foreach (var p in PolygonsBelow(tree, i))
                    foreach (var v in p.Vertices)
                        Assert.True(Vector3.Distance(b.Center, v) <= b.Radius + 1e-5f, $"node {i}: vertex {v} outside {b}");
            }
    }

    [Fact]
    public void BoundsOnThePathContainEverySolidPoint()
    {
        // The solid region must be inside the bounds of every node on the way down to its leaf.
        var tree = BspCompiler.Compile(LPrism());
        var r = new Random(7);
        int solid = 0;
        for (int k = 0; k < 2000; k++)
        {
            var p = RandomIn(r, new Vector3(-1), new Vector3(3, 3, 2));
            if (!InSolid(tree, p)) continue;
            solid++;
            foreach (int i in PathTo(tree, p))
            {
                var b = tree.Nodes[i].Bounds;
                Assert.True(Vector3.Distance(b.Center, p) <= b.Radius + 1e-5f, $"node {i}: solid point {p} outside {b}");
            }
        }
        Assert.True(solid > 100);
    }

    [Fact]
    public void BoxBounds_AreTheCircumscribedSphere()
    {
        var tree = BspShapes.Box(BoxMin, BoxMax);
        Assert.True(Vector3.Distance((BoxMin + BoxMax) / 2, tree.Bounds.Center) < 1e-5f);
        Assert.Equal(Vector3.Distance(BoxMin, BoxMax) / 2, tree.Bounds.Radius, 3);
    }

    // ---------- determinism ----------

    [Fact]
    public void SameInput_GivesIdenticalTree()
    {
        var a = BspCompiler.Compile(LPrism().Concat(BoxFaces(new(5, 5, 5), new(6, 7, 8))).ToList());
        var b = BspCompiler.Compile(LPrism().Concat(BoxFaces(new(5, 5, 5), new(6, 7, 8))).ToList());
        Assert.Equal(a.Nodes.Length, b.Nodes.Length);
        for (int i = 0; i < a.Nodes.Length; i++)
        {
            var x = a.Nodes[i];
            var y = b.Nodes[i];
            Assert.Equal((x.IsLeaf, x.Solid, x.Front, x.Back, x.FirstPolygon, x.PolygonCount), (y.IsLeaf, y.Solid, y.Front, y.Back, y.FirstPolygon, y.PolygonCount));
            Assert.Equal(x.SplitPlane, y.SplitPlane);
            Assert.Equal(x.Bounds.Center, y.Bounds.Center);
            Assert.Equal(x.Bounds.Radius, y.Bounds.Radius);
        }
        Assert.Equal(a.PolygonIndices.ToArray(), b.PolygonIndices.ToArray());
        Assert.Equal(a.Polygons.Length, b.Polygons.Length);
        for (int p = 0; p < a.Polygons.Length; p++)
            Assert.Equal(a.Polygons[p].Vertices.ToArray(), b.Polygons[p].Vertices.ToArray());
    }

    // ---------- bad input ----------

    [Fact]
    public void Compile_NullList_Throws()
    {
        var e = Assert.Throws<ArgumentNullException>(() => BspCompiler.Compile(null!));
        Assert.Equal("polygons", e.ParamName);
    }

    [Fact]
    public void Compile_EmptyList_ThrowsNamingTheList()
    {
        var e = Assert.Throws<ArgumentException>(() => BspCompiler.Compile(Array.Empty<Polygon>(), "door"));
        Assert.Contains("door", e.Message);
        Assert.Contains("at least one polygon", e.Message);
    }

    [Fact]
    public void Compile_NullEntry_ThrowsNamingTheIndex()
    {
        var list = new List<Polygon> { BspShapes.FloorPolygon(Vector3.Zero, Vector2.One), null! };
        var e = Assert.Throws<ArgumentException>(() => BspCompiler.Compile(list));
        Assert.Contains("polygons[1]", e.Message);
    }

    [Theory]
    [InlineData(1f, 0f, 0f, "max.X")]
    [InlineData(0f, 1f, 0f, "max.Y")]
    [InlineData(0f, 0f, 1f, "max.Z")]
    [InlineData(2f, 0f, 0f, "max.X")]
    public void Box_MinNotBelowMax_ThrowsNamingTheAxis(float dx, float dy, float dz, string field)
    {
        var min = new Vector3(0, 0, 0);
        var max = new Vector3(1, 1, 1) - new Vector3(dx, dy, dz);
        var e = Assert.Throws<ArgumentException>(() => BspShapes.Box(min, max));
        Assert.StartsWith(field, e.Message);
        e = Assert.Throws<ArgumentException>(() => BspShapes.BoxPolygons(min, max));
        Assert.StartsWith(field, e.Message);
    }

    [Fact]
    public void Box_NonFiniteCorner_ThrowsNamingIt()
    {
        Assert.StartsWith("min", Assert.Throws<ArgumentException>(() => BspShapes.Box(new Vector3(float.NaN, 0, 0), Vector3.One)).Message);
        Assert.StartsWith("max", Assert.Throws<ArgumentException>(() => BspShapes.Box(Vector3.Zero, new Vector3(1, float.PositiveInfinity, 1))).Message);
    }

    [Fact]
    public void FloorAndSlab_BadArguments_ThrowNamingTheField()
    {
        Assert.StartsWith("size.X", Assert.Throws<ArgumentException>(() => BspShapes.Floor(Vector3.Zero, new Vector2(0, 1))).Message);
        Assert.StartsWith("size.Y", Assert.Throws<ArgumentException>(() => BspShapes.Floor(Vector3.Zero, new Vector2(1, -1))).Message);
        Assert.StartsWith("center", Assert.Throws<ArgumentException>(() => BspShapes.Floor(new Vector3(float.NaN), Vector2.One)).Message);
        Assert.StartsWith("size.Z", Assert.Throws<ArgumentException>(() => BspShapes.Slab(Vector3.Zero, new Vector3(1, 1, 0), Quaternion.Identity)).Message);
        Assert.StartsWith("rotation", Assert.Throws<ArgumentException>(() => BspShapes.Slab(Vector3.Zero, Vector3.One, default)).Message);
    }

    [Fact]
    public void DegeneratePolygon_IsRefusedBeforeCompileWithItsName()
    {
        var e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.Zero, Vector3.UnitX, 2 * Vector3.UnitX], name: "polygons[4]"));
        Assert.Contains("polygons[4]", e.Message);
        Assert.Contains("degenerate", e.Message);
        e = Assert.Throws<ArgumentException>(() => new Polygon([Vector3.Zero, new Vector3(float.NaN, 0, 0), Vector3.UnitY], name: "polygons[2]"));
        Assert.StartsWith("polygons[2].vertices[1]", e.Message);
    }

    // ---------- helpers ----------

    private static bool Inside(Vector3 p, Vector3 min, Vector3 max) =>
        p.X > min.X && p.Y > min.Y && p.Z > min.Z && p.X < max.X && p.Y < max.Y && p.Z < max.Z;

    private static bool NearBoxSurface(Vector3 p, Vector3 min, Vector3 max)
    {
        const float m = 1e-3f;
        bool nearX = MathF.Abs(p.X - min.X) < m || MathF.Abs(p.X - max.X) < m;
        bool nearY = MathF.Abs(p.Y - min.Y) < m || MathF.Abs(p.Y - max.Y) < m;
        bool nearZ = MathF.Abs(p.Z - min.Z) < m || MathF.Abs(p.Z - max.Z) < m;
        return nearX || nearY || nearZ;
    }

    /// <summary>The union of [0,2]x[0,1]x[0,1] and [0,1]x[1,2]x[0,1], as a closed surface (no inner faces).</summary>
    private static List<Polygon> LPrism() =>
    [
        Rect(new(0, 0, 0), new(2, 1, 0), -Vector3.UnitZ),
        Rect(new(0, 1, 0), new(1, 2, 0), -Vector3.UnitZ),
        Rect(new(0, 0, 1), new(2, 1, 1), Vector3.UnitZ),
        Rect(new(0, 1, 1), new(1, 2, 1), Vector3.UnitZ),
        Rect(new(0, 0, 0), new(0, 2, 1), -Vector3.UnitX),
        Rect(new(0, 0, 0), new(2, 0, 1), -Vector3.UnitY),
        Rect(new(2, 0, 0), new(2, 1, 1), Vector3.UnitX),
        Rect(new(1, 1, 0), new(2, 1, 1), Vector3.UnitY),
        Rect(new(1, 1, 0), new(1, 2, 1), Vector3.UnitX),
        Rect(new(0, 2, 0), new(1, 2, 1), Vector3.UnitY),
    ];

    private static bool InsideL(Vector3 p) =>
        Inside(p, new(0, 0, 0), new(2, 1, 1)) || Inside(p, new(0, 1, 0), new(1, 2, 1)) ||
        (p.Y == 1 && p.X > 0 && p.X < 1 && p.Z > 0 && p.Z < 1);

    private static void AssertClassifies(BspTree tree, Func<Vector3, bool> inside, Vector3 min, Vector3 max, int seed)
    {
        var r = new Random(seed);
        int ins = 0, outs = 0;
        for (int k = 0; k < 3000; k++)
        {
            var p = RandomIn(r, min, max);
            // Skip points within a hair of a surface, where either answer is right.
            bool a = inside(p);
            bool stable = true;
            foreach (var d in new[] { Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitX, -Vector3.UnitY, -Vector3.UnitZ })
                if (inside(p + d * 1e-3f) != a) stable = false;
            if (!stable) continue;
            Assert.True(a == InSolid(tree, p), $"point {p}: expected inside={a}");
            if (a) ins++; else outs++;
        }
        Assert.True(ins > 50 && outs > 50, $"sampling too thin: {ins} in, {outs} out");
    }

    private static IEnumerable<BspTree> SampleTrees()
    {
        yield return BspShapes.Box(BoxMin, BoxMax);
        yield return BspShapes.Floor(Vector3.Zero, new Vector2(3, 2));
        yield return BspShapes.Slab(new Vector3(1, 2, 3), new Vector3(2, 1, 0.5f), Quaternion.CreateFromYawPitchRoll(0.3f, 0.2f, 0.1f));
        yield return BspCompiler.Compile(LPrism());
        yield return BspCompiler.Compile(BoxFaces(new(0, 0, 0), new(1, 1, 1)).Concat(BoxFaces(new(3, 0, 0), new(4, 1, 1))).ToList());
        yield return BspCompiler.Compile([Rect(new(-2, -2, 0), new(2, 2, 0), Vector3.UnitZ), Rect(new(0, -1, -1), new(0, 1, 1), Vector3.UnitX)]);
    }
}
