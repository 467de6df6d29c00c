using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// The side-by-side points of the sphere path (<see cref="PointLanes"/>, not retail): the rows it turns them
/// into are a sphere's layout (centre, radius) with point i in row i, and the current sphere is taken into
/// lane 2; both on the SSE path and on the element-by-element fallback.
/// </summary>
public class PointLanesTests
{
    private static readonly PointLanes Sample = PointLanes.Of(new(1, 2, 3), new(4, 5, 6), new(7, 8, 9), new(10, 11, 12));
    private static readonly Vector128<float> Radii = Vector128.Create(0.5f, 0.25f, 0.125f, 99f);

    [Fact]
    public void Rows_AreThePointsWithTheirRadius_OnBothPaths()
    {
        Sample.Rows(Radii, out var r0, out var r1, out var r2);
        Sample.RowsByLane(Radii, out var b0, out var b1, out var b2);
        foreach (var (row, byLane, expected) in new[]
                 {
                     (r0, b0, Vector128.Create(1f, 2f, 3f, 0.5f)),
                     (r1, b1, Vector128.Create(4f, 5f, 6f, 0.25f)),
                     (r2, b2, Vector128.Create(7f, 8f, 9f, 0.125f)),
                 })
        {
            Assert.Equal(expected, row);
            Assert.Equal(expected, byLane);
        }
    }

    [Fact]
    public void WithLane2From_KeepsLanes0And1_AndTakesTheOthersLane0_OnBothPaths()
    {
        var other = PointLanes.Of(new(-1, -2, -3), new(-4, -5, -6), new(-7, -8, -9), new(-10, -11, -12));
        foreach (var mixed in new[] { Sample.WithLane2From(other), Sample.WithLane2FromByLane(other) })
        {
            Assert.Equal(new Vector3(1, 2, 3), mixed[0]);
            Assert.Equal(new Vector3(4, 5, 6), mixed[1]);
            Assert.Equal(new Vector3(-1, -2, -3), mixed[2]);
        }
    }

    [Fact]
    public void Pairs_PutTheFirstInLanes0And1_AndTheSecondIn2And3_OnBothPaths()
    {
        var first = new Vector3(1.5f, -2.25f, 3f);
        var second = new Vector3(-192f, 0f, -0f);
        foreach (var pairs in new[] { PointLanes.Pairs(first, second), PointLanes.PairsByLane(first, second) })
        {
            Assert.Equal(first, pairs[0]);
            Assert.Equal(first, pairs[1]);
            Assert.Equal(second, pairs[2]);
            Assert.Equal(second, pairs[3]);
            Assert.True(float.IsNegative(pairs.Z.GetElement(2)), "the sign of a zero is kept");
        }
    }
}
