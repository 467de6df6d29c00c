using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Bench.Compile;

/// <summary>
/// Meshes for the BSP compiler's cost job and its output-identity test: a triangle soup (overlapping,
/// many splits), a convex prism (one tree level per face plane: the compiler's worst case) and an open
/// height field. Each is a fixed function of its arguments (System.Random with a seed).
/// </summary>
public static class CompileMeshes
{
    /// <summary><paramref name="count"/> triangles of 1–2 m, scattered in a 10 m cube, randomly oriented.</summary>
    public static Polygon[] Soup(int count, int seed)
    {
        var random = new Random(seed);
        float R(float scale) => (float)(random.NextDouble() * 2 - 1) * scale;
        var result = new Polygon[count];
        for (int i = 0; i < count; i++)
        {
            var centre = new Vector3(R(5), R(5), R(5));
            while (true)
            {
                var a = centre + new Vector3(R(1), R(1), R(1));
                var b = centre + new Vector3(R(1), R(1), R(1));
                var c = centre + new Vector3(R(1), R(1), R(1));
                if (Vector3.Cross(b - a, c - a).Length() < 0.2f)
                    continue;
                result[i] = new Polygon([a, b, c]);
                break;
            }
        }
        return result;
    }

    /// <summary>A closed convex prism of radius 10 m and height 1 m: <paramref name="sides"/> side quads, top and bottom fans (3 × sides faces).</summary>
    public static Polygon[] Prism(int sides)
    {
        var faces = new List<Polygon>();
        for (int i = 0; i < sides; i++)
        {
            double a0 = 2 * Math.PI * i / sides, a1 = 2 * Math.PI * (i + 1) / sides;
            var p = new Vector3(10 * (float)Math.Cos(a0), 10 * (float)Math.Sin(a0), 0f);
            var q = new Vector3(10 * (float)Math.Cos(a1), 10 * (float)Math.Sin(a1), 0f);
            var up = Vector3.UnitZ;
            faces.Add(new Polygon([p, q, q + up, p + up]));
            faces.Add(new Polygon([up, p + up, q + up]));
            faces.Add(new Polygon([Vector3.Zero, q, p]));
        }
        return faces.ToArray();
    }

    /// <summary>An open height field of <paramref name="size"/> × <paramref name="size"/> one-metre cells, two triangles each, heights 0–1 m.</summary>
    public static Polygon[] HeightField(int size, int seed)
    {
        var random = new Random(seed);
        var h = new float[size + 1, size + 1];
        for (int x = 0; x <= size; x++)
            for (int y = 0; y <= size; y++)
                h[x, y] = (float)random.NextDouble();
        var faces = new List<Polygon>();
        for (int x = 0; x < size; x++)
            for (int y = 0; y < size; y++)
            {
                Vector3 P(int i, int j) => new(i, j, h[i, j]);
                faces.Add(new Polygon([P(x, y), P(x + 1, y), P(x + 1, y + 1)]));
                faces.Add(new Polygon([P(x, y), P(x + 1, y + 1), P(x, y + 1)]));
            }
        return faces.ToArray();
    }
}
