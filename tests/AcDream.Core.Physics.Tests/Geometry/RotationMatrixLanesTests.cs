namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// The widened matrix the sphere path transforms through (not retail; changes no result) gives, in every
/// lane, the very bits of retail's scalar evaluation in <see cref="RotationMatrix"/>, whose values the
/// frame-math tests and the ACE parity files pin: both the side-by-side form (AVX) and the one-lane-at-a-time
/// fallback that runs without it. Checked on rotations about every axis and skewed ones, with points whose
/// products and sums round (thirds, large and small coordinates, negative zero) and a z difference that
/// float cannot hold exactly (the unrounded z row of Frame::globaltolocal).
/// </summary>
public class RotationMatrixLanesTests
{
    private static readonly Vector3[] Points =
    [
        new(0f, 0f, 0f), new(1f / 3f, -2f / 3f, 0.475f), new(191.99998f, 0.0001f, -1.35f),
        new(-0f, 7.123457f, 1e-7f), new(-95.5f, 120.25f, 33.333332f), new(0.48f, 0.48f, 0.48f),
        new(3.1f, -0.2f, 1234.5677f),
    ];

    private static IEnumerable<Quaternion> Rotations()
    {
        yield return Quaternion.Identity;
        foreach (var axis in new[] { Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, Vector3.Normalize(new Vector3(1, 2, 3)), Vector3.Normalize(new Vector3(-0.3f, 0.9f, 0.1f)) })
            for (int degrees = -170; degrees <= 180; degrees += 37)
                yield return Quaternion.CreateFromAxisAngle(axis, degrees * MathF.PI / 180f);
    }

    private static uint[] Bits(Vector3 v) => [BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z)];

    // Every point in every lane: four consecutive points of the list (wrapping), each lane a different one.
    private static IEnumerable<PointLanes> Quadruples()
    {
        for (int i = 0; i < Points.Length; i++)
            yield return PointLanes.Of(Points[i], Points[(i + 1) % Points.Length], Points[(i + 3) % Points.Length], Points[(i + 5) % Points.Length]);
    }

    [Fact]
    public void PositionToGlobal_AndFrameToLocal_GiveTheScalarFormInEveryLane_OnBothPaths()
    {
        int checks = 0;
        foreach (var q in Rotations())
        {
            var scalar = new Frame(Vector3.Zero, q).Matrix;
            var lanes = new RotationMatrixLanes(scalar);
            foreach (var points in Quadruples())
                foreach (var origin in Points)
                {
                    var toGlobal = lanes.PositionToGlobal(points, origin);
                    var toGlobalByLane = lanes.PositionToGlobalByLane(points, origin);
                    var toLocal = lanes.FrameToLocal(points, origin);
                    var toLocalByLane = lanes.FrameToLocalByLane(points, origin);
                    for (int lane = 0; lane < 4; lane++)
                    {
                        var global = Bits(scalar.PositionToGlobal(points[lane], origin));
                        var local = Bits(scalar.FrameToLocal(points[lane], origin));
                        Assert.Equal(global, Bits(toGlobal[lane]));
                        Assert.Equal(global, Bits(toGlobalByLane[lane]));
                        Assert.Equal(local, Bits(toLocal[lane]));
                        Assert.Equal(local, Bits(toLocalByLane[lane]));
                        checks++;
                    }
                }
        }
        Assert.True(checks > 4000, $"{checks} checks");
    }

    /// <summary>
    /// The lanes take the float z difference of Frame::globaltolocal by a float subtraction instead of
    /// rounding the double difference: the same number, because double rounding of a sum of two floats
    /// through double is innocuous (53 ≥ 2·24 + 1 bits). Checked on differences with every exponent gap,
    /// random significands, exact halves of the float spacing and their neighbours, signed zeros and
    /// subnormals.
    /// </summary>
    [Fact]
    public void TheFloatDifference_IsTheDoubleDifferenceRoundedToFloat()
    {
        var random = new Random(25);
        var values = new List<float> { 0f, -0f, 1f, -1f, float.Epsilon, -float.Epsilon, 1e-40f, float.MaxValue / 2, 191.99998f, 1234.5677f };
        for (int i = 0; i < 4000; i++)
        {
            float big = BitConverter.Int32BitsToSingle(random.Next(0x0080_0000, 0x4F00_0000)) * (random.Next(2) == 0 ? 1 : -1);
            int gap = random.Next(0, 64);
            float small = MathF.ScaleB(1f + random.NextSingle(), (int)MathF.ILogB(big) - gap) * (random.Next(2) == 0 ? 1 : -1);
            values.Add(big);
            values.Add(small);
            // Half the spacing of floats at `big`, and its neighbours: the tie cases of the rounding.
            float half = MathF.ScaleB(1f, (int)MathF.ILogB(big) - 24);
            values.Add(half);
            values.Add(MathF.BitIncrement(half));
            values.Add(MathF.BitDecrement(half));
        }
        int checks = 0;
        for (int i = 0; i < values.Count; i++)
            for (int j = Math.Max(0, i - 6); j < Math.Min(values.Count, i + 6); j++)
            {
                float a = values[i], b = values[j];
                float direct = a - b;
                float throughDouble = (float)((double)a - b);
                Assert.Equal(BitConverter.SingleToUInt32Bits(throughDouble), BitConverter.SingleToUInt32Bits(direct));
                checks++;
            }
        Assert.True(checks > 100000, $"{checks} checks");
    }
}
