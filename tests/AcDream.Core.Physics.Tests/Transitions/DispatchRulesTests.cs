using AcDream.Core.Physics;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Transitions;

public class DispatchRulesTests
{
    [Theory]
    // state has bsp, missileIgnore, exemption -> BSP only
    [InlineData(true, false, false, true)]
    [InlineData(true, true, false, false)]
    [InlineData(true, false, true, false)]
    [InlineData(true, true, true, false)]
    [InlineData(false, false, false, false)]
    [InlineData(false, true, false, false)]
    [InlineData(false, false, true, false)]
    [InlineData(false, true, true, false)]
    public void BspOnlyDispatch_TruthTable(bool hasBsp, bool missileIgnore, bool exemption, bool expected)
    {
        var state = PhysicsState.ReportCollisions | (hasBsp ? PhysicsState.HasPhysicsBsp : 0);
        Assert.Equal(expected, ObjectCollisions.BspOnlyDispatch(state, missileIgnore, exemption));
    }

    [Theory]
    [InlineData(0x10008u, true)]
    [InlineData(0x10009u, true)]
    [InlineData(0x00008u, false)]
    [InlineData(0x00009u, false)]
    public void BspOnlyDispatch_SeedDoorStates(uint state, bool expected)
        => Assert.Equal(expected, ObjectCollisions.BspOnlyDispatch((PhysicsState)state, false, false));

    [Theory]
    [InlineData(ObjectInfoState.IsPlayer, ShadowFlags.IsPlayer, true)]
    [InlineData(ObjectInfoState.None, ShadowFlags.IsPlayer, false)]
    [InlineData(ObjectInfoState.IsPlayer, ShadowFlags.None, false)]
    [InlineData(ObjectInfoState.IsPlayer | ObjectInfoState.IsImpenetrable, ShadowFlags.IsPlayer, false)]
    [InlineData(ObjectInfoState.IsPlayer, ShadowFlags.IsPlayer | ShadowFlags.IsImpenetrable, false)]
    [InlineData(ObjectInfoState.IsPlayer | ObjectInfoState.IsPK, ShadowFlags.IsPlayer | ShadowFlags.IsPK, false)]
    [InlineData(ObjectInfoState.IsPlayer | ObjectInfoState.IsPK, ShadowFlags.IsPlayer, true)]
    [InlineData(ObjectInfoState.IsPlayer | ObjectInfoState.IsPKLite, ShadowFlags.IsPlayer | ShadowFlags.IsPKLite, false)]
    [InlineData(ObjectInfoState.IsPlayer | ObjectInfoState.IsPK, ShadowFlags.IsPlayer | ShadowFlags.IsPKLite, true)]
    public void PvpExemption_TruthTable(ObjectInfoState mover, ShadowFlags target, bool expected)
        => Assert.Equal(expected, ObjectCollisions.PvpExemption(mover, target));
}

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

/// <summary>A mover that is also registered as an object (as a client registers every physics object) never collides with its own rows.</summary>
public class SelfCollisionTests
{
    [Fact]
    public void AMoverRegisteredAsAnObject_WalksThroughItsOwnShapes()
    {
        // The mover's own cylinder (radius 0.5, height 2) is registered at its start; it walks 1 m away in
        // 0.1 m frames. Tested against itself it would be stuck inside at once; skipped, it ends 1 m along.
        var world = Support.TestGeometry.FlatWorld();
        var mover = new MoverDescription(0x5000_000D, [new AcDream.Core.Physics.Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 0.6f, 0.8f,
            PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var start = Support.TestGeometry.At(100, 100, 0);
        world.Objects.Register(mover.ObjectId, new AcDream.Core.Physics.PhysicsSetup { CylSpheres = [new AcDream.Core.Physics.CylSphere(Vector3.Zero, 0.5f, 2f)] },
            start, 1f, PhysicsState.Static);
        var walker = new Support.Mover(world, mover, MoverState.OnFloor(start, 0f));
        walker.Walk(new Vector3(0, 0.1f, 0), 10);
        Assert.InRange(walker.Origin.Y, 101f - 0.001f, 101f + 0.001f);
        Assert.All(walker.Frames, f => Assert.False(f.Result.CollisionNormalValid));
    }
}
