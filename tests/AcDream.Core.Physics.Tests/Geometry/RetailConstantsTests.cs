namespace AcDream.Core.Physics.Tests.Geometry;

public class RetailConstantsTests
{
    [Fact]
    public void FloorZ_IsTheRetailOddAngle_NotCos45()
    {
        // Retail took cos of 48.381 (degrees) — an odd walkable limit that must be kept.
        Assert.Equal(PhysicsConstants.FloorZ, MathF.Cos(48.381f * MathF.PI / 180f), 5);
        Assert.NotEqual(PhysicsConstants.FloorZ, MathF.Cos(MathF.PI / 4f), 3);
    }

    [Fact]
    public void LandingZ_IsCos85Degrees()
        => Assert.Equal(PhysicsConstants.LandingZ, MathF.Cos(85f * MathF.PI / 180f), 6);

    [Theory]
    [InlineData(PhysicsState.HasPhysicsBsp, 0x10000u)]
    [InlineData(PhysicsState.Missile, 0x40u)]
    [InlineData(PhysicsState.Ethereal, 0x4u)]
    [InlineData(PhysicsState.ReportCollisions, 0x8u)]
    [InlineData(PhysicsState.EdgeSlide, 0x400000u)]
    public void PhysicsState_HasRetailValues(PhysicsState flag, uint expected) => Assert.Equal(expected, (uint)flag);

    [Theory]
    [InlineData(ObjectInfoState.Contact, 0x1u)]
    [InlineData(ObjectInfoState.OnWalkable, 0x2u)]
    [InlineData(ObjectInfoState.IsPlayer, 0x100u)]
    [InlineData(ObjectInfoState.EdgeSlide, 0x200u)]
    [InlineData(ObjectInfoState.IsPKLite, 0x1000u)]
    public void ObjectInfoState_HasRetailValues(ObjectInfoState flag, uint expected) => Assert.Equal(expected, (uint)flag);

    [Fact]
    public void TransitionState_HasRetailValues()
    {
        Assert.Equal(1, (int)TransitionState.OK);
        Assert.Equal(2, (int)TransitionState.Collided);
        Assert.Equal(3, (int)TransitionState.Adjusted);
        Assert.Equal(4, (int)TransitionState.Slid);
    }
}
