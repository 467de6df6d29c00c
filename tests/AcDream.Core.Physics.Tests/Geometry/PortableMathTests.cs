using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Tests.Geometry;

/// <summary>
/// The portable maths against the platform's (<see cref="Math"/>, <see cref="MathF"/>): at most 1 ulp apart
/// over random and edge inputs of each documented domain, and the IEEE special values exactly.
/// </summary>
public class PortableMathTests
{
    /// <summary>Distance in representable doubles (0 when equal, also for +0 and −0).</summary>
    internal static long Ulps(double a, double b)
    {
        if (a == b)
            return 0;
        static long Ordered(double v)
        {
            long bits = BitConverter.DoubleToInt64Bits(v);
            return bits < 0 ? long.MinValue - bits : bits;
        }
        return Math.Abs(Ordered(a) - Ordered(b));
    }

    internal static long Ulps(float a, float b)
    {
        if (a == b)
            return 0;
        static long Ordered(float v)
        {
            int bits = BitConverter.SingleToInt32Bits(v);
            return bits < 0 ? int.MinValue - (long)bits : bits;
        }
        return Math.Abs(Ordered(a) - Ordered(b));
    }

    /// <summary>The largest distance over the inputs, and the input where it occurs (for the failure message).</summary>
    private static (long Max, string Worst, double Differing) Worst<T>(IEnumerable<T> inputs, Func<T, long> ulps)
    {
        long max = 0, count = 0, differing = 0;
        string worst = "none";
        foreach (var x in inputs)
        {
            long u = ulps(x);
            count++;
            if (u != 0)
                differing++;
            if (u > max)
            {
                max = u;
                worst = x!.ToString()!;
            }
        }
        return (max, worst, (double)differing / count);
    }

    /// <summary>
    /// At most 1 ulp from the platform everywhere, and bit-equal to it on all but a small share of the inputs
    /// (the platform's libraries are within about half an ulp, so a share above it means a lost correction term).
    /// </summary>
    private static void AtMostOneUlp<T>(string what, IEnumerable<T> inputs, Func<T, long> ulps, double maxDiffering)
    {
        var (max, worst, differing) = Worst(inputs, ulps);
        Assert.True(max <= 1, $"{what}: {max} ulps from the platform at {worst}");
        Assert.True(differing <= maxDiffering, $"{what}: {differing:P3} of the inputs differ from the platform in the last bit (at most {maxDiffering:P3} expected)");
    }

    private static double Uniform(Random r, double lo, double hi) => lo + (hi - lo) * r.NextDouble();

    /// <summary>Random doubles with a random exponent: magnitudes spread evenly over 2^lo .. 2^hi.</summary>
    private static double LogUniform(Random r, int lo, int hi) => Math.Pow(2, Uniform(r, lo, hi)) * (1 + r.NextDouble());

    private static IEnumerable<double> Angles(int seed)
    {
        var r = new Random(seed);
        for (int i = 0; i < 200_000; i++) yield return Uniform(r, -2 * Math.PI, 2 * Math.PI);   // slerp, placement, spin
        for (int i = 0; i < 50_000; i++) yield return Uniform(r, -1000, 1000);
        for (int i = 0; i < 50_000; i++) yield return (r.Next(2) == 0 ? 1 : -1) * LogUniform(r, -40, 1000); // any magnitude
        for (int k = -2000; k <= 2000; k++)
        {
            // Next to multiples of π/2, where the reduction cancels most.
            double m = k * (Math.PI / 2);
            yield return m;
            yield return Math.BitIncrement(m);
            yield return Math.BitDecrement(m);
        }
        yield return Math.PI / 4;
        yield return Math.BitIncrement(Math.PI / 4);
        yield return 1.4901161193847656e-08;
        yield return 7.450580596923828e-09;
        yield return double.Epsilon;
        yield return double.MaxValue;
    }

    /// <summary>
    /// Huge arguments against correctly rounded values computed with 4000-bit arithmetic (mpmath), not the
    /// platform: the first is the double nearest a multiple of π/2 (Muller, Elementary Functions, 2016),
    /// where this machine's C library is 8 ulps off in cos while the portable reduction is exact.
    /// </summary>
    public static TheoryData<double, double, double> HugeArguments() => new()
    {
        { 5.319372648326541e+255, 1.0, -4.687165924254628e-19 },
        { 1e+22, -0.8522008497671888, 0.523214785395139 },
        { 1e+100, -0.3806377310050287, 0.9247242387519338 },
        { 1e+300, -0.8178819121159085, -0.5753861119575491 },
        { 1.7976931348623157e+308, 0.004961954789184062, -0.9999876894265599 },
        { 8.98846567431158e+307, 0.563127779850884, -0.826369834614148 },
        { 1e+16, 0.7796880066069788, -0.6261681981330862 },
        { 1.152921504606847e+18, -0.8306492176372546, -0.5567960822766417 },
        { 3.802951800684688e+30, 0.03734425598969816, -0.999302459991256 },
        { 123456789.0, 0.9901147518020355, 0.14025968153390964 },
        { 3294195.87584, -0.3514337331765099, -0.9362127595721079 },
    };

    [Theory]
    [MemberData(nameof(HugeArguments))]
    public void SinAndCos_OfHugeArguments_AreWithinOneUlpOfTheTrueValue(double x, double sin, double cos)
    {
        Assert.True(Ulps(PortableMath.Sin(x), sin) <= 1, $"sin({x:R}) = {PortableMath.Sin(x):R}, true {sin:R}");
        Assert.True(Ulps(PortableMath.Cos(x), cos) <= 1, $"cos({x:R}) = {PortableMath.Cos(x):R}, true {cos:R}");
        Assert.True(Ulps(PortableMath.Sin(-x), -sin) <= 1, $"sin(-{x:R})");
    }

    [Fact]
    public void Sin_IsWithinOneUlpOfThePlatform()
        => AtMostOneUlp("sin", Angles(1), x => Ulps(PortableMath.Sin(x), Math.Sin(x)), 0.04);

    [Fact]
    public void Cos_IsWithinOneUlpOfThePlatform()
        => AtMostOneUlp("cos", Angles(2), x => Ulps(PortableMath.Cos(x), Math.Cos(x)), 0.04);

    [Fact]
    public void SinAndCos_OfFloats_AreWithinOneUlpOfMathF()
    {
        var r = new Random(3);
        var inputs = Enumerable.Range(0, 200_000).Select(_ => (float)Uniform(r, -7, 7))
            .Concat(Enumerable.Range(0, 720).Select(d => d * (MathF.PI / 180f))).ToArray();
        AtMostOneUlp("sinf", inputs, x => Ulps(PortableMath.Sin(x), MathF.Sin(x)), 0.02);
        AtMostOneUlp("cosf", inputs, x => Ulps(PortableMath.Cos(x), MathF.Cos(x)), 0.02);
    }

    [Fact]
    public void SinAndCos_SpecialValues()
    {
        Assert.Equal(0.0, PortableMath.Sin(0.0));
        Assert.True(double.IsNegative(PortableMath.Sin(-0.0)), "sin(-0) is -0");
        Assert.False(double.IsNegative(PortableMath.Sin(0.0)), "sin(+0) is +0");
        Assert.Equal(1.0, PortableMath.Cos(0.0));
        Assert.Equal(1.0, PortableMath.Cos(-0.0));
        foreach (double bad in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity })
        {
            Assert.True(double.IsNaN(PortableMath.Sin(bad)), $"sin({bad})");
            Assert.True(double.IsNaN(PortableMath.Cos(bad)), $"cos({bad})");
        }
        // Exact values the platform gives too: the nearest doubles to π and π/2 have these sines and cosines.
        Assert.Equal(1.2246467991473532e-16, PortableMath.Sin(Math.PI));
        Assert.Equal(-1.0, PortableMath.Cos(Math.PI));
        Assert.Equal(1.0, PortableMath.Sin(Math.PI / 2));
        Assert.Equal(6.123233995736766e-17, PortableMath.Cos(Math.PI / 2));
    }

    private static IEnumerable<double> Cosines(int seed)
    {
        var r = new Random(seed);
        for (int i = 0; i < 200_000; i++) yield return Uniform(r, -1, 1);
        for (int i = 0; i < 50_000; i++) yield return 1 - LogUniform(r, -53, -1); // near 1: a slerp of close rotations
        for (int i = 0; i < 50_000; i++) yield return -1 + LogUniform(r, -53, -1);
        for (int i = 0; i < 20_000; i++) yield return (r.Next(2) == 0 ? 1 : -1) * LogUniform(r, -1074, -1);
        yield return 0.5;
        yield return -0.5;
        yield return Math.BitDecrement(1.0);
        yield return Math.BitIncrement(-1.0);
    }

    [Fact]
    public void Acos_IsWithinOneUlpOfThePlatform()
        => AtMostOneUlp("acos", Cosines(4), x => Ulps(PortableMath.Acos(x), Math.Acos(x)), 0.002);

    [Fact]
    public void Acos_SpecialValues()
    {
        Assert.Equal(0.0, PortableMath.Acos(1.0));
        Assert.False(double.IsNegative(PortableMath.Acos(1.0)), "acos(1) is +0");
        Assert.Equal(Math.PI, PortableMath.Acos(-1.0));
        Assert.Equal(Math.PI / 2, PortableMath.Acos(0.0));
        Assert.Equal(Math.PI / 2, PortableMath.Acos(-0.0));
        foreach (double bad in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity, Math.BitIncrement(1.0), -1.5 })
            Assert.True(double.IsNaN(PortableMath.Acos(bad)), $"acos({bad})");
    }

    private static IEnumerable<(double Y, double X)> Pairs(int seed)
    {
        var r = new Random(seed);
        double Sign() => r.Next(2) == 0 ? 1 : -1;
        for (int i = 0; i < 200_000; i++) yield return (Uniform(r, -10, 10), Uniform(r, -10, 10));
        for (int i = 0; i < 100_000; i++) yield return (Sign() * LogUniform(r, -500, 500), Sign() * LogUniform(r, -500, 500));
        for (int i = 0; i < 50_000; i++)
        {
            // Nearly along an axis or a diagonal, where the octant or the sixteenth changes.
            double x = Sign() * LogUniform(r, -20, 20);
            double k = r.Next(17) / 16.0;
            yield return (x * k * (1 + Uniform(r, -1e-9, 1e-9)), x);
            yield return (x, x * k * (1 + Uniform(r, -1e-9, 1e-9)));
        }
        for (int i = 0; i < 20_000; i++) yield return (Sign() * LogUniform(r, -1074, -1030), Sign() * LogUniform(r, -1074, -1030)); // subnormals
        for (int i = 0; i < 20_000; i++) yield return (Sign() * LogUniform(r, 1000, 1023), Sign() * LogUniform(r, 1000, 1023));
    }

    [Fact]
    public void Atan2_IsWithinOneUlpOfThePlatform()
        => AtMostOneUlp("atan2", Pairs(5), p => Ulps(PortableMath.Atan2(p.Y, p.X), Math.Atan2(p.Y, p.X)), 0.002);

    [Fact]
    public void Atan2_OfFloats_IsWithinOneUlpOfMathF()
    {
        var r = new Random(6);
        var inputs = Enumerable.Range(0, 200_000).Select(_ => ((float)Uniform(r, -5, 5), (float)Uniform(r, -5, 5))).ToArray();
        AtMostOneUlp("atan2f", inputs, p => Ulps(PortableMath.Atan2(p.Item1, p.Item2), MathF.Atan2(p.Item1, p.Item2)), 0.2);
    }

    [Fact]
    public void Atan2_SpecialValues_MatchThePlatformBitForBit()
    {
        double[] values = [0.0, -0.0, 1.0, -1.0, 3e-310, -3e-310, 1e308, -1e308, double.PositiveInfinity, double.NegativeInfinity, double.NaN];
        foreach (double y in values)
        foreach (double x in values)
        {
            double expected = Math.Atan2(y, x), actual = PortableMath.Atan2(y, x);
            bool same = BitConverter.DoubleToInt64Bits(expected) == BitConverter.DoubleToInt64Bits(actual)
                || (double.IsNaN(expected) && double.IsNaN(actual));
            Assert.True(same, $"atan2({y}, {x}): platform {expected:R}, portable {actual:R}");
        }
        // The four quadrants, by name.
        Assert.Equal(Math.PI / 4, PortableMath.Atan2(1.0, 1.0));
        Assert.Equal(3 * Math.PI / 4, PortableMath.Atan2(1.0, -1.0));
        Assert.Equal(-3 * Math.PI / 4, PortableMath.Atan2(-1.0, -1.0));
        Assert.Equal(-Math.PI / 4, PortableMath.Atan2(-1.0, 1.0));
        Assert.Equal(Math.PI, PortableMath.Atan2(0.0, -0.0));
        Assert.Equal(-Math.PI, PortableMath.Atan2(-0.0, -1.0));
    }

    private static IEnumerable<(double X, double Y)> Powers(int seed)
    {
        var r = new Random(seed);
        // The friction's domain: (1 − f)^quantum, f a float fraction, quantum a float up to 0.2 s.
        for (int i = 0; i < 200_000; i++) yield return (1.0 - r.NextSingle(), (double)(float)Uniform(r, 0, 0.2));
        for (int i = 0; i < 20_000; i++) yield return (1.0 - (1 - MathF.Pow(2, -r.Next(1, 24))), (double)(float)Uniform(r, 0, 0.2));
        // Any base, with |y·ln x| ≤ 32.
        for (int i = 0; i < 100_000; i++)
        {
            double x = LogUniform(r, -1074, 1023);
            double lnx = Math.Log(x);
            double y = lnx == 0 ? 1 : Uniform(r, -32, 32) / Math.Abs(lnx);
            yield return (x, y);
        }
        for (int i = 0; i < 50_000; i++) yield return (Uniform(r, 0.5, 2), Uniform(r, -20, 20));
    }

    [Fact]
    public void Pow_IsWithinOneUlpOfThePlatform()
        => AtMostOneUlp("pow", Powers(7), p => Ulps(PortableMath.Pow(p.X, p.Y), Math.Pow(p.X, p.Y)), 0.015);

    [Fact]
    public void Pow_SpecialValues_MatchThePlatform()
    {
        double[] bases = [0.0, -0.0, 0.5, 1.0, 2.0, 3e-310, 1e308, double.PositiveInfinity, double.NaN];
        double[] exponents = [0.0, -0.0, 0.1, 1.0, 2.0, -1.0, -0.5, 1e6, -1e6, double.PositiveInfinity, double.NegativeInfinity, double.NaN];
        foreach (double x in bases)
        foreach (double y in exponents)
        {
            if (double.IsNegative(x) && x == 0.0 && y == Math.Floor(y) && Math.Abs(y) % 2 == 1)
                continue; // (−0)^odd integer keeps the sign in Math.Pow; negative bases are outside the domain
            double expected = Math.Pow(x, y), actual = PortableMath.Pow(x, y);
            bool same = expected == actual || (double.IsNaN(expected) && double.IsNaN(actual));
            Assert.True(same, $"pow({x}, {y}): platform {expected:R}, portable {actual:R}");
        }
        Assert.True(double.IsNaN(PortableMath.Pow(-2.0, 0.5)), "negative base");
        Assert.Equal(1.0, PortableMath.Pow(-2.0, 0.0));
    }
}
