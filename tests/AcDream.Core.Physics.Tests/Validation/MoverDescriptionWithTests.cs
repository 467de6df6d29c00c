namespace AcDream.Core.Physics.Tests.Validation;

/// <summary>MoverDescription.With: a copy with some fields replaced, the rest kept, checked like a new description.</summary>
public class MoverDescriptionWithTests
{
    [Fact]
    public void With_ReplacesTheNamedFields_KeepsTheOthers_AndLeavesTheOriginalAlone()
    {
        var player = MoverDescription.Player();
        var copy = player.With(physicsState: PhysicsState.Gravity, stepDownHeight: 0.5f);

        Assert.Equal(PhysicsState.Gravity, copy.PhysicsState);
        Assert.Equal(0.5f, copy.StepDownHeight);
        // Kept: the retail player's values (Setup 0x02000001).
        Assert.Equal(0x50000001u, copy.ObjectId);
        Assert.Equal(0.6f, copy.StepUpHeight);
        Assert.Equal(ObjectInfoState.IsPlayer, copy.Flags);
        Assert.Equal(1f, copy.Scale);
        Assert.Equal(0u, copy.TargetId);
        Assert.Equal([new Sphere(new Vector3(0, 0, 0.475f), 0.48f), new Sphere(new Vector3(0, 0, 1.35f), 0.48f)], copy.Spheres.ToArray());
        // The original is immutable and unchanged.
        Assert.Equal(PhysicsState.Gravity | PhysicsState.EdgeSlide, player.PhysicsState);
        Assert.Equal(MoverDescription.PlayerStepDownHeight, player.StepDownHeight);
    }

    [Fact]
    public void With_NothingGiven_CopiesEveryField()
    {
        var missile = new MoverDescription(0x7000_0100, [new Sphere(new Vector3(0, 0, 0.1f), 0.1f)], 0f, 0f,
            PhysicsState.Missile, ObjectInfoState.IsImpenetrable, 2f, targetId: 0x5000_0002);
        var copy = missile.With();
        Assert.NotSame(missile, copy);
        Assert.Equal((0x7000_0100u, 0f, 0f, PhysicsState.Missile, ObjectInfoState.IsImpenetrable, 2f, 0x5000_0002u),
            (copy.ObjectId, copy.StepUpHeight, copy.StepDownHeight, copy.PhysicsState, copy.Flags, copy.Scale, copy.TargetId));
        Assert.Equal(missile.Spheres.ToArray(), copy.Spheres.ToArray());
    }

    [Fact]
    public void With_ABadValue_IsRefusedLikeTheConstructor_NamingTheField()
    {
        var player = MoverDescription.Player();
        var error = Assert.Throws<ArgumentException>(() => player.With(scale: float.NaN));
        Assert.Contains("mover.scale", error.Message);
        error = Assert.Throws<ArgumentException>(() => player.With(flags: ObjectInfoState.Contact));
        Assert.Contains("mover.flags", error.Message);
        Assert.Equal(1f, player.Scale);
    }
}
