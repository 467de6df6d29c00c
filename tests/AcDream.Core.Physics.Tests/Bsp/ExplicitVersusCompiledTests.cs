using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Bsp;

/// <summary>
/// The same solid as an explicit, hand-ordered tree (as retail trees arrive) and as a tree from our
/// compiler must answer every query the same way.
/// </summary>
public class ExplicitVersusCompiledTests
{
    private static readonly Vector3 Min = new(-0.5f, -0.009f, 0f), Max = new(0.5f, 0.252f, 2.2f);

    private static (BspTree Explicit, BspTree Compiled) Trees() =>
        (TestGeometry.BoxTree(Min, Max), BspCompiler.Compile(TestGeometry.BoxFaces(Min, Max)));

    [Fact]
    public void PointIntersectsSolid_Agrees_OnRandomPoints()
    {
        var (a, b) = Trees();
        var rng = new Random(7);
        int inside = 0;
        for (int i = 0; i < 5000; i++)
        {
            var p = new Vector3((float)rng.NextDouble() * 2 - 1, (float)rng.NextDouble() * 1 - 0.4f, (float)rng.NextDouble() * 3 - 0.4f);
            bool expected = BspQuery.PointIntersectsSolid(a, p);
            Assert.Equal(expected, BspQuery.PointIntersectsSolid(b, p));
            inside += expected ? 1 : 0;
        }
        Assert.InRange(inside, 100, 4900); // both sides were sampled
    }

    [Fact]
    public void SphereIntersectsSolid_Agrees_OnRandomSpheres()
    {
        var (a, b) = Trees();
        var rng = new Random(11);
        int hits = 0;
        for (int i = 0; i < 5000; i++)
        {
            var s = new Sphere(new Vector3((float)rng.NextDouble() * 3 - 1.5f, (float)rng.NextDouble() * 2 - 1f, (float)rng.NextDouble() * 3.5f - 0.6f),
                0.05f + (float)rng.NextDouble() * 0.5f);
            bool expected = BspQuery.SphereIntersectsSolid(a, s);
            Assert.Equal(expected, BspQuery.SphereIntersectsSolid(b, s));
            hits += expected ? 1 : 0;
        }
        Assert.InRange(hits, 100, 4900);
    }

    [Fact]
    public void SphereIntersectsPoly_AgreesOnHitAndPlane_ForMovesTowardTheFaces()
    {
        var (a, b) = Trees();
        var rng = new Random(13);
        int hits = 0;
        for (int i = 0; i < 3000; i++)
        {
            var s = new Sphere(new Vector3((float)rng.NextDouble() * 3 - 1.5f, (float)rng.NextDouble() * 2 - 1f, (float)rng.NextDouble() * 3.5f - 0.6f), 0.48f);
            var movement = Vector3.Normalize(new Vector3(0, 0.12f, 1.1f) - s.Center) * 0.1f;
            Polygon? hitA = null, hitB = null;
            Vector3 contactA = default, contactB = default;
            bool ha = BspNodeQuery.SphereIntersectsPoly(a, 0, s, movement, ref hitA, ref contactA);
            bool hb = BspNodeQuery.SphereIntersectsPoly(b, 0, s, movement, ref hitB, ref contactB);
            Assert.Equal(ha, hb);
            if (!ha)
                continue;
            hits++;
            // Which face wins may differ with leaf order, but both must be faces the sphere really touches.
            Assert.True(PolygonQuery.HitsSphere(hitA!, s));
            Assert.True(PolygonQuery.HitsSphere(hitB!, s));
        }
        Assert.True(hits > 50);
    }
}
