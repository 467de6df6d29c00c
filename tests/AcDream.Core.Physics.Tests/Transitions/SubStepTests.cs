using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

public class SubStepTests
{
    [Theory]
    // distance, radius, viewer -> steps (retail CalcNumSteps: ceil(d/r) when d > r, else 1 if moving, 0 if not; the camera takes floor(d/r)+1)
    [InlineData(0f, 0.48f, false, 0)]
    [InlineData(0.1f, 0.48f, false, 1)]
    [InlineData(0.48f, 0.48f, false, 1)]
    [InlineData(0.49f, 0.48f, false, 2)]
    [InlineData(4f, 0.48f, false, 9)]
    [InlineData(4f, 0.48f, true, 9)]
    [InlineData(0.96f, 0.48f, true, 3)]
    [InlineData(0.0001f, 0.48f, true, 0)]
    // Distance an exact multiple of the radius (both exact in binary): ceil(d / r) = d / r, not one more.
    [InlineData(0.5f, 0.5f, false, 1)]
    [InlineData(1f, 0.5f, false, 2)]
    [InlineData(1.5f, 0.5f, false, 3)]
    [InlineData(2f, 0.25f, false, 8)]
    // The camera's rule at an exact multiple: floor(d / r) + 1.
    [InlineData(1f, 0.5f, true, 3)]
    public void CalcNumSteps_FollowsRetail(float distance, float radius, bool viewer, int expected)
    {
        int n = Transition.CalcNumSteps(new Vector3(0, distance, 0), radius, viewer, out var perStep);
        Assert.Equal(expected, n);
        if (n > 0 && !viewer)
            Assert.Equal(distance / n, perStep.Y, 5);
    }

    /// <summary>
    /// A motion no longer than the radius is answered without the square root; around that boundary (a few
    /// float steps either side, along an axis and diagonally, and for zero, negative and NaN radii) the count
    /// and per-step offset are retail's rule worked out here in full: n = ceil(d / r) when d / r > 1, else
    /// 1 for any motion and 0 for none.
    /// </summary>
    [Fact]
    public void CalcNumSteps_AtTheRadius_FollowsRetailsFullRule()
    {
        var offsets = new List<Vector3>();
        foreach (float r in new[] { 0.48f, 0.5f, 0.3f })
        {
            float along = r;
            for (int k = 0; k < 6; k++) along = MathF.BitDecrement(along);
            for (int k = 0; k < 12; k++, along = MathF.BitIncrement(along))
            {
                offsets.Add(new Vector3(0, along, 0));
                float side = along / MathF.Sqrt(2f);
                offsets.Add(new Vector3(side, side, 0));
                offsets.Add(new Vector3(side, 0, -side));
            }
        }
        offsets.Add(Vector3.Zero);
        offsets.Add(new Vector3(-0f, 0f, -0f));
        foreach (var offset in offsets)
            foreach (float radius in new[] { 0.48f, 0.5f, 0.3f, 0f, -0.48f, float.NaN })
            {
                double step = Math.Sqrt((double)offset.X * offset.X + (double)offset.Y * offset.Y + (double)offset.Z * offset.Z) / radius;
                double count = Math.Ceiling(step);
                int expected = step > 1.0 ? (count > int.MaxValue ? int.MaxValue : (int)count) : offset != Vector3.Zero ? 1 : 0;
                int n = Transition.CalcNumSteps(offset, radius, false, out var perStep);
                Assert.True(expected == n, $"offset {offset:R}, radius {radius:R}: {n} steps, retail {expected}");
                var expectedPerStep = step > 1.0
                    ? new Vector3((float)(1.0 / count * offset.X), (float)(1.0 / count * offset.Y), (float)(1.0 / count * offset.Z))
                    : offset;
                Assert.True(expectedPerStep.Equals(perStep), $"offset {offset:R}, radius {radius:R}: per step {perStep:R}, retail {expectedPerStep:R}");
            }
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(-1f)]
    [InlineData(float.NaN)]
    public void SubStepScale_RefusesNonPositive(float scale)
    {
        var t = new Transition(new PhysicsWorld());
        Assert.Throws<ArgumentException>(() => t.SubStepScale = scale);
        Assert.Equal(1f, t.SubStepScale);
    }

    /// <summary>
    /// Through the engine: a one-sphere mover (r = 0.5) in open air asked to move exactly 1.5 m takes
    /// 1.5 / 0.5 = 3 sub-steps of 0.5 m each (reported by the observer), and ends exactly at the target.
    /// </summary>
    [Fact]
    public void AMoveOfExactlyThreeRadii_TakesThreeSubSteps()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(AcDream.Core.Physics.Terrain.Flat(Support.TestGeometry.Landblock, 0f));
        var mover = new MoverDescription(0x5000_000C, [new AcDream.Core.Physics.Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f);
        var log = new AcDream.Core.Physics.Diagnostics.TransitionEventLog();
        var engine = new PhysicsEngine(world) { Observer = log };
        var start = MoverState.Airborne(Support.TestGeometry.At(100, 100, 10));
        var target = start.Position;
        target.Frame.Origin += new Vector3(0, 1.5f, 0);
        var result = engine.Resolve(mover, start, target);
        var steps = log.Events.Where(e => e.Kind == AcDream.Core.Physics.Diagnostics.TransitionEventKind.SubStep).ToList();
        Assert.Equal(3, steps.Count);
        Assert.All(steps, e => Assert.Equal(0.5f, e.Vector2.Y, 5));
        Assert.Equal(101.5f, result.Next.Position.Origin.Y, 4);
    }
}
