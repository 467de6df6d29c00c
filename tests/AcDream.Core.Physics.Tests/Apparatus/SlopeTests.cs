using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>Terrain slopes either side of retail's walkable limit floor_z = 0.66417414.</summary>
public class SlopeTests
{
    /// <summary>A landblock whose ground rises <paramref name="rise"/> metres per metre eastward.</summary>
    private static PhysicsWorld Slope(float rise)
    {
        var heights = new float[81];
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                heights[x * 9 + y] = rise * x * 24f;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(new Terrain(TestGeometry.Landblock, heights));
        return world;
    }

    private static Mover OnSlope(float rise, float x, float stepDownHeight = MoverDescription.PlayerStepDownHeight)
    {
        var normal = Vector3.Normalize(new Vector3(-rise, 0, 1));
        // Retail quirk (OBJECTINFO::validate_walkable, ACE ObjectInfo.ValidateWalkable): terrain contact is
        // measured from sphere 0's lowest point (centre − r·Z), not from its surface, so on a slope the
        // mover rests with that point on the plane: origin z = ground + 0.48 − 0.475.
        float originZ = rise * x + 0.005f;
        var start = TestGeometry.At(x, 100, originZ);
        var state = new MoverState
        {
            Position = start,
            Contact = true,
            OnWalkable = normal.Z >= PhysicsConstants.FloorZ,
            ContactPlane = new Plane(normal, 0f),
            ContactPlaneCellId = start.CellId,
        };
        return new Mover(Slope(rise), MoverDescription.Player(stepDownHeight: stepDownHeight), state);
    }

    [Theory]
    [InlineData(1.0f, true)]    // 45°: normal z 0.707 ≥ floor_z
    [InlineData(1.25f, false)]  // 51°: normal z 0.625 < floor_z
    public void Standing_IsOnWalkableOnlyAboveFloorZ(float rise, bool walkable)
    {
        var mover = OnSlope(rise, 100);
        mover.Step(new Vector3(0, 0.05f, 0));
        Assert.Equal(walkable, mover.State.OnWalkable);
        // Retail (CTransition::adjust_offset) lifts a sphere that sinks into its contact plane until its surface
        // touches it; on a steep slope the non-walkable step-down probe (0.04 m) cannot reach back down, so the
        // mover is left in the air. On walkable ground the setup's probe finds the surface again.
        Assert.Equal(walkable, mover.State.Contact);
    }

    /// <summary>
    /// On ground steeper than floor_z the mover is never on walkable ground, so a client keeps applying
    /// gravity and the transition turns the fall into motion along the slope: the mover slides down even
    /// when it asks for no horizontal motion. On a walkable slope it stays where it stands.
    /// </summary>
    [Theory]
    [InlineData(1.25f, true)]
    [InlineData(0.5f, false)]
    public void OnlyASlopeSteeperThanFloorZ_SlidesTheMoverDown(float rise, bool slides)
    {
        var mover = OnSlope(rise, 100);
        var start = mover.Origin;
        for (int i = 0; i < 60; i++)
            mover.StepWithGravity(Vector3.Zero, 1f / 30f);
        var moved = mover.Origin - start;
        if (slides)
        {
            Assert.True(moved.X < -0.5f, $"the mover should slide downhill (−X), moved {moved}");
            Assert.True(moved.Z < -0.5f * rise, $"and down, moved {moved}");
            Assert.DoesNotContain(mover.Frames, f => f.Result.Next.OnWalkable);
        }
        else
        {
            Assert.True(moved.Length() < 0.01f, $"a walkable slope holds the mover, moved {moved}");
            Assert.True(mover.State.OnWalkable);
        }
        // Never below the surface by more than the rest height (lowest point on the ground).
        Assert.All(mover.Frames, f => Assert.True(f.After.Z - rise * f.After.X > -0.01f, $"under the ground at {f.After}"));
    }

    [Fact]
    public void WalkingDownAWalkableSlope_FollowsTheSurface()
    {
        const float rise = 0.5f;
        var mover = OnSlope(rise, 100);
        float z0 = mover.Origin.Z;
        mover.Walk(new Vector3(-0.1f, 0, 0), 10);
        float dx = mover.Origin.X - 100f;
        Assert.InRange(dx, -1.01f, -0.99f);
        Assert.Equal(z0 + rise * dx, mover.Origin.Z, 2);
        Assert.True(mover.State.OnWalkable);
    }
}
