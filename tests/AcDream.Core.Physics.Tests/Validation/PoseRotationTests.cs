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

    /// <summary>
    /// A move whose start rotation must be normalized (twice the length of a 10° tilt about X) begins its
    /// path at the normalized start and ends like the move from the unit tilt (to rounding); the caller's
    /// state is left as it was.
    /// </summary>
    [Fact]
    public void AStartRotationOfLengthTwo_MovesAsTheNormalizedStart()
    {
        var world = Support.TestGeometry.FlatWorld();
        var mover = MoverDescription.Player();
        var tilt = Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI / 18);
        var unit = MoverState.Airborne(Support.TestGeometry.At(100, 100, 3));
        unit.Position.Frame = new Frame(unit.Position.Frame.Origin, tilt);
        var doubled = unit;
        doubled.Position.Frame = new Frame(unit.Position.Frame.Origin, new Quaternion(2 * tilt.X, 2 * tilt.Y, 2 * tilt.Z, 2 * tilt.W));
        var target = unit.Position;
        target.Frame.Origin += new Vector3(0.05f, 0.1f, 0);

        var fromUnit = new PhysicsEngine(world).Resolve(mover, unit, target);
        var engine = new PhysicsEngine(world);
        var fromDoubled = engine.Resolve(mover, doubled, target);

        var begin = engine.Transition.SpherePath.BeginPos.Frame.Orientation;
        Assert.True(MathF.Abs(Quaternion.Dot(begin, tilt) - 1f) < 1e-5f, $"the path began from {begin}");

        Assert.True(Vector3.Distance(fromUnit.Position.Frame.Origin, fromDoubled.Position.Frame.Origin) < 1e-5f,
            $"from the unit tilt {fromUnit.Position.Frame.Origin}, from the doubled one {fromDoubled.Position.Frame.Origin}");
        Assert.True(MathF.Abs(Quaternion.Dot(fromDoubled.Position.Frame.Orientation, tilt) - 1f) < 1e-5f,
            $"result rotation {fromDoubled.Position.Frame.Orientation}");
        Assert.Equal(2 * tilt.W, doubled.Position.Frame.Orientation.W);
    }
}
