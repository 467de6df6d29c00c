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
}
