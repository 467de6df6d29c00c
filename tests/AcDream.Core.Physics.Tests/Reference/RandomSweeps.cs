namespace AcDream.Core.Physics.Tests.Reference;

/// <summary>Seeded random geometry shared by the reference sweep's property tests.</summary>
internal static class RandomSweeps
{
    /// <summary>A convex polygon facing <paramref name="n"/> around <paramref name="center"/>: 3–6 vertices on a circle of 0.2–3 m, counter-clockwise.</summary>
    public static Polygon ConvexPolygon(Random rng, Vector3 n, Vector3 center)
    {
        var u = Vector3.Normalize(Vector3.Cross(n, MathF.Abs(n.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitX));
        var w = Vector3.Cross(n, u);
        int count = 3 + rng.Next(4);
        float size = Uniform(rng, 0.2f, 3f);
        var vertices = new Vector3[count];
        float step = 2f * MathF.PI / count;
        for (int k = 0; k < count; k++)
        {
            // Angles increase by less than a half turn, on a circle, so the polygon is convex.
            float angle = k * step + Uniform(rng, 0f, 0.6f * step);
            vertices[k] = center + size * (MathF.Cos(angle) * u + MathF.Sin(angle) * w);
        }
        return new Polygon(vertices);
    }

    /// <summary>Hundreds of metres from the origin one time in three (where a float step is 15 µm), else the origin.</summary>
    public static Vector3 Far(Random rng) =>
        rng.Next(3) == 0 ? new Vector3(Uniform(rng, -200f, 200f), Uniform(rng, -200f, 200f), Uniform(rng, -50f, 50f)) : Vector3.Zero;

    /// <summary>A random unit vector (rejection sampling in the unit ball).</summary>
    public static Vector3 UnitVector(Random rng)
    {
        while (true)
        {
            var v = new Vector3(Uniform(rng, -1f, 1f), Uniform(rng, -1f, 1f), Uniform(rng, -1f, 1f));
            float l = v.Length();
            if (l > 0.1f && l <= 1f)
                return v / l;
        }
    }

    /// <summary>A uniform float in [<paramref name="lo"/>, <paramref name="hi"/>).</summary>
    public static float Uniform(Random rng, float lo, float hi) => lo + (float)rng.NextDouble() * (hi - lo);
}
