using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

public class MissileIgnoreTests
{
    private static ObjectInfo Mover(bool missile, uint target = 0, bool player = false) => new()
    {
        PhysicsState = missile ? PhysicsState.Missile : PhysicsState.None,
        TargetId = target,
        State = player ? ObjectInfoState.IsPlayer : ObjectInfoState.None,
    };

    [Fact]
    public void AMissileObject_IsIgnoredByEveryMover_EvenAPlayerItIsAimedAt()
    {
        Assert.True(ObjectCollisions.MissileIgnore(Mover(false, player: true), 5, PhysicsState.Missile, ShadowFlags.HasWeenie));
        Assert.True(ObjectCollisions.MissileIgnore(Mover(false), 5, PhysicsState.Missile, ShadowFlags.None));
    }

    [Theory]
    // target id, target state, target flags, mover's target -> ignored
    [InlineData(7u, PhysicsState.Ethereal, ShadowFlags.HasWeenie, 0u, true)]
    [InlineData(7u, PhysicsState.Ethereal, ShadowFlags.None, 0u, false)]          // scenery has no weenie
    [InlineData(7u, PhysicsState.None, ShadowFlags.IsCreature, 9u, true)]          // a creature that is not the target
    [InlineData(9u, PhysicsState.None, ShadowFlags.IsCreature, 9u, false)]         // the target itself
    [InlineData(7u, PhysicsState.None, ShadowFlags.IsCreature, 0u, false)]         // untargeted missiles hit creatures
    [InlineData(7u, PhysicsState.Static, ShadowFlags.HasWeenie, 9u, false)]        // a door or wall is hit
    public void AMissileMover_IgnoresOnlyWhatRetailIgnores(uint targetId, PhysicsState state, ShadowFlags flags, uint moverTarget, bool expected)
        => Assert.Equal(expected, ObjectCollisions.MissileIgnore(Mover(true, moverTarget), targetId, state, flags));

    [Fact]
    public void AWalkingMover_IgnoresNothingButMissiles()
        => Assert.False(ObjectCollisions.MissileIgnore(Mover(false), 7, PhysicsState.Ethereal, ShadowFlags.IsCreature | ShadowFlags.HasWeenie));
}
