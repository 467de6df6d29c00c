using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// Casts over flat terrain with hand-computed answers: the cases issue 24 found wrong (a NaN point and
/// normal for a ray lying in the ground across a cell edge; hits above the ground, up to kilometres early
/// with tilted normals, for shallow rays and sphere casts over several landblocks).
/// </summary>
public class TerrainCastTests
{
    private const uint Land = 0xA9B40025;

    /// <summary>2 × 2 landblocks of flat ground at z = 0, south-west landblock 0xA9B4.</summary>
    private static WorldQuery FlatBlocks()
    {
        var world = new PhysicsWorld();
        foreach (uint block in new uint[] { 0xA9B4, 0xAAB4, 0xA9B5, 0xAAB5 })
            world.Cells.AddLandblock(Terrain.Flat(block, 0f));
        return new WorldQuery(world);
    }

    [Fact]
    public void RayLyingInTheGround_AcrossACellEdge_IsClear()
    {
        var q = new WorldQuery(SceneLibrary.Load("door").World);
        // Moving along the ground is not moving into it, on either side of the cell edge at x = 24.
        Assert.False(q.RayCast(new Position(Land, new Vector3(10, 100, 0)), new Vector3(30, 100, 0), out var hit), hit.ToString());
        Assert.False(q.SphereCast(new Position(Land, new Vector3(10, 100, 0)), new Vector3(30, 100, 0), 0f, out hit), hit.ToString());
        // Starting 4 µm short of the edge (within the contact slop of the next cell's triangles): a ray is
        // judged by the face's normal, along which it does not move, not by the direction to the edge.
        Assert.False(q.RayCast(new Position(Land, new Vector3(23.999996f, 100, 0)), new Vector3(30, 100, 0), out hit), hit.ToString());
    }

    [Fact]
    public void SphereRollingOnTheGround_AcrossCellEdges_IsClear()
    {
        var q = FlatBlocks();
        Assert.False(q.SphereCast(new Position(Land, new Vector3(10, 100, 0.3f)), new Vector3(300, 130, 0.3f), 0.3f, out var hit), hit.ToString());
    }

    [Fact]
    public void SphereCast_PassingBesideABall_WithinTheSumOfTheRadii_HitsIt()
    {
        // A 0.5 m ball at (100, 100, 1); a 0.3 m sphere passes 0.7 m beside its centre, under 0.8 m:
        // contact when (x − 100)² + 0.7² = 0.8², x = 100 − √0.15. Its centre's path stays outside the
        // ball's bounds: only the cast's radius brings it within reach.
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        world.Objects.Register(7, new Physics.PhysicsSetup { Spheres = [new Physics.Sphere(Vector3.Zero, 0.5f)] }, Position.Outdoor(0xA9B4, new Vector3(100, 100, 1)));
        var q = new WorldQuery(world);
        Assert.True(q.SphereCast(Position.Outdoor(0xA9B4, new Vector3(98, 100.7f, 1)), new Vector3(102, 100.7f, 1), 0.3f, out var hit));
        Assert.Equal(7u, hit.ObjectId);
        Assert.Equal((100 - MathF.Sqrt(0.15f) - 98) / 4, hit.Fraction, 4);
        Assert.False(q.SphereCast(Position.Outdoor(0xA9B4, new Vector3(98, 100.85f, 1)), new Vector3(102, 100.85f, 1), 0.3f, out _));
    }

    [Fact]
    public void AShallowRay_ThroughTheSeamOfTwoTiltedTriangles_HitsOneOfThem()
    {
        // Landblock 0xAAB5 of a plane z = 30 + 0.07 x − 0.04 y (global metres from landblock 0xA8B3's
        // corner, heights rounded to float, so neighbouring triangles are a few micrometres off one plane).
        // The ray descends at 0.4° onto the midpoint of the edge between cells (4, 6) and (4, 7), reached at
        // two thirds of its length; each triangle's own plane crossing lies a fraction of a millimetre
        // outside it, on the other's side (the case the property test found).
        var heights = new float[81];
        for (int x = 0; x <= 8; x++)
            for (int y = 0; y <= 8; y++)
                heights[x * 9 + y] = 30f + 0.07f * (float)(384 + 24 * x) + -0.04f * (float)(384 + 24 * y);
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(new Terrain(0xAAB5, heights));
        var q = new WorldQuery(world);
        Assert.True(q.RayCast(new Position(0xAAB50001, new Vector3(90.74563f, 147.02267f, 42.18578f)), new Vector3(116.62718f, 178.48866f, 42.447105f), out var hit));
        Assert.Equal(2f / 3f, hit.Fraction, 1e-4f);
        Assert.Equal(SurfaceKind.Terrain, hit.Kind);
    }

    [Fact]
    public void ASingleSidedFace_IsNotMetFromBehind_EvenAtItsEdge()
    {
        // A one-sided 2 m floor tile at z = 1 facing up (x 99..101). A 0.3 m sphere rising straight up
        // 0.25 m east of its east edge, from 0.4 m below its plane to 0.6 m above: it comes within 0.3 m of
        // the edge at z = 0.834, behind the plane, and leaves it above; no contact from behind. The same
        // sphere falling 0.3 m above the tile, moving west, lands on its front.
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, -10f));
        var tile = new Physics.PhysicsModel(Physics.Scenes.BspShapes.Floor(Vector3.Zero, new Vector2(2, 2)));
        world.Objects.Register(9, new Physics.PhysicsSetup { Parts = [new Physics.SetupPart(tile, Frame.Identity)] }, Position.Outdoor(0xA9B4, new Vector3(100, 100, 1)));
        var q = new WorldQuery(world);
        Assert.False(q.SphereCast(Position.Outdoor(0xA9B4, new Vector3(101.25f, 100, 0.6f)), new Vector3(101.25f, 100, 1.6f), 0.3f, out var hit), hit.ToString());
        Assert.True(q.SphereCast(Position.Outdoor(0xA9B4, new Vector3(101.5f, 100, 1.3f)), new Vector3(100.5f, 100, 1.27f), 0.3f, out hit));
        Assert.Equal(9u, hit.ObjectId);
    }

    [Fact]
    public void ShallowRays_OverFourLandblocks_HitWhereTheyMeetTheGround()
    {
        var q = FlatBlocks();
        var failures = new List<string>();
        for (int i = 0; i < 200; i++)
        {
            // From 0.5–5 m up near the south-west corner to 0.01–1 m under the ground up to 380 m away.
            float h = 0.5f + 4.5f * (i % 10) / 9f, depth = 0.01f + (i % 7) / 6f;
            var from = new Vector3(3 + i % 13, 4 + i % 11, h);
            var to = new Vector3(40 + 340 * (i % 17) / 16f, 30 + 340 * (i % 19) / 18f, -depth);
            float expected = h / (h + depth);
            if (!q.RayCast(new Position(Land & 0xFFFF0000 | 1, from), to, out var hit))
                failures.Add($"ray {i}: no hit, expected fraction {expected}");
            else if (MathF.Abs(hit.Fraction - expected) > 1e-4f || hit.Normal != Vector3.UnitZ || MathF.Abs(hit.Point.Z) > 1e-3f)
                failures.Add($"ray {i}: {hit}, expected fraction {expected}, normal (0, 0, 1), point on z = 0");
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures.Take(10)) + $"\n({failures.Count} of 200)");
    }

    [Fact]
    public void ShallowSphereCasts_OverFourLandblocks_TouchTheGroundAtTheirRadius()
    {
        var q = FlatBlocks();
        const float r = 0.3f;
        var failures = new List<string>();
        for (int i = 0; i < 200; i++)
        {
            float h = r + 0.05f + 4.5f * (i % 10) / 9f, depth = 0.01f + (i % 7) / 6f;
            var from = new Vector3(3 + i % 13, 4 + i % 11, h);
            var to = new Vector3(40 + 340 * (i % 17) / 16f, 30 + 340 * (i % 19) / 18f, -depth);
            float expected = (h - r) / (h + depth);
            if (!q.SphereCast(new Position(Land & 0xFFFF0000 | 1, from), to, r, out var hit))
                failures.Add($"cast {i}: no hit, expected fraction {expected}");
            else if (MathF.Abs(hit.Fraction - expected) > 1e-4f || Vector3.Distance(hit.Normal, Vector3.UnitZ) > 1e-4f || MathF.Abs(hit.Point.Z) > 1e-3f)
                failures.Add($"cast {i}: {hit}, expected fraction {expected}, normal (0, 0, 1), point on z = 0");
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures.Take(10)) + $"\n({failures.Count} of 200)");
    }
}
