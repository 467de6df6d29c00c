using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Geometry;

public class PolygonQueryTests
{
    private const float Eps = PhysicsConstants.Epsilon;

    // The square [-1, 1]² in the plane z = 0, facing +Z.
    private static Polygon Floor(PolygonSides sides = PolygonSides.Single) =>
        new(new Vector3[] { new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0) }, sides);

    // A unit-ish square through the origin whose normal is (sin t, 0, cos t) with cos t = normalZ.
    private static Polygon Slope(float normalZ)
    {
        float s = MathF.Sqrt(1f - normalZ * normalZ);
        var u = new Vector3(normalZ, 0, -s);
        var v = Vector3.UnitY;
        return new Polygon(new[] { -u - v, u - v, u + v, -u + v });
    }

    private static bool Hits(Polygon p, Vector3 center, float radius) => PolygonQuery.HitsSphere(p, new Sphere(center, radius));

    [Fact]
    public void HitsSphere_Face_HitWhenPlaneWithinRadius()
    {
        Assert.True(Hits(Floor(), new Vector3(0.2f, -0.3f, 0.4f), 0.5f));
        Assert.False(Hits(Floor(), new Vector3(0.2f, -0.3f, 0.6f), 0.5f));
    }

    [Fact]
    public void HitsSphere_ExactTouchAtRadius_IsAMiss_BecauseRetailShrinksByEpsilon()
        => Assert.False(Hits(Floor(), new Vector3(0, 0, 0.5f), 0.5f));

    [Theory]
    [InlineData(-1e-5f, true)]
    [InlineData(+1e-5f, false)]
    public void HitsSphere_FaceTolerance_IsRadiusMinusEpsilon(float delta, bool expected)
        => Assert.Equal(expected, Hits(Floor(), new Vector3(0, 0, 0.5f - Eps + delta), 0.5f));

    [Theory]
    [InlineData(1.3f, 0f, 0f, true)]     // 0.3 from the edge x = 1
    [InlineData(1.6f, 0f, 0f, false)]    // 0.6 from it
    [InlineData(1.3f, 0f, 0.3f, true)]   // sqrt(0.18) = 0.424 from the edge
    [InlineData(1.4f, 0f, 0.3f, false)]  // exactly 0.5: beyond radius − EPSILON
    public void HitsSphere_Edge(float x, float y, float z, bool expected)
        => Assert.Equal(expected, Hits(Floor(), new Vector3(x, y, z), 0.5f));

    [Theory]
    [InlineData(1.3f, 1.3f, 0f, true)]     // 0.424 from the corner
    [InlineData(1.36f, 1.36f, 0f, false)]  // 0.509
    [InlineData(1.3f, 1.3f, 0.2f, true)]   // sqrt(0.22) = 0.469
    [InlineData(1.3f, 1.3f, 0.3f, false)]  // sqrt(0.27) = 0.520
    public void HitsSphere_Corner(float x, float y, float z, bool expected)
        => Assert.Equal(expected, Hits(Floor(), new Vector3(x, y, z), 0.5f));

    [Theory]
    [InlineData(0.4999f - Eps, true)]  // 0.5 − EPS − 1e-4 from the edge x = 1 (in plane)
    [InlineData(0.5001f - Eps, false)]
    public void HitsSphere_GrazingEdge_TolerancePerSide(float gap, bool expected)
        => Assert.Equal(expected, Hits(Floor(), new Vector3(1f + gap, 0, 0), 0.5f));

    [Theory]
    [InlineData(PolygonSides.Single)]
    [InlineData(PolygonSides.Double)]
    public void HitsSphere_IgnoresSidedness_HitsFromBehindToo(PolygonSides sides)
    {
        Assert.True(Hits(Floor(sides), new Vector3(0, 0, -0.4f), 0.5f));
        Assert.False(Hits(Floor(sides), new Vector3(0, 0, -0.6f), 0.5f));
    }

    [Fact]
    public void PrecisePolygonHitsSphere_SetsContactPointToProjectedCentre()
    {
        var contact = Vector3.Zero;
        Assert.True(PolygonQuery.PolygonHitsSpherePrecise(Floor(), new Sphere(new Vector3(0.5f, 0.25f, 0.3f), 0.5f), ref contact));
        Assert.Equal(0.5f, contact.X, 5);
        Assert.Equal(0.25f, contact.Y, 5);
        Assert.Equal(0f, contact.Z, 5);
    }

    [Theory]
    [InlineData(0f, 0f, 0.4f, true)]
    [InlineData(1.3f, 0f, 0f, true)]
    [InlineData(1.6f, 0f, 0f, false)]
    [InlineData(0f, 0f, 0.6f, false)]
    public void SinglePassPolygonHitsSphere_AgreesOnSimpleCases(float x, float y, float z, bool expected)
    {
        var contact = Vector3.Zero;
        Assert.Equal(expected, PolygonQuery.PolygonHitsSphere(Floor(), new Sphere(new Vector3(x, y, z), 0.5f), ref contact));
    }

    [Theory]
    [InlineData(-1e-5f, true)]
    [InlineData(+1e-5f, false)]
    public void SinglePassPolygonHitsSphere_SameEpsilonTolerance(float delta, bool expected)
    {
        var contact = Vector3.Zero;
        Assert.Equal(expected, PolygonQuery.PolygonHitsSphere(Floor(), new Sphere(new Vector3(0.3f, 0, 0.5f - Eps + delta), 0.5f), ref contact));
    }

    [Fact]
    public void PosHitsSphere_CountsOnlyMovesIntoTheFront_ButRecordsTheGrazedPolygon()
    {
        var floor = Floor();
        var contact = Vector3.Zero;
        Polygon? struck = null;
        var sphere = new Sphere(new Vector3(0, 0, 0.3f), 0.5f);

        Assert.True(PolygonQuery.PosHitsSphere(floor, sphere, new Vector3(0, 0, -1), ref contact, ref struck));
        Assert.Same(floor, struck);

        struck = null;
        Assert.False(PolygonQuery.PosHitsSphere(floor, sphere, new Vector3(0, 0, 1), ref contact, ref struck));
        Assert.Same(floor, struck); // retail quirk: set before the direction gate

        struck = null;
        Assert.False(PolygonQuery.PosHitsSphere(floor, sphere, new Vector3(1, 0, 0), ref contact, ref struck)); // parallel: movement·N = 0
        Assert.Same(floor, struck);

        struck = null;
        Assert.False(PolygonQuery.PosHitsSphere(floor, new Sphere(new Vector3(0, 0, 2), 0.5f), new Vector3(0, 0, -1), ref contact, ref struck));
        Assert.Null(struck);
    }

    [Theory]
    [InlineData(+1e-4f, true)]
    [InlineData(-1e-4f, false)]
    public void WalkableHitsSphere_SlopeJustAboveOrBelowFloorZ(float delta, bool expected)
    {
        var slope = Slope(PhysicsConstants.FloorZ + delta);
        Assert.Equal(PhysicsConstants.FloorZ + delta, slope.Plane.Normal.Z, 5);
        var sphere = new Sphere(slope.Plane.Normal * 0.3f, 0.5f);
        Assert.True(PolygonQuery.HitsSphere(slope, sphere));
        Assert.Equal(expected, PolygonQuery.WalkableHitsSphere(slope, sphere, Vector3.UnitZ, PhysicsConstants.FloorZ));
    }

    [Fact]
    public void WalkableHitsSphere_NeedsAHit()
        => Assert.False(PolygonQuery.WalkableHitsSphere(Floor(), new Sphere(new Vector3(0, 0, 0.7f), 0.5f), Vector3.UnitZ, PhysicsConstants.FloorZ));

    [Theory]
    [InlineData(0f, 0f, true)]
    [InlineData(1f, 0f, true)]          // on an edge
    [InlineData(1f, 1f, true)]          // on a vertex
    [InlineData(0.9999f, 0.5f, true)]
    [InlineData(1.0001f, 0.5f, false)]
    [InlineData(0.5f, -1.0001f, false)]
    public void PointInPolygon_OnAndNearEdges(float x, float y, bool expected)
        => Assert.Equal(expected, PolygonQuery.PointInPolygon(Floor(), new Vector3(x, y, 0)));

    [Fact]
    public void PointInPoly2D_PositiveWantsCounterClockwise_OtherSidesClockwise()
    {
        var ccw = Floor();
        var cw = new Polygon(new Vector3[] { new(-1, 1, 0), new(1, 1, 0), new(1, -1, 0), new(-1, -1, 0) });
        var inside = new Vector3(0.3f, -0.2f, 5f); // Z is ignored
        Assert.True(PolygonQuery.PointInPoly2D(ccw, inside, Sidedness.Positive));
        Assert.False(PolygonQuery.PointInPoly2D(ccw, inside, Sidedness.Negative));
        Assert.True(PolygonQuery.PointInPoly2D(cw, inside, Sidedness.Negative));
        Assert.False(PolygonQuery.PointInPoly2D(cw, inside, Sidedness.Positive));
        Assert.True(PolygonQuery.PointInPoly2D(ccw, new Vector3(1f, 0.5f, 0), Sidedness.Positive)); // on an edge
        Assert.False(PolygonQuery.PointInPoly2D(ccw, new Vector3(1.001f, 0.5f, 0), Sidedness.Positive));
    }

    [Fact]
    public void Triangle2D_AnswersAsPointInPoly2DOnThePositiveSide_OnAndAroundItsEdges()
    {
        // The terrain's prepared triangles stand in for retail's point_in_poly2D: every answer must agree,
        // on the edges and vertices too, for both windings and a sloped, off-grid triangle.
        var triangles = new[]
        {
            new Polygon(new Vector3[] { new(0, 0, 0), new(24, 0, 1), new(24, 24, 2) }),
            new Polygon(new Vector3[] { new(0, 0, 0), new(24, 24, 2), new(0, 24, 1) }),
            new Polygon(new Vector3[] { new(1.1f, 2.3f, 0), new(17.9f, 0.7f, 3), new(9.5f, 21.1f, -2) }),
            new Polygon(new Vector3[] { new(0, 0, 0), new(0, 24, 0), new(24, 0, 0) }), // clockwise: never holds a point strictly inside
        };
        int checks = 0;
        foreach (var polygon in triangles)
        {
            var prepared = new Triangle2D(polygon.Vertices);
            for (float x = -1f; x <= 25f; x += 0.375f)
                for (float y = -1f; y <= 25f; y += 0.375f)
                {
                    var point = new Vector3(x, y, 7f);
                    Assert.Equal(PolygonQuery.PointInPoly2D(polygon, point, Sidedness.Positive), prepared.Contains(point));
                    checks++;
                }
        }
        Assert.True(checks > 15000, $"{checks} checks");
    }

    [Theory]
    [InlineData(1.5f, 0f, -1f, 0f)]    // crossed x = 1: normal points back in (−X)
    [InlineData(0f, 1.5f, 0f, -1f)]    // crossed y = 1
    [InlineData(-1.5f, 0f, 1f, 0f)]    // crossed x = −1
    [InlineData(1.5f, 1.5f, -1f, 0f)]  // past a corner: the first crossed edge in vertex order is x = 1, not y = 1
    [InlineData(-1.5f, -1.5f, 1f, 0f)] // the closing edge (last vertex → vertex 0, x = −1) is tested first
    public void FindCrossedEdge_PicksTheFirstCrossedEdge(float x, float y, float nx, float ny)
    {
        Assert.True(PolygonQuery.FindCrossedEdge(Floor(), new Sphere(new Vector3(x, y, 0.3f), 0.5f), Vector3.UnitZ, out var normal));
        Assert.Equal(nx, normal.X, 5);
        Assert.Equal(ny, normal.Y, 5);
        Assert.Equal(0f, normal.Z, 5);
    }

    [Fact]
    public void FindCrossedEdge_InsideIsFalse_AndProjectionFollowsUp()
    {
        Assert.False(PolygonQuery.FindCrossedEdge(Floor(), new Sphere(new Vector3(0.9f, 0, 3f), 0.5f), Vector3.UnitZ, out var none));
        Assert.Equal(Vector3.Zero, none);
        // Along a slanted up the centre (0.9, 0, 5) lands at (−4.1, 0, 0): past x = −1.
        var up = Vector3.Normalize(new Vector3(1, 0, 1));
        Assert.True(PolygonQuery.FindCrossedEdge(Floor(), new Sphere(new Vector3(0.9f, 0, 5f), 0.5f), up, out var normal));
        Assert.Equal(1f, normal.X, 5);
        // Parallel up: no answer.
        Assert.False(PolygonQuery.FindCrossedEdge(Floor(), new Sphere(new Vector3(5, 0, 0), 0.5f), Vector3.UnitX, out _));
    }

    [Fact]
    public void CheckWalkable_FullAndSmallDisc()
    {
        var floor = Floor();
        var overEdge = new Sphere(new Vector3(1.3f, 0, 0.4f), 0.5f); // 0.3 past the edge
        Assert.True(PolygonQuery.CheckWalkable(floor, overEdge, Vector3.UnitZ, small: false));
        Assert.False(PolygonQuery.CheckWalkable(floor, overEdge, Vector3.UnitZ, small: true)); // half radius: 0.25 < 0.3
        Assert.False(PolygonQuery.CheckSmallWalkable(floor, overEdge, Vector3.UnitZ));
        Assert.True(PolygonQuery.CheckSmallWalkable(floor, new Sphere(new Vector3(1.2f, 0, 0.4f), 0.5f), Vector3.UnitZ));
        Assert.True(PolygonQuery.CheckWalkable(floor, new Sphere(new Vector3(0, 0, 9f), 0.5f), Vector3.UnitZ, small: true));
        Assert.False(PolygonQuery.CheckWalkable(floor, new Sphere(new Vector3(0, 0, 0.4f), 0.5f), Vector3.UnitX, small: false));
        // Retail tests |N·up|: a downward up still works.
        Assert.True(PolygonQuery.CheckWalkable(floor, new Sphere(new Vector3(0, 0, 0.4f), 0.5f), -Vector3.UnitZ, small: false));
    }

    [Fact]
    public void AdjustSphereToPlane_BacksOffToTangent_AndLowersWalkInterp()
    {
        var sphere = new Sphere(new Vector3(0, 0, 0.2f), 0.5f);
        float interp = 1f;
        Assert.True(PolygonQuery.AdjustSphereToPlane(Floor(), ref sphere, new Vector3(0, 0, -1), ref interp));
        Assert.Equal(0.5f, sphere.Center.Z, 5);
        Assert.Equal(0.7f, interp, 5);

        // A second adjustment that would not lower walk_interp is refused.
        var again = new Sphere(new Vector3(0, 0, 0.5f), 0.5f);
        float interp2 = 0.7f;
        Assert.False(PolygonQuery.AdjustSphereToPlane(Floor(), ref again, new Vector3(0, 0, -1), ref interp2));
        Assert.Equal(0.7f, interp2);

        var parallel = new Sphere(new Vector3(0, 0, 0.2f), 0.5f);
        float interp3 = 1f;
        Assert.False(PolygonQuery.AdjustSphereToPlane(Floor(), ref parallel, new Vector3(1, 0, 0), ref interp3));
        Assert.Equal(0.2f, parallel.Center.Z);
    }

    [Fact]
    public void AdjustSphereToPoly_TouchTimes()
    {
        var s = new Sphere(Vector3.Zero, 0.5f);
        Assert.Equal(0.5f, PolygonQuery.AdjustSphereToPoly(Floor(), s, new Vector3(0, 0, 2), new Vector3(0, 0, -3)), 5);
        Assert.Equal(1f, PolygonQuery.AdjustSphereToPoly(Floor(), s, new Vector3(0, 0, 0.3f), new Vector3(0, 0, -3)));
        Assert.Equal(0f, PolygonQuery.AdjustSphereToPoly(Floor(), s, new Vector3(0, 0, 2), new Vector3(3, 0, 0)));
        // A move no longer than the radius aims at the far side (ACE's recovered predicate): (−0.5 − 2) / −0.4.
        Assert.Equal(6.25f, PolygonQuery.AdjustSphereToPoly(Floor(), s, new Vector3(0, 0, 2), new Vector3(0, 0, -0.4f)), 4);
    }

    [Theory]
    [InlineData(-0.2f, true, true, 0.5f)]   // in solid and behind: the two flips cancel (retail; ACE would give −0.5)
    [InlineData(-0.2f, false, true, -0.5f)]  // behind only
    [InlineData(0.2f, true, true, -0.5f)]   // in solid only
    [InlineData(0.2f, false, true, 0.5f)]
    [InlineData(-0.2f, true, false, 0.5f)]  // no solid check: always the front
    public void AdjustToPlacementPoly_TargetSide(float z, bool centerSolid, bool solidCheck, float expectedZ)
    {
        var struck = new Sphere(new Vector3(0.1f, 0.1f, z), 0.5f);
        var other = new Sphere(new Vector3(0, 0, 3), 0.5f);
        PolygonQuery.AdjustToPlacementPoly(Floor(), ref struck, ref other, 0.5f, centerSolid, solidCheck);
        Assert.Equal(expectedZ, struck.Center.Z, 5);
        Assert.Equal(0.1f, struck.Center.X, 6);
        Assert.Equal(3f + (expectedZ - z), other.Center.Z, 5);
    }

    [Fact]
    public void PolygonHitsRay_SingleSidedOnlyFromFront_DoubleFromBoth()
    {
        Assert.True(PolygonQuery.PolygonHitsRay(Floor(), new Vector3(0.5f, 0.5f, 2), -Vector3.UnitZ, out float t));
        Assert.Equal(2f, t, 5);
        Assert.False(PolygonQuery.PolygonHitsRay(Floor(), new Vector3(0.5f, 0.5f, -2), Vector3.UnitZ, out _));
        Assert.True(PolygonQuery.PolygonHitsRay(Floor(PolygonSides.Double), new Vector3(0.5f, 0.5f, -2), Vector3.UnitZ, out float t2));
        Assert.Equal(2f, t2, 5);
        Assert.False(PolygonQuery.PolygonHitsRay(Floor(), new Vector3(1.5f, 0.5f, 2), -Vector3.UnitZ, out _)); // misses the square
        Assert.False(PolygonQuery.PolygonHitsRay(Floor(), new Vector3(0.5f, 0.5f, 2), Vector3.UnitZ, out _)); // plane behind the ray (single-sided gate)
        Assert.False(PolygonQuery.PolygonHitsRay(Floor(PolygonSides.Double), new Vector3(0.5f, 0.5f, 2), Vector3.UnitZ, out _)); // time < 0
    }
}
