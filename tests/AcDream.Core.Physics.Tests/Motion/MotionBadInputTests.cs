namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>Bad commands get a clear error naming the field, and nothing the caller owns changes.</summary>
public class MotionBadInputTests
{
    private static void Unchanged(MotionRig rig, Action act, string field)
    {
        var state = rig.State;
        var body = rig.Body;
        var interpreted = rig.Motion.Interpreted;
        var ex = Assert.Throws<ArgumentException>(act);
        Assert.StartsWith(field, ex.Message);
        Assert.Equal(state.Position.Frame.Origin, rig.State.Position.Frame.Origin);
        Assert.Equal(state.OnWalkable, rig.State.OnWalkable);
        Assert.Equal(body.Velocity, rig.Body.Velocity);
        Assert.Equal(interpreted, rig.Motion.Interpreted);
    }

    [Fact]
    public void AnUnknownCommand_IsRefused()
    {
        var rig = new MotionRig();
        Unchanged(rig, () => rig.Do(0x41000099), "motion: command 0x41000099");
    }

    [Fact]
    public void AnUnknownStyle_IsRefused()
    {
        var rig = new MotionRig();
        Unchanged(rig, () => rig.Do(0x8000003C), "motion: command 0x8000003C");
    }

    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    [InlineData(float.NegativeInfinity)]
    [InlineData(1e9f)]
    public void ANonFiniteOrHugeSpeed_IsRefused(float speed)
    {
        var rig = new MotionRig();
        Unchanged(rig, () => rig.Do(MotionCommand.WalkForward, speed: speed), "parameters.Speed");
    }

    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    [InlineData(-0.5f)]
    public void ANonFiniteOrNegativeExtent_IsRefused(float extent)
    {
        var rig = new MotionRig();
        Unchanged(rig, () => rig.Motion.Jump(extent, true, rig.Mover, ref rig.State, ref rig.Body), "extent");
    }

    [Fact]
    public void ANonFiniteBodyVelocity_IsRefused()
    {
        var rig = new MotionRig();
        rig.Body.Velocity = new System.Numerics.Vector3(float.NaN, 0, 0);
        var ex = Assert.Throws<ArgumentException>(() => rig.Do(MotionCommand.WalkForward));
        Assert.StartsWith("body.velocity", ex.Message);
        Assert.Throws<ArgumentException>(() => rig.Engine.Step(rig.Mover, rig.State, rig.Body, rig.Motion, 1.0 / 30));
    }
}
