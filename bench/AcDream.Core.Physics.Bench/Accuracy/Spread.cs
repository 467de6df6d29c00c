using System.Linq;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>Mean, 99th percentile and maximum of a sample.</summary>
public readonly record struct Spread(double Mean, double P99, double Max)
{
    /// <summary>Summarises the finite values of a sample (zeros when empty).</summary>
    public static Spread Of(IEnumerable<float> values)
    {
        var sorted = values.Where(float.IsFinite).Select(v => (double)v).OrderBy(v => v).ToArray();
        if (sorted.Length == 0)
            return new Spread(0, 0, 0);
        int p99 = Math.Clamp((int)Math.Ceiling(0.99 * sorted.Length) - 1, 0, sorted.Length - 1);
        return new Spread(sorted.Average(), sorted[p99], sorted[^1]);
    }
}
