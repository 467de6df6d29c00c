using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>Two trees the same to the bit: every node's plane, sphere, children, leaf flags and polygon list; every polygon's vertices, plane and sides.</summary>
internal static class TreeAssert
{
    public static void Same(BspTree expected, BspTree actual, string name, bool bounds = true)
    {
        Assert.True(expected.NodeArray.Length == actual.NodeArray.Length, $"{name}: {expected.NodeArray.Length} nodes, got {actual.NodeArray.Length}");
        for (int i = 0; i < expected.NodeArray.Length; i++)
        {
            var (e, a) = (expected.NodeArray[i], actual.NodeArray[i]);
            Assert.True(e.IsLeaf == a.IsLeaf && e.Solid == a.Solid && e.Front == a.Front && e.Back == a.Back, $"{name}.nodes[{i}]: leaf/solid/children differ");
            Assert.True(e.SplitPlane.Equals(a.SplitPlane), $"{name}.nodes[{i}].splitPlane: {e.SplitPlane} vs {a.SplitPlane}");
            Assert.True(!bounds || e.Bounds.Center.Equals(a.Bounds.Center) && e.Bounds.Radius.Equals(a.Bounds.Radius), $"{name}.nodes[{i}].bounds: {e.Bounds} vs {a.Bounds}");
            Assert.True(expected.IndexArray.AsSpan(e.FirstPolygon, e.PolygonCount).SequenceEqual(actual.IndexArray.AsSpan(a.FirstPolygon, a.PolygonCount)), $"{name}.nodes[{i}].polygons differ");
        }
        Assert.Equal(expected.PolygonArray.Length, actual.PolygonArray.Length);
        for (int p = 0; p < expected.PolygonArray.Length; p++)
        {
            var (e, a) = (expected.PolygonArray[p], actual.PolygonArray[p]);
            Assert.True(e.Vertices.SequenceEqual(a.Vertices), $"{name}.polygons[{p}].vertices differ");
            Assert.True(e.Plane.Equals(a.Plane) && e.Sides == a.Sides, $"{name}.polygons[{p}]: plane {e.Plane} {e.Sides} vs {a.Plane} {a.Sides}");
        }
    }
}
