using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Tests.Bsp;

public class BspNodeQueryTests
{
    private const float Eps = PhysicsConstants.Epsilon;

    private static bool Solid(Vector3 center, float radius, bool centerCheck = true)
        => BspQuery.SphereIntersectsSolid(BoxFixtures.SolidBox(out _), new Sphere(center, radius), centerCheck);

    [Theory]
    [InlineData(5f, 0f, 0f, false)]       // far outside
    [InlineData(1.4f, 0f, 0f, true)]      // face, 0.4 away
    [InlineData(1.5f, 0f, 0f, false)]     // exactly touching: a miss (radius − EPSILON)
    [InlineData(1.3f, 1.3f, 0f, true)]    // edge, 0.424 away
    [InlineData(1.36f, 1.36f, 0f, false)] // edge, 0.509 away
    [InlineData(1.25f, 1.25f, 1.25f, true)] // corner, 0.433 away
    [InlineData(1.3f, 1.3f, 1.3f, false)]   // corner, 0.520 away
    [InlineData(-1.2f, 0f, 0.5f, true)]   // the −X face, reached through the chain
    [InlineData(0f, 0f, -1.45f, true)]    // the −Z face, last in the chain
    public void SphereIntersectsSolid_FaceEdgeCorner(float x, float y, float z, bool expected)
        => Assert.Equal(expected, Solid(new Vector3(x, y, z), 0.5f));

    [Theory]
    [InlineData(-1e-5f, true)]
    [InlineData(+1e-5f, false)]
    public void SphereIntersectsSolid_EpsilonTolerance(float delta, bool expected)
        => Assert.Equal(expected, Solid(new Vector3(1f + 0.5f - Eps + delta, 0.2f, -0.3f), 0.5f));

    [Fact]
    public void SphereIntersectsSolid_CentreInSolidLeaf_OnlyWithCentreCheck()
    {
        Assert.True(Solid(Vector3.Zero, 0.1f, centerCheck: true));
        Assert.False(Solid(Vector3.Zero, 0.1f, centerCheck: false));
        // Straddling a face with the centre outside: the solid flag is not passed to the outer side, but the face is hit.
        Assert.True(Solid(new Vector3(1.05f, 0, 0), 0.1f, centerCheck: false));
    }

    [Theory]
    [InlineData(0f, 0f, 0f, true)]
    [InlineData(0.999f, -0.999f, 0.5f, true)]
    [InlineData(1.001f, 0f, 0f, false)]
    [InlineData(1f, 0f, 0f, false)] // exactly on the split: retail goes front (outside); ACE would go back (solid)
    [InlineData(0f, 0f, -1.5f, false)]
    public void PointIntersectsSolid(float x, float y, float z, bool expected)
        => Assert.Equal(expected, BspQuery.PointIntersectsSolid(BoxFixtures.SolidBox(out _), new Vector3(x, y, z)));

    [Fact]
    public void SphereIntersectsPoly_FrontHitWhenMovingIn_GrazeWhenMovingOut()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var sphere = new Sphere(new Vector3(1.3f, 0, 0), 0.5f);
        Polygon? hit = null;
        var contact = Vector3.Zero;
        Assert.True(BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere, new Vector3(-0.5f, 0, 0), ref hit, ref contact));
        Assert.Same(faces[0], hit);
        Assert.Equal(new Vector3(1, 0, 0), contact);

        hit = null;
        Assert.False(BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere, new Vector3(0.5f, 0, 0), ref hit, ref contact));
        Assert.Same(faces[0], hit); // grazed from behind: retail reports it through the out parameter

        hit = null;
        Assert.False(BspNodeQuery.SphereIntersectsPoly(tree, 0, new Sphere(new Vector3(3, 0, 0), 0.5f), new Vector3(-0.5f, 0, 0), ref hit, ref contact));
        Assert.Null(hit);
    }

    [Fact]
    public void SphereIntersectsSolidPoly_ReportsPolygonOrCentreSolid()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        bool centerSolid = false;
        Polygon? hit = null;
        Assert.True(BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, new Sphere(new Vector3(0, 1.2f, 0), 0.5f), 0.5f, ref centerSolid, ref hit, true));
        Assert.Same(faces[2], hit);
        Assert.False(centerSolid);

        centerSolid = false;
        hit = null;
        Assert.True(BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, new Sphere(Vector3.Zero, 0.2f), 0.2f, ref centerSolid, ref hit, true));
        Assert.Null(hit);
        Assert.True(centerSolid);

        centerSolid = false;
        Assert.False(BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, new Sphere(new Vector3(0, 3, 0), 0.5f), 0.5f, ref centerSolid, ref hit, true));
    }

    [Fact]
    public void HitsWalkable_TopFaceYes_SideFaceNo()
    {
        var tree = BoxFixtures.SolidBox(out _);
        Assert.True(BspNodeQuery.HitsWalkable(tree, 0, new Sphere(new Vector3(0.3f, 0.3f, 1.4f), 0.5f), Vector3.UnitZ, PhysicsConstants.FloorZ));
        Assert.False(BspNodeQuery.HitsWalkable(tree, 0, new Sphere(new Vector3(1.4f, 0, 0), 0.5f), Vector3.UnitZ, PhysicsConstants.FloorZ));
        // Over the edge by 0.3: the sphere hits the top face but the half-radius disc (0.25) is off it.
        Assert.False(BspNodeQuery.HitsWalkable(tree, 0, new Sphere(new Vector3(1.3f, 0, 1.3f), 0.5f), Vector3.UnitZ, PhysicsConstants.FloorZ));
    }

    [Fact]
    public void FindWalkable_LiftsOntoTheTopFace()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var sphere = new Sphere(new Vector3(0.2f, 0, 1.3f), 0.5f);
        Polygon? polygon = null;
        float interp = 1f;
        bool changed = false;
        BspNodeQuery.FindWalkable(tree, 0, ref sphere, ref polygon, new Vector3(0, 0, -0.3f), Vector3.UnitZ, PhysicsConstants.FloorZ, ref interp, ref changed);
        Assert.True(changed);
        Assert.Same(faces[4], polygon);
        Assert.Equal(1.5f, sphere.Center.Z, 5);
        Assert.Equal(1f / 3f, interp, 5);
    }

    [Fact]
    public void BoundingSphere_EarlyOut_SkipsTheTree()
    {
        // Same box, but the root's bounding sphere is given far away: retail trusts it and finds nothing.
        var faces = BoxFixtures.Faces();
        var nodes = new List<BspNodeData>();
        for (int i = 0; i < 6; i++)
            nodes.Add(new BspNodeData
            {
                SplitPlane = new Plane(BoxFixtures.Normals[i], -1f), Back = i + 1,
                Bounds = i == 0 ? new Sphere(new Vector3(100, 0, 0), 1f) : null,
            });
        nodes.Add(new BspNodeData { IsLeaf = true, Solid = true, Polygons = new[] { 0, 1, 2, 3, 4, 5 } });
        var tree = BspTree.Create(faces, nodes);
        Assert.False(BspQuery.SphereIntersectsSolid(tree, new Sphere(new Vector3(1.4f, 0, 0), 0.5f)));
    }
    [Fact]
    public void SphereIntersectsPoly_StraddledSplit_SearchesTheFrontSideToo()
    {
        // Root split x = 0 (normal +X, D 0); its front is a leaf holding one wall at x = 0.3 facing −X
        // (plane −x + 0.3 = 0), its back is empty. Sphere r 0.5 at x = −0.1 moving +X:
        //   split distance −0.1, reach 0.5 − 0.0002 = 0.4998 → −0.4998 < −0.1 < 0.4998: it straddles, so
        //   both sides are searched;
        //   wall distance −(−0.1) + 0.3 = 0.4 ≤ 0.4998 → hit; movement·N = 0.5·(−1) < 0 → from the front;
        //   contact = centre − N·0.4 = (−0.1 + 0.4, 0, 0) = (0.3, 0, 0).
        // Searching only the back (empty) side would miss it.
        var wall = BspTestKit.Rect(new Vector3(0.3f, -1, -1), new Vector3(0.3f, 1, 1), -Vector3.UnitX);
        var tree = BspTree.Create(new[] { wall }, new[]
        {
            new BspNodeData { SplitPlane = new Plane(Vector3.UnitX, 0f), Front = 1, Back = -1 },
            new BspNodeData { IsLeaf = true, Solid = false, Polygons = new[] { 0 } },
        });
        Polygon? hit = null;
        var contact = Vector3.Zero;
        Assert.True(BspNodeQuery.SphereIntersectsPoly(tree, 0, new Sphere(new Vector3(-0.1f, 0, 0), 0.5f), new Vector3(0.5f, 0, 0), ref hit, ref contact));
        Assert.Same(wall, hit);
        Assert.Equal(0.3f, contact.X, 5);
    }
}
