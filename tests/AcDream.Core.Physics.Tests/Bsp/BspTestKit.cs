using AcDream.Core.Physics.Bsp;

namespace AcDream.Core.Physics.Tests.Bsp;

/// <summary>Test-side helpers: a tiny classifier over split planes, and polygon builders independent of BspShapes.</summary>
internal static class BspTestKit
{
    public static float Dist(Plane plane, Vector3 p) => Vector3.Dot(plane.Normal, p) + plane.D;

    /// <summary>Walks the split planes from the root (front when strictly positive) and returns the leaf index.</summary>
    public static int LeafOf(BspTree tree, Vector3 p)
    {
        int i = 0;
        for (int guard = 0; guard < 10_000; guard++)
        {
            var node = tree.Nodes[i];
            if (node.IsLeaf)
                return i;
            int next = Dist(node.SplitPlane, p) > 0 ? node.Front : node.Back;
            if (next < 0)
                return -1;
            i = next;
        }
        throw new InvalidOperationException("walk did not end");
    }

    /// <summary>Inside the solid = the leaf reached is Solid.</summary>
    public static bool InSolid(BspTree tree, Vector3 p)
    {
        int leaf = LeafOf(tree, p);
        return leaf >= 0 && tree.Nodes[leaf].Solid;
    }

    /// <summary>Cell-BSP style: inside when on the front of every split on the path (a leaf or missing front = inside).</summary>
    public static bool InsideCell(BspTree tree, Vector3 p)
    {
        int i = 0;
        while (true)
        {
            var node = tree.Nodes[i];
            if (node.IsLeaf)
                return true;
            if (Dist(node.SplitPlane, p) < 0)
                return false;
            if (node.Front < 0)
                return true;
            i = node.Front;
        }
    }

    /// <summary>The node indices on the path from the root to <paramref name="p"/>'s leaf.</summary>
    public static List<int> PathTo(BspTree tree, Vector3 p)
    {
        var path = new List<int>();
        int i = 0;
        while (i >= 0)
        {
            path.Add(i);
            var node = tree.Nodes[i];
            if (node.IsLeaf) break;
            i = Dist(node.SplitPlane, p) > 0 ? node.Front : node.Back;
        }
        return path;
    }

    /// <summary>The polygons held below (and at) node <paramref name="i"/>.</summary>
    public static IEnumerable<Polygon> PolygonsBelow(BspTree tree, int i)
    {
        var node = tree.Nodes[i];
        for (int k = 0; k < node.PolygonCount; k++)
            yield return tree.Polygons[tree.PolygonIndices[node.FirstPolygon + k]];
        if (!node.IsLeaf)
        {
            if (node.Front >= 0) foreach (var p in PolygonsBelow(tree, node.Front)) yield return p;
            if (node.Back >= 0) foreach (var p in PolygonsBelow(tree, node.Back)) yield return p;
        }
    }

    public static IEnumerable<int> Leaves(BspTree tree)
    {
        for (int i = 0; i < tree.Nodes.Length; i++)
            if (tree.Nodes[i].IsLeaf) yield return i;
    }

    /// <summary>An axis-aligned rectangle with opposite corners a and b (flat along one axis), oriented to face <paramref name="normal"/>.</summary>
    public static Polygon Rect(Vector3 a, Vector3 b, Vector3 normal, PolygonSides sides = PolygonSides.Single)
    {
        Vector3 c1, c3;
        if (a.X == b.X) { c1 = new(a.X, b.Y, a.Z); c3 = new(a.X, a.Y, b.Z); }
        else if (a.Y == b.Y) { c1 = new(b.X, a.Y, a.Z); c3 = new(a.X, a.Y, b.Z); }
        else { c1 = new(b.X, a.Y, a.Z); c3 = new(a.X, b.Y, a.Z); }
        var corners = new[] { a, c1, b, c3 };
        if (Vector3.Dot(Vector3.Cross(c1 - a, b - a), normal) < 0)
            Array.Reverse(corners);
        return new Polygon(corners, sides);
    }

    /// <summary>The six outward faces of a box, built here (not by BspShapes).</summary>
    public static List<Polygon> BoxFaces(Vector3 min, Vector3 max) =>
    [
        Rect(new(max.X, min.Y, min.Z), max, Vector3.UnitX),
        Rect(min, new(min.X, max.Y, max.Z), -Vector3.UnitX),
        Rect(new(min.X, max.Y, min.Z), max, Vector3.UnitY),
        Rect(min, new(max.X, min.Y, max.Z), -Vector3.UnitY),
        Rect(new(min.X, min.Y, max.Z), max, Vector3.UnitZ),
        Rect(min, new(max.X, max.Y, min.Z), -Vector3.UnitZ),
    ];

    public static Vector3 RandomIn(Random r, Vector3 min, Vector3 max) =>
        new(min.X + (float)r.NextDouble() * (max.X - min.X),
            min.Y + (float)r.NextDouble() * (max.Y - min.Y),
            min.Z + (float)r.NextDouble() * (max.Z - min.Z));

    public static float Area(Polygon p)
    {
        var v = p.Vertices;
        var sum = Vector3.Zero;
        for (int i = 1; i < v.Length - 1; i++)
            sum += Vector3.Cross(v[i] - v[0], v[i + 1] - v[0]);
        return 0.5f * sum.Length();
    }
}
