using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

public class UnitMemoTests
{
    /// <summary>
    /// The memo answers exactly as a fresh normalization would, bit for bit, through repeats, a vector that
    /// differs only in the sign of a zero, one too short to normalize (left unchanged, reported short), and
    /// a return to an earlier vector.
    /// </summary>
    [Fact]
    public void AnswersAsAFreshNormalization_ThroughRepeatsAndChanges()
    {
        var inputs = new[]
        {
            new Vector3(0.3f, -4f, 0f), new Vector3(0.3f, -4f, 0f), new Vector3(0.3f, -4f, -0f),
            new Vector3(0.0001f, 0f, 0f), new Vector3(0.0001f, 0f, 0f), new Vector3(0.3f, -4f, 0f),
            new Vector3(1f, 0f, 0f), new Vector3(0.70710677f, -0.70710677f, 0f), new Vector3(0.70710677f, -0.70710677f, 0f),
        };
        var memo = new UnitMemo();
        foreach (var input in inputs)
        {
            var expected = input;
            bool expectedShort = VectorMath.NormalizeCheckSmall(ref expected);
            var actual = input;
            bool actualShort = memo.NormalizeCheckSmall(ref actual);
            Assert.True(expectedShort == actualShort, $"{input:R}: short {actualShort}, fresh {expectedShort}");
            Assert.True(Bits(expected) == Bits(actual), $"{input:R}: {actual:R}, fresh {expected:R}");
        }
    }

    /// <summary>
    /// The memo's key test compares bits, lane by lane, all three lanes: a sign of zero or a NaN payload in
    /// any one lane makes the vectors differ; the very same bits (a NaN too) are the same.
    /// </summary>
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(2)]
    public void SameBits_SeesEveryLane(int lane)
    {
        var a = new Vector3(0.25f, -3f, 7f);
        var negativeZero = Vector3.Zero;
        negativeZero[lane] = -0f;
        var otherNaN = a;
        otherNaN[lane] = BitConverter.UInt32BitsToSingle(0x7FC00001);
        var nextUp = a;
        nextUp[lane] = MathF.BitIncrement(a[lane]);
        Assert.False(VectorMath.SameBits(Vector3.Zero, negativeZero));
        Assert.False(VectorMath.SameBits(a, nextUp));
        Assert.False(VectorMath.SameBits(a, otherNaN));
        var canonicalNaN = a;
        canonicalNaN[lane] = float.NaN;
        Assert.False(VectorMath.SameBits(canonicalNaN, otherNaN));
        Assert.True(VectorMath.SameBits(otherNaN, otherNaN));
        Assert.True(VectorMath.SameBits(a, new Vector3(0.25f, -3f, 7f)));
    }

    private static (uint, uint, uint) Bits(Vector3 v) =>
        (BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z));
}
