using AcDream.Core.Physics.Geometry;
using Xunit.Abstractions;
using static AcDream.Core.Physics.Tests.Reference.RandomSweeps;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// The exact polygon sweep solves an edge (and its first corner) only when the edge's box meets the box the
/// sphere's centre sweeps until the best contact so far, widened by the radius and a margin
/// (<see cref="TimeOfImpact.EdgeReach"/>). That skip changes no answer only if every contact <see cref="TimeOfImpact.Segment"/>
/// or <see cref="TimeOfImpact.Point"/> reports before that time has its edge's box meeting the swept box. Checked
/// here on seeded sweeps: spheres of many radii, edges of random and of axis-aligned polygons (a door's slab,
/// where a contact's offset from the edge lies along an axis and uses the whole radius), sweeps cut off at a
/// random earlier contact, at the origin and hundreds of metres from it.
/// </summary>
public class TimeOfImpactEdgeReachPropertyTests(ITestOutputHelper output)
{
    private const int Cases = 100_000;
    private const int Seed = 20261203;

    [Fact]
    public void EveryEdgeOrCornerContactBeforeTheLimit_HasItsEdgeInTheSweptBox()
    {
        var rng = new Random(Seed);
        var failures = new List<string>();
        int failed = 0, contacts = 0, skipped = 0, tight = 0;
        for (int i = 0; i < Cases; i++)
        {
            var (polygon, c, d, r, limit) = MakeCase(rng);
            TimeOfImpact.EdgeReach(c, d, r, limit, polygon, out var min, out var max);
            var v = polygon.Vertices;
            for (int k = 0; k < v.Length; k++)
            {
                var a = v[k];
                var b = v[(k + 1) % v.Length];
                bool meets = TimeOfImpact.EdgeMeetsBox(a, b, min, max);
                if (!meets)
                    skipped++;
                bool edge = TimeOfImpact.Segment(c, d, r, a, b, out float te, out _) && te <= limit;
                bool corner = TimeOfImpact.Point(c, d, r, a, out float tv, out _) && tv <= limit;
                if (!edge && !corner)
                    continue;
                contacts++;
                // How close the contact came to being skipped: the edge's box inside the swept box by less than 2 cm.
                var edgeMin = Vector3.Min(a, b);
                var edgeMax = Vector3.Max(a, b);
                float inside = MathF.Min(MathF.Min(MathF.Min(edgeMax.X - min.X, edgeMax.Y - min.Y), edgeMax.Z - min.Z),
                    MathF.Min(MathF.Min(max.X - edgeMin.X, max.Y - edgeMin.Y), max.Z - edgeMin.Z));
                if (inside < 0.02f)
                    tight++;
                if (!meets)
                {
                    failed++;
                    if (failures.Count < 10)
                        failures.Add($"case {i}: c {c} d {d} r {r} limit {limit} edge {a} -> {b}: {(edge ? $"edge t={te}" : "")} {(corner ? $"corner t={tv}" : "")} outside the box {min}..{max}");
                }
            }
        }
        output.WriteLine($"seed {Seed}: {Cases} sweeps, {contacts} edge or corner contacts before the limit ({tight} within 2 cm of the box's side), {skipped} edges skipped");
        Assert.True(failed == 0, $"{failed} contacts lie on skipped edges; the first:\n" + string.Join("\n", failures));
        Assert.True(contacts > Cases / 4, $"only {contacts} contacts");
        Assert.True(tight > Cases / 50, $"only {tight} contacts near the box's side: the margin is not tested");
        Assert.True(skipped > Cases, $"only {skipped} edges skipped");
    }

    /// <summary>
    /// A polygon (half of them axis-aligned rectangles, the rest random convex polygons) and a sweep ending near
    /// one of its edges or corners, from either side, cut off at a random fraction (half of them at 1).
    /// </summary>
    private static (Polygon, Vector3, Vector3, float, float) MakeCase(Random rng)
    {
        float r = rng.Next(4) switch
        {
            0 => Uniform(rng, 1e-4f, 0.02f),
            1 or 2 => Uniform(rng, 0.1f, 0.6f),
            _ => Uniform(rng, 0.6f, 3f),
        };
        var far = Far(rng);
        Polygon polygon;
        bool axes = rng.Next(2) == 0;
        if (axes)
        {
            // A face of a slab: a rectangle in one of the axis planes.
            int axis = rng.Next(3);
            float w = Uniform(rng, 0.1f, 3f), h = Uniform(rng, 0.1f, 3f);
            Vector3 U(float x, float y) => axis switch
            {
                0 => new Vector3(0, x, y),
                1 => new Vector3(y, 0, x),
                _ => new Vector3(x, y, 0),
            };
            polygon = new Polygon([far + U(0, 0), far + U(w, 0), far + U(w, h), far + U(0, h)]);
        }
        else
        {
            polygon = ConvexPolygon(rng, UnitVector(rng), far);
        }
        var v = polygon.Vertices;
        int e = rng.Next(v.Length);
        var a = v[e];
        var b = v[(e + 1) % v.Length];
        var target = rng.Next(3) == 0 ? a : Vector3.Lerp(a, b, Uniform(rng, 0f, 1f));
        // The end: within about a radius of the edge, often along an axis (where the box is tight).
        var offset = axes && rng.Next(2) == 0 ? Axis(rng) * Uniform(rng, 0.5f * r, 1.3f * r) : UnitVector(rng) * Uniform(rng, 0f, 1.5f * r);
        var end = target + offset;
        var d = axes && rng.Next(2) == 0 ? Axis(rng) * Uniform(rng, 0.01f, 4f) : UnitVector(rng) * Uniform(rng, 0.01f, 4f);
        var c = end - d;
        float limit = rng.Next(2) == 0 ? 1f : Uniform(rng, 0f, 1f);
        return (polygon, c, d, r, limit);
    }

    private static Vector3 Axis(Random rng)
    {
        float sign = rng.Next(2) == 0 ? -1f : 1f;
        return rng.Next(3) switch { 0 => new Vector3(sign, 0, 0), 1 => new Vector3(0, sign, 0), _ => new Vector3(0, 0, sign) };
    }
}
