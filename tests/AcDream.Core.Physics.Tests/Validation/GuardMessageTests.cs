using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Tests.Validation;

/// <summary>
/// The per-frame checks answer the common case with one test and build their messages out of line; a bad
/// value must still get the message that says what is wrong with it.
/// </summary>
public class GuardMessageTests
{
    [Theory]
    [InlineData(float.NaN, 0f, 0f, "must be finite")]
    [InlineData(float.PositiveInfinity, 0f, 0f, "must be finite")]
    [InlineData(200_000f, 0f, 0f, "must be finite")]
    [InlineData(0f, 0f, 2f, "must be a unit vector")]
    [InlineData(0f, 0f, 0f, "must be a unit vector")]
    public void UnitNormal_SaysWhetherTheNormalIsNotFiniteOrNotUnit(float x, float y, float z, string expected)
    {
        var e = Assert.Throws<ArgumentException>(() => Guard.UnitNormal(new Vector3(x, y, z), "plane", ".normal"));
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
        Assert.StartsWith("plane.normal: ", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void UnitNormal_AcceptsAUnitVector() => Guard.UnitNormal(Vector3.Normalize(new Vector3(1, 2, 3)), "plane");

    [Theory]
    [InlineData(float.NaN, 0f, 0f, 1f, "quaternion must be finite")]
    [InlineData(0f, float.PositiveInfinity, 0f, 1f, "quaternion must be finite")]
    [InlineData(0f, 0f, 0f, 0f, "quaternion has zero length")]
    [InlineData(0f, 0f, 3e19f, 3e19f, "too long to normalize")]
    public void Pose_SaysWhatIsWrongWithTheRotation(float x, float y, float z, float w, string expected)
    {
        var frame = new Frame(Vector3.Zero, new Quaternion(x, y, z, w));
        var e = Assert.Throws<ArgumentException>(() => Guard.Pose(ref frame, "target"));
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
        Assert.StartsWith("target.orientation: ", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Pose_NormalizesALongRotation_AndKeepsAnAcceptedOneBitForBit()
    {
        var frame = new Frame(Vector3.Zero, new Quaternion(0, 0, 0, 2));
        Guard.Pose(ref frame, "target");
        Assert.Equal(Quaternion.Identity, frame.Orientation);

        // Within retail's Frame::IsValid tolerance: used as given, not normalized.
        var nearlyUnit = new Quaternion(0, 0, 0, 1.0002f);
        frame = new Frame(Vector3.Zero, nearlyUnit);
        Guard.Pose(ref frame, "target");
        Assert.Equal(nearlyUnit, frame.Orientation);
    }

    [Theory]
    // Squared lengths just inside and just outside retail's 5 × EPSILON (0.001) of one, beyond the quick test's 0.0009.
    [InlineData(1.000475f, false)]  // 1.00095
    [InlineData(0.999525f, false)]  // 0.99905
    [InlineData(1.00055f, true)]    // 1.0011
    [InlineData(0.99945f, true)]    // 0.9989
    public void Pose_FollowsFrameIsValid_AtItsEdge(float w, bool normalized)
    {
        var q = new Quaternion(0, 0, 0, w);
        var frame = new Frame(Vector3.Zero, q);
        Guard.Pose(ref frame, "target");
        Assert.Equal(normalized ? Quaternion.Identity : q, frame.Orientation);
        Assert.Equal(normalized ? Quaternion.Identity : q, Guard.Rotation(q, "target"));
    }
    [Theory]
    // Each component on its own (the check tests the three lanes at once): NaN, ±∞, just beyond ±100 km.
    [InlineData(0, float.NaN)]
    [InlineData(1, float.NaN)]
    [InlineData(2, float.NaN)]
    [InlineData(0, float.NegativeInfinity)]
    [InlineData(1, float.PositiveInfinity)]
    [InlineData(2, float.NegativeInfinity)]
    [InlineData(0, 100_000.01f)]
    [InlineData(1, -100_000.01f)]
    [InlineData(2, 100_000.01f)]
    public void Finite_RefusesABadValueInAnyComponent(int component, float bad)
    {
        var v = new Vector3(1, -2, 3);
        v[component] = bad;
        var e = Assert.Throws<ArgumentException>(() => Guard.Finite(v, "state.position", ".origin"));
        Assert.StartsWith("state.position.origin: ", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Finite_AcceptsEveryComponentAtTheLimit()
    {
        Guard.Finite(new Vector3(InputLimits.MaxCoordinate, -InputLimits.MaxCoordinate, InputLimits.MaxCoordinate), "v");
        Guard.Finite(new Vector3(-0f, float.Epsilon, -InputLimits.MaxCoordinate), "v");
    }
}
