using System;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Geometry;

/// <summary>
/// Sine, cosine, arc cosine, arc tangent and power written with IEEE double addition, subtraction,
/// multiplication, division and square root only, so that they give the same bits on every architecture.
/// <see cref="Math.Sin(double)"/> and its siblings go to the platform's C library, whose results differ in
/// the last bit between x64 and ARM64 for some inputs (docs/robustness.md, "Determinism").
/// <para>
/// Method: argument reduction to a small interval, then a truncated Taylor series evaluated by Horner's rule,
/// with the leading terms and the reduction carried as a double-double (an unevaluated sum hi + lo) so that
/// only the final addition rounds noticeably. The exact building blocks are Knuth's TwoSum, Dekker's
/// FastTwoSum and Dekker's TwoProduct with Veltkamp's splitting (Dekker 1971; Muller et al., Handbook of
/// Floating-Point Arithmetic, ch. 4). The constants (π/2, 2/π, ln 2, atan(k/16)) were computed to 2000 bits
/// and rounded; the series coefficients are ±1/n! and ±1/(2n+1).
/// </para>
/// <para>
/// The JIT never contracts a * b + c into a fused multiply-add, so every line below rounds exactly as written.
/// Error bounds: at most 1 ulp from <see cref="Math"/> on the domains each function documents (asserted by
/// <c>PortableMathTests</c>); measured against 300-bit values, sin 0.73, cos 0.75, acos 0.50, atan2 0.50
/// and pow 0.59 ulp at most (docs/robustness.md, "Determinism").
/// </para>
/// </summary>
internal static class PortableMath
{
    private const double PiOver2Hi = 1.5707963267948966, PiOver2Lo = 6.123233995736766e-17;
    private const double PiHi = 3.141592653589793, PiLo = 1.2246467991473532e-16;

    // π/2 = Part1 + Part2 + Part3 + Part4 (the first three of 33 significant bits each, exact).
    private const double PiOver2Part1 = 1.5707963267341256, PiOver2Part2 = 6.077100506303966e-11;
    private const double PiOver2Part3 = 2.0222662487111665e-21, PiOver2Part4 = 8.4784276603689e-32;

    // ln 2 split so that k * Ln2Hi is exact for |k| < 2^11 (Ln2Hi has 42 significant bits).
    private const double Ln2Hi = 0.6931471805598903, Ln2Lo = 5.497923018708371e-14;
    private const double InvLn2 = 1.4426950408889634;

    /// <summary>2/π in binary, 64 bits a word, from its first fractional bit (weight 2^-1): 1280 bits, enough for any double.</summary>
    private static ReadOnlySpan<ulong> TwoOverPiBits =>
    [
        0xA2F9836E4E441529, 0xFC2757D1F534DDC0, 0xDB6295993C439041, 0xFE5163ABDEBBC561, 0xB7246E3A424DD2E0,
        0x06492EEA09D1921C, 0xFE1DEB1CB129A73E, 0xE88235F52EBB4484, 0xE99C7026B45F7E41, 0x3991D639835339F4,
        0x9C845F8BBDF9283B, 0x1FF897FFDE05980F, 0xEF2F118B5A0A6D1F, 0x6D367ECF27CB09B7, 0x4F463F669E5FEA2D,
        0x7527BAC7EBE5F17B, 0x3D0739F78A5292EA, 0x6BFB5FB11F8D5D08, 0x56033046FC7B6BAB, 0xF0CFBC209AF4361D,
    ];

    /// <summary>atan(k/16) for k = 0..16, as hi + lo.</summary>
    private static ReadOnlySpan<double> AtanHi =>
    [
        0.0, 0.06241880999595735, 0.12435499454676144, 0.18534794999569476, 0.24497866312686414,
        0.3028848683749714, 0.35877067027057225, 0.4124104415973873, 0.4636476090008061, 0.5123894603107377,
        0.5585993153435624, 0.6022873461349642, 0.6435011087932844, 0.6823165548747481, 0.7188299996216245,
        0.7531512809621944, 0.7853981633974483,
    ];

    private static ReadOnlySpan<double> AtanLo =>
    [
        0.0, -1.5490756308295046e-18, -3.1253241424539383e-18, 4.180692268843079e-18, 1.0698755618734451e-17,
        -1.1010827903001369e-17, -2.4623815582638635e-17, -1.587652227770689e-17, 2.2698777452961687e-17,
        -2.5462781472855804e-17, -5.4556305485916264e-18, 2.950430737228402e-17, 1.5834785051444286e-17,
        6.943223671560008e-18, -2.1478388444456983e-17, -2.4256934659182068e-17, 3.061616997868383e-17,
    ];

    // ---- exact building blocks ----------------------------------------------------------------------------

    /// <summary>Knuth's TwoSum: s + e == a + b exactly, s the rounded sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double TwoSum(double a, double b, out double e)
    {
        double s = a + b;
        double bb = s - a;
        e = (a - (s - bb)) + (b - bb);
        return s;
    }

    /// <summary>Dekker's FastTwoSum (|a| ≥ |b| or a == 0): s + e == a + b exactly.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double FastTwoSum(double a, double b, out double e)
    {
        double s = a + b;
        e = b - (s - a);
        return s;
    }

    /// <summary>Dekker's TwoProduct with Veltkamp's split: p + e == a * b exactly (|a|, |b| below 2^995, no underflow).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double TwoProduct(double a, double b, out double e)
    {
        double p = a * b;
        Split(a, out double ah, out double al);
        Split(b, out double bh, out double bl);
        e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        return p;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Split(double a, out double hi, out double lo)
    {
        double c = 134217729.0 * a; // 2^27 + 1
        hi = c - (c - a);
        lo = a - hi;
    }

    // ---- sine and cosine ------------------------------------------------------------------------------------

    /// <summary>sin x for every double: ≤ 1 ulp from the platform for any finite x; NaN for NaN and ±∞; sin(−0) = −0.</summary>
    public static double Sin(double x)
    {
        if (!double.IsFinite(x))
            return double.NaN;
        double a = Math.Abs(x);
        if (a < 1.4901161193847656e-08) // 2^-26
            return x; // x³/6 is below half an ulp of x
        int n = Reduce(a, out double rh, out double rl);
        double s = (n & 1) == 0 ? SinKernel(rh, rl) : CosKernel(rh, rl);
        if ((n & 2) != 0)
            s = -s;
        return x < 0 ? -s : s;
    }

    /// <summary>cos x for every double: ≤ 1 ulp from the platform for any finite x; NaN for NaN and ±∞.</summary>
    public static double Cos(double x)
    {
        if (!double.IsFinite(x))
            return double.NaN;
        double a = Math.Abs(x);
        if (a < 7.450580596923828e-09) // 2^-27
            return 1.0; // x²/2 is below half an ulp of 1
        int n = Reduce(a, out double rh, out double rl);
        double c = (n & 1) == 0 ? CosKernel(rh, rl) : SinKernel(rh, rl);
        return ((n + 1) & 2) != 0 ? -c : c;
    }

    /// <summary>sin x of a float, through the double routine (one more rounding, to float).</summary>
    public static float Sin(float x) => (float)Sin((double)x);

    /// <summary>cos x of a float, through the double routine (one more rounding, to float).</summary>
    public static float Cos(float x) => (float)Cos((double)x);

    /// <summary>
    /// Writes a (≥ 0, finite) as n·π/2 + r, |r| ≤ π/4, r = rh + rl, returning n mod 4. Below 64 (every
    /// angle the library turns by) it is Cody–Waite's reduction; from 64 on the Payne–Hanek reduction:
    /// a = m·2^q with m a 53-bit integer, so a·2/π mod 4 needs only the 192 bits of 2/π from weight
    /// 2^(1−q) on; the product m × those bits, modulo 2^192, is 2 bits of quadrant and 190 bits of
    /// fraction, exact but for the bits of 2/π left out (below 2^-136 of a quadrant).
    /// </summary>
    private static int Reduce(double a, out double rh, out double rl)
    {
        if (a <= 0.78539816339744828)
        {
            rh = a;
            rl = 0.0;
            return 0;
        }
        if (a < 64.0)
        {
            // π/2 in four parts, the first three of 33 bits, so k·part is exact for k ≤ 41; a − k·Part1 is exact
            // (both are multiples of ulp(a)), the next subtraction is a TwoSum, and the rounding of the rest is
            // below 2^-60 of the smallest remainder a double under 64 leaves (about 2^-52).
            double k = Math.Round(a * 0.6366197723675814);
            double d = a - k * PiOver2Part1;
            double hi = TwoSum(d, -(k * PiOver2Part2), out double e);
            rh = FastTwoSum(hi, e - k * PiOver2Part3 - k * PiOver2Part4, out rl);
            return (int)k & 3;
        }
        long bits = BitConverter.DoubleToInt64Bits(a);
        int exponent = (int)(bits >> 52) & 0x7FF; // a > π/4, so normal
        ulong m = ((ulong)bits & 0xFFFFFFFFFFFFFUL) | (1UL << 52);
        int q = exponent - 1075; // a = m · 2^q
        int first = q - 1;       // the first bit of 2/π that matters mod 4 (weight 2^-first)
        ulong w0 = TwoOverPiWord(first), w1 = TwoOverPiWord(first + 64), w2 = TwoOverPiWord(first + 128);
        UInt128 t = (UInt128)m * w2;
        ulong p2 = (ulong)t;
        t = (UInt128)m * w1 + (t >> 64);
        ulong p1 = (ulong)t;
        ulong p0 = (ulong)((UInt128)m * w0 + (t >> 64));
        // p0:p1:p2 = quadrant (2 bits) . fraction (190 bits); keep 128 bits of the fraction.
        int n = (int)(p0 >> 62);
        UInt128 f = ((UInt128)((p0 << 2) | (p1 >> 62)) << 64) | ((p1 << 2) | (p2 >> 62));
        bool negative = false;
        if ((f >> 127) != 0)
        {
            // Fraction ≥ 1/2: the nearer multiple is the next one, r is negative.
            n++;
            f = (UInt128)0 - f;
            negative = true;
        }
        // f · 2^-128 as hi + lo (53 bits each), then times π/2.
        int shift = (int)UInt128.LeadingZeroCount(f);
        if (shift == 128)
        {
            rh = 0.0;
            rl = 0.0;
            return n & 3;
        }
        f <<= shift;
        double scale = Pow2(-128 - shift);
        double fh = (double)(ulong)(f >> 75) * Pow2(75) * scale;
        double fl = (double)((ulong)(f >> 22) & ((1UL << 53) - 1)) * Pow2(22) * scale;
        double ph = TwoProduct(fh, PiOver2Hi, out double pe);
        pe += fh * PiOver2Lo + fl * PiOver2Hi;
        rh = FastTwoSum(ph, pe, out rl);
        if (negative)
        {
            rh = -rh;
            rl = -rl;
        }
        return n & 3;
    }

    /// <summary>64 bits of 2/π starting at bit <paramref name="first"/> (weight 2^-first); bits before the first fractional one are 0.</summary>
    private static ulong TwoOverPiWord(int first)
    {
        int p = first - 1;
        if (p < 0)
            return p <= -64 ? 0UL : TwoOverPiWord(1) >> -p;
        var words = TwoOverPiBits;
        int i = p >> 6, o = p & 63;
        ulong hi = words[i] << o;
        return o == 0 ? hi : hi | (words[i + 1] >> (64 - o));
    }

    /// <summary>2^e for −1022 ≤ e ≤ 1023, exactly.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Pow2(int e) => BitConverter.Int64BitsToDouble((long)(e + 1023) << 52);

    /// <summary>sin(rh + rl), |rh| ≤ π/4, |rl| ≤ ulp(rh): the Taylor series through r^17 (truncation below 2^-62 relative).</summary>
    private static double SinKernel(double rh, double rl)
    {
        double z = rh * rh;
        double p = -0.16666666666666666 + z * (0.008333333333333333 + z * (-0.0001984126984126984 + z * (2.7557319223985893e-06
            + z * (-2.505210838544172e-08 + z * (1.6059043836821613e-10 + z * (-7.647163731819816e-13 + z * 2.8114572543455206e-15))))));
        // sin(rh + rl) = sin rh + rl·cos rh; cos rh ≈ 1 − z/2 is enough for rl.
        return rh + (rh * z * p + (rl - rl * z * 0.5));
    }

    /// <summary>cos(rh + rl), |rh| ≤ π/4: the Taylor series through r^18, 1 − z/2 split off exactly.</summary>
    private static double CosKernel(double rh, double rl)
    {
        double z = rh * rh;
        double p = 0.041666666666666664 + z * (-0.001388888888888889 + z * (2.48015873015873e-05 + z * (-2.755731922398589e-07
            + z * (2.08767569878681e-09 + z * (-1.1470745597729725e-11 + z * (4.779477332387385e-14 + z * -1.5619206968586225e-16))))));
        double half = 0.5 * z;
        double w = 1.0 - half;
        // (1 − w) − half is the rounding error of w (1 − w is exact: w is within a factor 2 of 1).
        return w + (((1.0 - w) - half) + (z * z * p - rh * rl));
    }

    // ---- arc tangent and arc cosine -------------------------------------------------------------------------

    /// <summary>
    /// atan2(y, x) with the IEEE special cases of <see cref="Math.Atan2"/> (signed zeros, infinities, NaN);
    /// ≤ 1 ulp from the platform where the ratio of the smaller to the larger magnitude is at least 2^-1000.
    /// </summary>
    public static double Atan2(double y, double x)
    {
        if (double.IsNaN(x) || double.IsNaN(y))
            return double.NaN;
        double ax = Math.Abs(x), ay = Math.Abs(y);
        bool westward = double.IsNegative(x);
        double h, l;
        if (ay == 0.0)
        {
            h = westward ? PiHi : 0.0;
            l = 0.0;
        }
        else if (double.IsInfinity(ax) && double.IsInfinity(ay))
        {
            h = westward ? 2.356194490192345 : 0.7853981633974483;
            l = 0.0;
        }
        else if (ax == 0.0 || double.IsInfinity(ay))
        {
            h = PiOver2Hi;
            l = 0.0;
        }
        else
        {
            bool steep = ay > ax;
            double big = steep ? ay : ax, small = steep ? ax : ay;
            double q = small / big;
            if (q < 9.313225746154785e-10) // 2^-30
            {
                h = q; // atan q rounds to q
                l = 0.0;
            }
            else
            {
                // Scale both so the larger is in [1, 2) (exact: the smaller stays above 2^-31), then q as hi + lo.
                // (A subnormal larger magnitude reads as 2^-1023 and lands below 2, which is as good.)
                int e = (int)((BitConverter.DoubleToInt64Bits(big) >> 52) & 0x7FF) - 1023;
                double s1 = Pow2(-e / 2), s2 = Pow2(-e - -e / 2);
                big = big * s1 * s2;
                small = small * s1 * s2;
                double p = TwoProduct(q, big, out double pe);
                double ql = ((small - p) - pe) / big;
                h = AtanUnit(q, ql, out l);
            }
            if (steep)
                h = Subtract(PiOver2Hi, PiOver2Lo, h, l, out l);
            if (westward)
                h = Subtract(PiHi, PiLo, h, l, out l);
        }
        double r = h + l;
        return double.IsNegative(y) ? -r : r;
    }

    /// <summary>atan2 of floats, through the double routine (one more rounding, to float).</summary>
    public static float Atan2(float y, float x) => (float)Atan2((double)y, (double)x);

    /// <summary>acos x for −1 ≤ x ≤ 1 (NaN outside and for NaN): 2·atan2(√(1 − x), √(1 + x)), each root a double-double; ≤ 1 ulp from the platform.</summary>
    public static double Acos(double x)
    {
        if (!(Math.Abs(x) <= 1.0))
            return double.NaN;
        double dh = TwoSum(1.0, -x, out double dl);
        double sh = SqrtDD(dh, dl, out double sl);
        double uh = TwoSum(1.0, x, out double ul);
        double ch = SqrtDD(uh, ul, out double cl);
        double h, l;
        if (sh <= ch)
        {
            double q = Divide(sh, sl, ch, cl, out double ql);
            h = AtanUnit(q, ql, out l);
        }
        else
        {
            double q = Divide(ch, cl, sh, sl, out double ql);
            h = AtanUnit(q, ql, out l);
            h = Subtract(PiOver2Hi, PiOver2Lo, h, l, out l);
        }
        return 2.0 * (h + l);
    }

    /// <summary>√(ah + al) as hi + lo (ah ≥ 0, small enough for <see cref="TwoProduct"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double SqrtDD(double ah, double al, out double lo)
    {
        double s = Math.Sqrt(ah);
        if (s == 0.0)
        {
            lo = 0.0;
            return s;
        }
        double p = TwoProduct(s, s, out double pe);
        lo = (((ah - p) - pe) + al) / (2.0 * s);
        return s;
    }

    /// <summary>(nh + nl) / (dh + dl) as hi + lo (0 ≤ n ≤ d, d &gt; 0, moderate magnitudes).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Divide(double nh, double nl, double dh, double dl, out double lo)
    {
        double q = nh / dh;
        double p = TwoProduct(q, dh, out double pe);
        lo = (((nh - p) - pe) + nl - q * dl) / dh;
        return q;
    }

    /// <summary>(ah + al) − (bh + bl) as hi + lo.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Subtract(double ah, double al, double bh, double bl, out double lo)
    {
        double s = TwoSum(ah, -bh, out double e);
        return FastTwoSum(s, e + (al - bl), out lo);
    }

    /// <summary>
    /// atan(th + tl) for 0 ≤ t ≤ 1 as hi + lo: t = c + (t − c)/(1 + t·c) with c = k/16 the nearest
    /// sixteenth, so atan t = atan c + atan u with |u| ≤ 1/32; atan u by its series through u^13.
    /// </summary>
    private static double AtanUnit(double th, double tl, out double lo)
    {
        int k = (int)(th * 16.0 + 0.5);
        double uh, ul;
        if (k == 0)
        {
            uh = th;
            ul = tl;
        }
        else
        {
            double c = k * 0.0625;
            double nh = th - c; // exact: t is within a factor 2 of c
            double p = TwoProduct(th, c, out double pe);
            double dh = TwoSum(1.0, p, out double de);
            de += pe + tl * c;
            uh = Divide(nh, tl, dh, de, out ul);
        }
        double z = uh * uh;
        double poly = -0.3333333333333333 + z * (0.2 + z * (-0.14285714285714285 + z * (0.1111111111111111
            + z * (-0.09090909090909091 + z * 0.07692307692307693))));
        double s = TwoSum(AtanHi[k], uh, out double e);
        return FastTwoSum(s, e + (AtanLo[k] + ul + uh * z * poly), out lo);
    }

    // ---- power ----------------------------------------------------------------------------------------------

    /// <summary>
    /// x^y for x ≥ 0 (NaN for a negative or NaN x unless y is 0): exp(y·ln x) with ln x and the product as
    /// double-doubles. ≤ 1 ulp from the platform while |y·ln x| ≤ 32; the error grows to |y·ln x|/128 ulp
    /// towards the overflow bound. Special values as <see cref="Math.Pow"/> for x ≥ 0.
    /// </summary>
    public static double Pow(double x, double y)
    {
        if (y == 0.0 || x == 1.0)
            return 1.0;
        if (double.IsNaN(x) || double.IsNaN(y) || x < 0.0)
            return double.NaN;
        if (x == 0.0)
            return y > 0.0 ? 0.0 : double.PositiveInfinity;
        if (double.IsPositiveInfinity(x))
            return y > 0.0 ? double.PositiveInfinity : 0.0;
        if (double.IsInfinity(y))
            return (x < 1.0) == (y > 0.0) ? 0.0 : double.PositiveInfinity;
        double lh = LogDD(x, out double ll);
        double ph = TwoProduct(y, lh, out double pe);
        ph = FastTwoSum(ph, pe + y * ll, out double pl);
        if (ph > 709.8)
            return double.PositiveInfinity;
        if (ph < -745.2)
            return 0.0;
        return ExpDD(ph, pl);
    }

    /// <summary>
    /// ln x (0 &lt; x &lt; ∞) as hi + lo: x = 2^k·m with √½ ≤ m ≤ √2, ln m = 2·atanh s, s = (m − 1)/(m + 1),
    /// |s| ≤ 0.172, by its series through s^25. Relative error about 2^-60.
    /// </summary>
    private static double LogDD(double x, out double lo)
    {
        int k = 0;
        if (x < 2.2250738585072014e-308) // 2^-1022
        {
            x *= 18014398509481984.0; // subnormal: times 2^54, exactly
            k = -54;
        }
        long bits = BitConverter.DoubleToInt64Bits(x);
        k += (int)(bits >> 52) - 1023;
        double m = BitConverter.Int64BitsToDouble((bits & 0xFFFFFFFFFFFFFL) | 0x3FF0000000000000L);
        if (m > 1.4142135623730951)
        {
            m *= 0.5;
            k++;
        }
        double f = m - 1.0; // exact
        double dh = TwoSum(m, 1.0, out double dl);
        double sh = Divide(f, 0.0, dh, dl, out double sl);
        double w = sh * sh;
        double poly = 0.3333333333333333 + w * (0.2 + w * (0.14285714285714285 + w * (0.1111111111111111 + w * (0.09090909090909091
            + w * (0.07692307692307693 + w * (0.06666666666666667 + w * (0.058823529411764705 + w * (0.05263157894736842
            + w * (0.047619047619047616 + w * (0.043478260869565216 + w * 0.04))))))))));
        double h = TwoSum(k * Ln2Hi, 2.0 * sh, out double e);
        e += k * Ln2Lo + 2.0 * sl + 2.0 * sh * w * poly;
        return FastTwoSum(h, e, out lo);
    }

    /// <summary>
    /// exp(xh + xl) for −745.2 ≤ xh ≤ 709.8: x = n·ln 2 + r, |r| ≤ 0.347, exp r by its series through r^14,
    /// then scaled by 2^n exactly (one rounding in the subnormal range).
    /// </summary>
    private static double ExpDD(double xh, double xl)
    {
        double n = Math.Round(xh * InvLn2);
        double r = xh - n * Ln2Hi; // exact: n·Ln2Hi is exact and within a factor 2 of xh (or n = 0)
        double rh = TwoSum(r, xl - n * Ln2Lo, out double rl);
        double poly = 0.5 + rh * (0.16666666666666666 + rh * (0.041666666666666664 + rh * (0.008333333333333333
            + rh * (0.001388888888888889 + rh * (0.0001984126984126984 + rh * (2.48015873015873e-05 + rh * (2.7557319223985893e-06
            + rh * (2.755731922398589e-07 + rh * (2.505210838544172e-08 + rh * (2.08767569878681e-09 + rh * (1.6059043836821613e-10
            + rh * 1.1470745597729725e-11)))))))))));
        double s = TwoSum(1.0, rh, out double e);
        double result = s + (e + (rl + rl * rh + rh * rh * poly));
        int ni = (int)n;
        if (ni > 1023)
            return result * Pow2(1023) * Pow2(ni - 1023);
        if (ni < -1022)
            return result * Pow2(ni + 600) * Pow2(-600); // the first product is exact, the second rounds once
        return result * Pow2(ni);
    }
}
