using AcDream.Core.Physics.Transitions;

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
