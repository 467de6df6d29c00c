using AcDream.Core.Physics;

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

public class LandDefsTests
{
    [Fact]
    public void BlockOffset_IsZeroWithinALandblock()
        => Assert.Equal(Vector3.Zero, LandDefs.BlockOffset(0xA9B40001, 0xA9B40105));

    [Fact]
    public void BlockOffset_IsOneBlockLengthPerLandblockStep()
    {
        // Landblock x is the high byte, y the low byte of the landblock id.
        Assert.Equal(new Vector3(192, 0, 0), LandDefs.BlockOffset(0xA9B40001, 0xAAB40001));
        Assert.Equal(new Vector3(0, -192, 0), LandDefs.BlockOffset(0xA9B40001, 0xA9B30001));
    }

    [Theory]
    [InlineData(0, 0, 0x00000001u)]
    [InlineData(0xA9 * 8 + 3, 0xB4 * 8 + 5, 0xA9B4001Eu)]   // cell (3,5): 3 * 8 + 5 + 1 = 30
    [InlineData(2039, 2039, 0xFEFE0040u)]
    [InlineData(-1, 0, 0u)]
    [InlineData(2040, 0, 0u)]
    public void LandCellAtGlobal_PacksLandblockAndCell(int gx, int gy, uint expected)
        => Assert.Equal(expected, LandDefs.LandCellAtGlobal(gx, gy));

    [Fact]
    public void LandCellAt_NumbersCellsColumnMajorFromOne()
    {
        Assert.Equal(0xA9B40001u, LandDefs.LandCellAt(0xA9B4, new Vector3(1, 1, 0)));
        Assert.Equal(0xA9B40002u, LandDefs.LandCellAt(0xA9B4, new Vector3(1, 25, 0)));
        Assert.Equal(0xA9B40009u, LandDefs.LandCellAt(0xA9B4, new Vector3(25, 1, 0)));
        Assert.Equal(0xA9B40040u, LandDefs.LandCellAt(0xA9B4, new Vector3(191.9f, 191.9f, 0)));
        Assert.Equal(0u, LandDefs.LandCellAt(0xA9B4, new Vector3(192f, 1, 0)));
    }
}

public class FrameTests
{
    [Fact]
    public void LocalToGlobal_AndBack_RoundTrips()
    {
        var frame = new Frame(new Vector3(10, 20, 3), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.7f));
        var p = new Vector3(1.5f, -2f, 0.25f);
        var back = frame.GlobalToLocal(frame.LocalToGlobal(p));
        Assert.True(Vector3.Distance(p, back) < 1e-5f);
    }

    [Fact]
    public void LocalToGlobal_RotatesThenTranslates()
    {
        var frame = new Frame(new Vector3(10, 0, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2));
        var g = frame.LocalToGlobal(Vector3.UnitX);
        Assert.True(Vector3.Distance(new Vector3(10, 1, 0), g) < 1e-5f);
    }
}
