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

    private static (uint, uint, uint) Bits(Vector3 v) =>
        (BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z));
}
