using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Tests.Bsp;

public class CellBspTests
{
    [Theory]
    [InlineData(0f, 0f, 0f, true)]
    [InlineData(0.99f, -0.99f, 0.99f, true)]
    [InlineData(1.0001f, 0f, 0f, true)]  // behind by 1e-4: within EPSILON, still inside
    [InlineData(1.0003f, 0f, 0f, false)] // behind by 3e-4: outside
    [InlineData(0f, 0f, -1.1f, false)]   // fails at the last split
    public void PointInsideCellBsp(float x, float y, float z, bool expected)
        => Assert.Equal(expected, BspQuery.PointInsideCellBsp(BoxFixtures.CellBox(), new Vector3(x, y, z)));

    [Theory]
    [InlineData(0f, 0f, 0f, "EntirelyInside")]
    [InlineData(0.48f, 0f, 0f, "EntirelyInside")]  // 0.52 from the wall ≥ 0.5 + 0.01
    [InlineData(0.8f, 0f, 0f, "PartiallyInside")]
    [InlineData(0f, 0f, -0.8f, "PartiallyInside")] // straddles the last split
    [InlineData(1.5f, 0f, 0f, "PartiallyInside")]  // just touching from outside: the 0.01 margin keeps it partial
    [InlineData(1.52f, 0f, 0f, "Outside")]
    [InlineData(0.8f, 0f, -1.6f, "Outside")]       // straddles one split, outside a later one
    // The expected result is named as a string: BoundingType is internal, and a public test method cannot take it.
    public void SphereIntersectsCellBsp(float x, float y, float z, string expected)
        => Assert.Equal(expected, BspQuery.SphereIntersectsCellBsp(BoxFixtures.CellBox(), new Sphere(new Vector3(x, y, z), 0.5f)).ToString());
}
