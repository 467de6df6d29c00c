using AcDream.Core.Physics.Geometry;
using Xunit.Abstractions;
using static AcDream.Core.Physics.Tests.Reference.RandomSweeps;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// The exact polygon sweep returns early for a sphere that starts behind a single-sided polygon and still ends
/// behind its plane. That is an optimization of the rule it had before — from behind, only an edge or a corner
/// can be met, and only with the centre in front of the plane at that moment — so it must give the same answer
/// bit for bit. Here the rule is written out as it was (every edge and corner solved, each contact kept when it
/// is the earliest so far and <c>s0 + t·vn ≥ 0</c>) and compared with <see cref="TimeOfImpact.Polygon(Vector3, Vector3, float, Polygon, out ImpactHit)"/>
/// on seeded sweeps that start behind the plane: rays and spheres of many radii, ending behind, just in front
/// or well in front of the plane, near edges and corners, skimming along the plane, crossing terrain-like
/// ridges, at the origin and hundreds of metres from it.
/// </summary>
public class TimeOfImpactBehindPropertyTests(ITestOutputHelper output)
{
    private const int Cases = 100_000;
    private const int Seed = 20261202;

    [Fact]
    public void StartBehindSingleSidedPolygon_SameAnswerAsSolvingEveryEdgeAndCorner()
    {
        var rng = new Random(Seed);
        var failures = new List<string>();
        int failed = 0, hits = 0, endsBehind = 0, refusedEndsBehind = 0, hitsEndingNearPlane = 0, rays = 0;
        var modes = new int[4];
        for (int i = 0; i < Cases; i++)
        {
            var (mode, polygon, c, d, r) = MakeCase(rng);
            modes[mode]++;
            if (r < 1e-4f)
                rays++;
            bool expected = OldRule(c, d, r, polygon, out var want, out bool refusedOnly);
            bool found = TimeOfImpact.Polygon(c, d, r, polygon, out var got);
            float s0 = Vector3.Dot(polygon.Plane.Normal, c - polygon.Vertices[0]);
            float vn = Vector3.Dot(polygon.Plane.Normal, d);
            if (s0 + vn < 0f)
            {
                endsBehind++;
                if (refusedOnly)
                    refusedEndsBehind++;
            }
            if (expected)
            {
                hits++;
                if (s0 + vn < 1e-3f)
                    hitsEndingNearPlane++;
            }
            if (found != expected || (found && !Same(got, want)))
            {
                failed++;
                if (failures.Count < 10)
                    failures.Add($"case {i} (mode {mode}): c {c} d {d} r {r} {polygon}: got {(found ? got.ToString() : "none")}, the rule gives {(expected ? want.ToString() : "none")}");
            }
        }
        output.WriteLine($"seed {Seed}: {Cases} sweeps from behind ({rays} rays), modes [{string.Join(", ", modes)}], {hits} hits " +
            $"({hitsEndingNearPlane} ending less than 1 mm in front), {endsBehind} ending behind ({refusedEndsBehind} with an edge or corner met while behind)");
        Assert.True(failed == 0, $"{failed} of {Cases} sweeps differ from the rule; the first:\n" + string.Join("\n", failures));
        // The generator must keep reaching the cases that tell the rule from a looser early return.
        Assert.True(hits > Cases / 20, $"only {hits} hits");
        Assert.True(hitsEndingNearPlane > 100, $"only {hitsEndingNearPlane} hits ending less than 1 mm in front of the plane");
        Assert.True(refusedEndsBehind > Cases / 20, $"only {refusedEndsBehind} sweeps ending behind met an edge or corner while behind");
    }

    /// <summary>
    /// The rule before the early return, for a start behind a single-sided polygon: rays and sweeps not moving
    /// towards the front meet nothing; otherwise each edge, then its first corner, in order, replaces the best
    /// contact when earlier and with the centre in front of the plane (<c>s0 + t·vn ≥ 0</c>). <paramref name="refusedOnly"/>:
    /// some edge or corner was met, but only while the centre was behind.
    /// </summary>
    private static bool OldRule(Vector3 c, Vector3 d, float r, Polygon polygon, out ImpactHit hit, out bool refusedOnly)
    {
        hit = default;
        refusedOnly = false;
        var n = polygon.Plane.Normal;
        var v = polygon.Vertices;
        float s0 = Vector3.Dot(n, c - v[0]);
        float vn = Vector3.Dot(n, d);
        Assert.True(s0 < 0f && polygon.Sides == PolygonSides.Single, "the generator made a start that is not behind");
        if (r < 1e-4f || !(vn > 0f))
            return false;
        float best = float.PositiveInfinity;
        var normal = Vector3.Zero;
        var feature = ImpactFeature.None;
        bool met = false;
        for (int i = 0; i < v.Length; i++)
        {
            var a = v[i];
            var b = v[(i + 1) % v.Length];
            if (TimeOfImpact.Segment(c, d, r, a, b, out float te, out var ne))
            {
                met = true;
                if (te < best && s0 + te * vn >= 0f)
                    (best, normal, feature) = (te, ne, ImpactFeature.Edge);
            }
            if (TimeOfImpact.Point(c, d, r, a, out float tv, out var nv))
            {
                met = true;
                if (tv < best && s0 + tv * vn >= 0f)
                    (best, normal, feature) = (tv, nv, ImpactFeature.Vertex);
            }
        }
        if (feature == ImpactFeature.None)
        {
            refusedOnly = met;
            return false;
        }
        hit = new ImpactHit(best, normal, feature);
        return true;
    }

    private static bool Same(ImpactHit a, ImpactHit b) =>
        a.Feature == b.Feature && Bits(a.Time) == Bits(b.Time)
        && Bits(a.Normal.X) == Bits(b.Normal.X) && Bits(a.Normal.Y) == Bits(b.Normal.Y) && Bits(a.Normal.Z) == Bits(b.Normal.Z);

    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    /// <summary>
    /// One sweep starting behind a single-sided polygon. Modes: 0, a random convex polygon and a sweep whose end
    /// lies near one of its edges or corners, from behind to within two radii on either side of the plane;
    /// 1, the same ending within a millimetre of the plane; 2, a sweep skimming along the plane (a small
    /// normal component) into an edge from outside; 3, a terrain ridge: a sphere low above one triangle, behind
    /// the next one's plane, rolling over the shared edge.
    /// </summary>
    private static (int Mode, Polygon Polygon, Vector3 C, Vector3 D, float R) MakeCase(Random rng)
    {
        while (true)
        {
            int mode = rng.Next(4);
            float r = Radius(rng);
            var far = Far(rng);
            (Polygon polygon, Vector3 c, Vector3 d) = mode == 3 ? Ridge(rng, far, r) : Convex(rng, mode, far, r);
            if (!(Vector3.Dot(polygon.Plane.Normal, c - polygon.Vertices[0]) < 0f))
                continue;
            return (mode, polygon, c, d, r);
        }
    }

    private static float Radius(Random rng) => rng.Next(5) switch
    {
        0 => Uniform(rng, 0f, 9e-5f), // a ray
        1 => Uniform(rng, 1e-4f, 0.02f),
        2 or 3 => Uniform(rng, 0.1f, 0.6f),
        _ => Uniform(rng, 0.6f, 3f),
    };

    private static (Polygon, Vector3, Vector3) Convex(Random rng, int mode, Vector3 far, float r)
    {
        var polygon = ConvexPolygon(rng, UnitVector(rng), far + new Vector3(Uniform(rng, -5f, 5f), Uniform(rng, -5f, 5f), Uniform(rng, -5f, 5f)));
        var vertices = polygon.Vertices;
        int count = vertices.Length;
        var n = polygon.Plane.Normal;
        // A point near an edge or a corner, in the plane, then the end of the sweep off it.
        int e = rng.Next(count);
        var a = vertices[e];
        var b = vertices[(e + 1) % count];
        var along = rng.Next(3) == 0 ? a : Vector3.Lerp(a, b, Uniform(rng, 0f, 1f));
        var outward = Vector3.Normalize(Vector3.Cross(b - a, n));
        var inPlane = along + outward * Uniform(rng, -1.5f * r, 2f * r) + Vector3.Normalize(b - a) * Uniform(rng, -0.5f * r, 0.5f * r);
        float s0, s1;
        Vector3 lateral;
        switch (mode)
        {
            case 0:
                s0 = -Uniform(rng, 0f, 2f * r + 0.01f);
                s1 = Uniform(rng, -2f * r - 0.01f, 2f * r + 0.01f);
                lateral = RandomInPlane(rng, n) * Uniform(rng, 0f, 3f * r + 0.05f);
                break;
            case 1:
                s0 = -Uniform(rng, 0f, 2f * r + 0.01f);
                s1 = Uniform(rng, -1e-3f, 1e-3f);
                lateral = RandomInPlane(rng, n) * Uniform(rng, 0f, 3f * r + 0.05f);
                break;
            default:
                // Skimming: starting just behind, outside the edge, moving inward across it.
                s0 = -Uniform(rng, 0f, 2e-3f);
                s1 = Uniform(rng, -2e-3f, 2e-3f);
                lateral = -outward * Uniform(rng, 0.5f * r, 4f * r + 0.05f) + Vector3.Normalize(b - a) * Uniform(rng, -r, r);
                break;
        }
        var end = inPlane + s1 * n;
        var start = end - lateral - (s1 - s0) * n;
        return (polygon, start, end - start);
    }

    /// <summary>
    /// Two terrain triangles on a 24 m cell's diagonal, the second folded down along the shared edge (a convex
    /// ridge); the sweep starts low above the first, which puts it behind the second's plane, and rolls over the ridge.
    /// </summary>
    private static (Polygon, Vector3, Vector3) Ridge(Random rng, Vector3 far, float r)
    {
        float cell = rng.Next(2) == 0 ? 24f : Uniform(rng, 1f, 24f);
        float h = Uniform(rng, -3f, 3f);
        float fold = Uniform(rng, 0.001f, 1f) * cell;
        var p00 = far + new Vector3(0, 0, h);
        var p11 = far + new Vector3(cell, cell, h);
        var p10 = far + new Vector3(cell, 0, h);
        var p01 = far + new Vector3(0, cell, h - fold);
        // The first triangle (p00, p10, p11) is flat; the second (p00, p11, p01) drops towards p01.
        var second = new Polygon([p00, p11, p01]);
        var diagonalIn = Vector3.Normalize(new Vector3(-1, 1, 0)); // from the ridge into the second triangle
        var onRidge = Vector3.Lerp(p00, p11, Uniform(rng, -0.1f, 1.1f));
        float height = rng.Next(2) == 0 ? r + Uniform(rng, -1e-3f, 1e-3f) : Uniform(rng, 0f, 2f * r + 0.01f);
        var start = onRidge - diagonalIn * Uniform(rng, 0f, 2f * r + 0.5f) + new Vector3(0, 0, height);
        var d = diagonalIn * Uniform(rng, 0.01f, 2f * r + 1f) + new Vector3(Uniform(rng, -0.2f, 0.2f), Uniform(rng, -0.2f, 0.2f), Uniform(rng, -0.3f, 0.05f));
        return (second, start, d);
    }

    private static Vector3 RandomInPlane(Random rng, Vector3 n)
    {
        var v = UnitVector(rng);
        v -= Vector3.Dot(v, n) * n;
        return v.LengthSquared() > 1e-6f ? Vector3.Normalize(v) : Vector3.Normalize(Vector3.Cross(n, Vector3.UnitX + Vector3.UnitY * 0.5f));
    }
}
