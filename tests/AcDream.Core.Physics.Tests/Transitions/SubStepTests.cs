using AcDream.Core.Physics;
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
        world.Cells.AddLandblock(AcDream.Core.Physics.World.Terrain.Flat(Support.TestGeometry.Landblock, 0f));
        var mover = new MoverDescription(0x5000_000C, [new AcDream.Core.Physics.Geometry.Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f);
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
