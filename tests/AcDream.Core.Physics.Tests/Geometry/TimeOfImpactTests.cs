using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>Analytic times of impact of the reference sweep (hand-solved distance equations).</summary>
public class TimeOfImpactTests
{
    private const float Tol = 1e-5f;

    /// <summary>A 2 m square in the z = 0 plane, facing +Z.</summary>
    private static readonly Polygon Square = new([new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0)]);

    [Fact]
    public void Plane_HeadOn()
    {
        Assert.True(TimeOfImpact.Plane(new Vector3(0, 0, 2), new Vector3(0, 0, -4), 0.5f, new Plane(Vector3.UnitZ, 0), out float t));
        Assert.Equal(0.375f, t, Tol);
        Assert.False(TimeOfImpact.Plane(new Vector3(0, 0, 2), new Vector3(0, 0, 4), 0.5f, new Plane(Vector3.UnitZ, 0), out _));
        Assert.False(TimeOfImpact.Plane(new Vector3(0, 0, 2), new Vector3(0, 0, -1), 0.5f, new Plane(Vector3.UnitZ, 0), out _));
    }

    [Fact]
    public void Polygon_Face()
    {
        Assert.True(TimeOfImpact.Polygon(new Vector3(0.3f, 0.2f, 2), new Vector3(0, 0, -4), 0.5f, Square, out var hit));
        Assert.Equal(ImpactFeature.Face, hit.Feature);
        Assert.Equal(0.375f, hit.Time, Tol);
        Assert.Equal(Vector3.UnitZ, hit.Normal);
    }

    [Fact]
    public void Polygon_SingleSided_IgnoredFromBehind_DoubleSidedHit()
    {
        Assert.False(TimeOfImpact.Polygon(new Vector3(0, 0, -2), new Vector3(0, 0, 4), 0.5f, Square, out _));
        var twoSided = new Polygon(Square.Vertices, PolygonSides.Double);
        Assert.True(TimeOfImpact.Polygon(new Vector3(0, 0, -2), new Vector3(0, 0, 4), 0.5f, twoSided, out var hit));
        Assert.Equal(0.375f, hit.Time, Tol);
        Assert.Equal(-Vector3.UnitZ, hit.Normal);
    }

    [Fact]
    public void Polygon_Edge()
    {
        // Centre 0.3 above the plane, moving at the x = 1 edge: contact when (x − 1)² + 0.3² = 0.5², x = 1.4.
        Assert.True(TimeOfImpact.Polygon(new Vector3(3, 0, 0.3f), new Vector3(-4, 0, 0), 0.5f, Square, out var hit));
        Assert.Equal(ImpactFeature.Edge, hit.Feature);
        Assert.Equal((3 - 1.4f) / 4, hit.Time, Tol);
        Assert.True(Vector3.Distance(new Vector3(0.8f, 0, 0.6f), hit.Normal) < 1e-4f, hit.ToString());
    }

    [Fact]
    public void Polygon_Vertex()
    {
        // Passing 0.2 beside the (1, 1, 0) corner, 0.3 above it: (x − 1)² = 0.25 − 0.04 − 0.09.
        Assert.True(TimeOfImpact.Polygon(new Vector3(3, 1.2f, 0.3f), new Vector3(-4, 0, 0), 0.5f, Square, out var hit));
        Assert.Equal(ImpactFeature.Vertex, hit.Feature);
        float x = 1 + MathF.Sqrt(0.12f);
        Assert.Equal((3 - x) / 4, hit.Time, Tol);
        Assert.True(Vector3.Distance(Vector3.Normalize(new Vector3(x - 1, 0.2f, 0.3f)), hit.Normal) < 1e-4f, hit.ToString());
    }

    [Fact]
    public void Polygon_Miss_WhenPassingBeyondTheRadius()
    {
        Assert.False(TimeOfImpact.Polygon(new Vector3(3, 1.6f, 0.3f), new Vector3(-4, 0, 0), 0.5f, Square, out _));
        Assert.False(TimeOfImpact.Polygon(new Vector3(0, 0, 3), new Vector3(0, 0, -2), 0.5f, Square, out _));
    }

    [Fact]
    public void Polygon_Resting_StopsOnlyWhenMovingIn()
    {
        Assert.True(TimeOfImpact.Polygon(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0, -0.1f), 0.5f, Square, out var hit));
        Assert.Equal(ImpactFeature.Resting, hit.Feature);
        Assert.Equal(0f, hit.Time);
        Assert.False(TimeOfImpact.Polygon(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0, 0), 0.5f, Square, out _));
        Assert.False(TimeOfImpact.Polygon(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0, 0.1f), 0.5f, Square, out _));
    }

    /// <summary>
    /// A start touching a corner that lies off the plane through vertex 0 (a polygon is accepted up to 1 mm off
    /// flat) is resting on the polygon even though its distance from that plane is more than the radius: the
    /// resting test is skipped only beyond a margin for the polygon's flatness (RestingMargin). A saddle quad,
    /// two opposite corners raised 0.9 mm; the sphere's centre 0.2 mm nearer than its radius to the corner that
    /// stands highest above vertex 0's plane, a little outside the polygon, moving down into it.
    /// </summary>
    [Fact]
    public void Polygon_Resting_OnACornerAboveVertexZerosPlane()
    {
        const float h = 0.0009f, r = 0.5f;
        var saddle = new Polygon([new(-1, -1, 0), new(1, -1, h), new(1, 1, 0), new(-1, 1, h)]);
        var n = saddle.Plane.Normal;
        var v = saddle.Vertices;
        int k = 0;
        for (int i = 1; i < v.Length; i++)
            if (Vector3.Dot(n, v[i] - v[0]) > Vector3.Dot(n, v[k] - v[0]))
                k = i;
        var outward = Vector3.Normalize(new Vector3(v[k].X, v[k].Y, 0));
        var c = v[k] + outward * 1e-4f + n * (r - 2e-4f);
        // The case in question: farther than radius + slop from vertex 0's plane, nearer than the radius to the corner.
        Assert.True(Vector3.Dot(n, c - v[0]) > r + TimeOfImpact.ContactSlop + 1e-4f, $"height above vertex 0's plane {Vector3.Dot(n, c - v[0])}");
        Assert.True(Vector3.Distance(c, v[k]) < r - 1e-4f);
        Assert.True(TimeOfImpact.Polygon(c, new Vector3(0, 0, -0.1f), r, saddle, out var hit));
        Assert.Equal(ImpactFeature.Resting, hit.Feature);
        Assert.Equal(0f, hit.Time);
    }

    private static readonly CylSphere Cyl = new(new Vector3(0, 0, 0), 0.5f, 2f);

    [Fact]
    public void Cylinder_Side()
    {
        Assert.True(TimeOfImpact.Cylinder(new Vector3(3, 0, 1), new Vector3(-4, 0, 0), 0.5f, Cyl, out var hit));
        Assert.Equal(ImpactFeature.CylinderSide, hit.Feature);
        Assert.Equal(0.5f, hit.Time, Tol);
        Assert.Equal(Vector3.UnitX, hit.Normal);
    }

    [Fact]
    public void Cylinder_Cap()
    {
        Assert.True(TimeOfImpact.Cylinder(new Vector3(0.2f, 0, 4), new Vector3(0, 0, -4), 0.5f, Cyl, out var hit));
        Assert.Equal(ImpactFeature.CylinderCap, hit.Feature);
        Assert.Equal(0.375f, hit.Time, Tol);
        Assert.Equal(Vector3.UnitZ, hit.Normal);
    }

    [Fact]
    public void Cylinder_Rim()
    {
        // Falling 0.3 outside the rim: (0.8 − 0.5)² + (z − 2)² = 0.5², z = 2.4.
        Assert.True(TimeOfImpact.Cylinder(new Vector3(0.8f, 0, 4), new Vector3(0, 0, -4), 0.5f, Cyl, out var hit));
        Assert.Equal(ImpactFeature.CylinderRim, hit.Feature);
        Assert.Equal(0.4f, hit.Time, 1e-4f);
        Assert.True(Vector3.Distance(new Vector3(0.6f, 0, 0.8f), hit.Normal) < 1e-3f, hit.ToString());
    }

    [Fact]
    public void Cylinder_Miss()
    {
        Assert.False(TimeOfImpact.Cylinder(new Vector3(3, 1.1f, 1), new Vector3(-6, 0, 0), 0.5f, Cyl, out _));
        Assert.False(TimeOfImpact.Cylinder(new Vector3(0, 0, 3.1f), new Vector3(4, 0, 0), 0.5f, Cyl, out _));
    }

    [Fact]
    public void Sphere_HeadOn_AndGlancing()
    {
        var obstacle = new Sphere(Vector3.Zero, 1f);
        Assert.True(TimeOfImpact.Sphere(new Vector3(5, 0, 0), new Vector3(-8, 0, 0), 0.5f, obstacle, out var hit));
        Assert.Equal((5 - 1.5f) / 8, hit.Time, Tol);
        Assert.Equal(Vector3.UnitX, hit.Normal);
        // Offset 0.9: contact when x² + 0.81 = 2.25.
        Assert.True(TimeOfImpact.Sphere(new Vector3(5, 0.9f, 0), new Vector3(-8, 0, 0), 0.5f, obstacle, out hit));
        Assert.Equal((5 - 1.2f) / 8, hit.Time, Tol);
        Assert.False(TimeOfImpact.Sphere(new Vector3(5, 1.6f, 0), new Vector3(-8, 0, 0), 0.5f, obstacle, out _));
    }
}
