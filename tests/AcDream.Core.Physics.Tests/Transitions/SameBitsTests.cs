using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>The bit comparisons the remembered work relies on.</summary>
public class SameBitsTests
{
    [Fact]
    public void APositionAndASpherePair_AreThirtyTwoBytesWithoutPadding_SoTheirBitsCompareInOneGo()
    {
        Assert.Equal(32, System.Runtime.CompilerServices.Unsafe.SizeOf<Position>());
        Assert.Equal(32, System.Runtime.CompilerServices.Unsafe.SizeOf<AcDream.Core.Physics.Transitions.SpherePair>());
    }

    [Fact]
    public void Positions_AreTheSameBits_OnlyWhenEveryFieldIs()
    {
        var a = new Position(0xA9B40031, new Frame(new Vector3(1, 2, 3), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f)));
        Assert.True(Position.SameBits(a, a));
        var b = a; b.CellId++;
        Assert.False(Position.SameBits(a, b));
        b = a; b.Frame.Origin.Z = -0f + b.Frame.Origin.Z * 1.0000001f;
        Assert.False(Position.SameBits(a, b));
        b = a; b.Frame.Orientation = new Quaternion(a.Frame.Orientation.X, a.Frame.Orientation.Y, a.Frame.Orientation.Z, -a.Frame.Orientation.W);
        Assert.False(Position.SameBits(a, b));
        var zero = new Position(1, new Frame(new Vector3(0f, 0f, 0f)));
        var negativeZero = new Position(1, new Frame(new Vector3(-0f, 0f, 0f)));
        Assert.False(Position.SameBits(zero, negativeZero)); // equal numbers, different bits
    }
}
