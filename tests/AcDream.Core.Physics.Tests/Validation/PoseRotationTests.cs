using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Tests.Validation;

/// <summary>
/// Guard.Pose answers most rotations with a quick float test of the squared length; it must keep a rotation
/// exactly when retail's test (Frame::IsValid: the squared length summed in double, within 5 × EPSILON of
/// one) accepts it, and normalize it otherwise, right up to that boundary.
/// </summary>
public class PoseRotationTests
{
    [Fact]
    public void ARotationIsKeptExactlyWhenRetailsTestAcceptsIt()
    {
        var rng = new Random(77);
        int kept = 0, normalized = 0;
        for (int i = 0; i < 200_000; i++)
        {
            var axis = Vector3.Normalize(new Vector3(rng.NextSingle() - 0.5f, rng.NextSingle() - 0.5f, rng.NextSingle() - 0.5f + 1e-3f));
            var unit = Quaternion.CreateFromAxisAngle(axis, rng.NextSingle() * 6.2f);
            // Squared lengths spread across retail's bound, 1 ± 0.001, and a little beyond.
            float length = MathF.Sqrt(1f + (rng.NextSingle() * 2f - 1f) * 0.0012f);
            var q = new Quaternion(unit.X * length, unit.Y * length, unit.Z * length, unit.W * length);
            var frame = new Frame(new Vector3(10, 20, 30), q);
            Guard.Pose(ref frame, "p");
            bool unchanged = frame.Orientation.Equals(q);
            bool retail = Frame.IsValidRotation(q);
            Assert.True(unchanged == retail, $"{q:R}: kept {unchanged}, retail's test says {retail}");
            if (retail) kept++; else normalized++;
        }
        Assert.True(kept > 10_000 && normalized > 10_000, $"both sides of the bound are sampled: {kept} kept, {normalized} normalized");
    }
}
