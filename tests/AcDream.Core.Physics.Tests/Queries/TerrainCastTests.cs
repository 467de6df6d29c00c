using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;

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
    }

    [Fact]
    public void SphereRollingOnTheGround_AcrossCellEdges_IsClear()
    {
        var q = FlatBlocks();
        Assert.False(q.SphereCast(new Position(Land, new Vector3(10, 100, 0.3f)), new Vector3(300, 130, 0.3f), 0.3f, out var hit), hit.ToString());
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
