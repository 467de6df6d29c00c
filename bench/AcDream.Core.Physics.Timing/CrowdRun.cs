using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Threading.Tasks;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// Times a <see cref="Crowd"/> tick by tick: <c>crowd [--ticks T] [--threads 1|2|both] N...</c>. Per creature
/// count and thread count, one line of the forming phase (the first third of the ticks, while the crowd
/// converges and piles up), one of the settled phase (the last third), the worst 30-tick mean, the bytes
/// allocated per settled tick and the fingerprint of every position of every tick.
/// </summary>
internal static class CrowdRun
{
    /// <summary>Runs the command; exit 2 on a usage error.</summary>
    public static int Run(string[] args)
    {
        int ticks = 600;
        var threadCounts = new List<int> { 1 };
        var counts = new List<int>();
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--ticks" && i + 1 < args.Length && int.TryParse(args[i + 1], out ticks) && ticks >= 90) i++;
            else if (args[i] == "--threads" && i + 1 < args.Length)
            {
                threadCounts = args[++i] switch { "1" => [1], "2" => [2], "both" => [1, 2], _ => [] };
                if (threadCounts.Count == 0) return Usage($"bad thread count '{args[i]}'");
            }
            else if (int.TryParse(args[i], NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n >= 1 && n <= 5000) counts.Add(n);
            else return Usage($"bad argument '{args[i]}'");
        }
        if (counts.Count == 0) counts.AddRange([200, 1000]);
        Warm(threadCounts);
        foreach (int n in counts)
            foreach (int threads in threadCounts)
                Report(n, threads, ticks);
        return 0;
    }

    private static int Usage(string message)
    {
        Console.Error.WriteLine($"crowd: {message}. Usage: crowd [--ticks T (90 or more)] [--threads 1|2|both] N...");
        return 2;
    }

    /// <summary>Runs small crowds until the JIT has compiled nothing new for a second (at most 60 s), so no tick is timed in first-tier code.</summary>
    private static void Warm(List<int> threadCounts)
    {
        var total = Stopwatch.StartNew();
        var quiet = Stopwatch.StartNew();
        long compiled = System.Runtime.JitInfo.GetCompiledMethodCount();
        while (total.Elapsed.TotalSeconds < 60)
        {
            foreach (int threads in threadCounts)
            {
                var crowd = new Crowd(120, threads);
                for (int t = 0; t < 240; t++) crowd.Tick();
            }
            long now = System.Runtime.JitInfo.GetCompiledMethodCount();
            if (now != compiled) { compiled = now; quiet.Restart(); }
            else if (quiet.Elapsed.TotalSeconds >= 1) break;
        }
    }

    private static void Report(int n, int threads, int ticks)
    {
        var crowd = new Crowd(n, threads);
        var ms = new double[ticks];
        var near = new int[ticks];
        long settledBytes = 0;
        int settledFrom = ticks - ticks / 3;
        for (int t = 0; t < ticks; t++)
        {
            long before = t >= settledFrom ? GC.GetTotalAllocatedBytes(precise: true) : 0;
            long t0 = Stopwatch.GetTimestamp();
            crowd.Tick();
            ms[t] = Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
            if (t >= settledFrom) settledBytes += GC.GetTotalAllocatedBytes(precise: true) - before;
            near[t] = crowd.NearPlayer(8f) * 10000 + crowd.NearPlayer(16f);
        }
        var forming = ms.AsSpan(0, ticks / 3);
        var settled = ms.AsSpan(settledFrom);
        double settledMean = Mean(settled);
        int worstAt = 0;
        double worst = 0;
        for (int t = 0; t + 30 <= ticks; t += 30)
        {
            double m = Mean(ms.AsSpan(t, 30));
            if (m > worst) { worst = m; worstAt = t; }
        }
        var c = CultureInfo.InvariantCulture;
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} ticks {ticks} fingerprint {crowd.Fingerprint:X16}"));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} forming ticks 1-{ticks / 3} {Stats(forming)} "));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} settled ticks {settledFrom + 1}-{ticks} {Stats(settled)} B/tick {settledBytes / (double)settled.Length:0.#}"));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} worst 30-tick mean {worst:0.000} ms at ticks {worstAt + 1}-{worstAt + 30} = {worst / settledMean:0.00}x settled"));
        var line = new System.Text.StringBuilder(string.Create(c, $"crowd {n} threads {threads} 30-tick means ms:"));
        for (int t = 0; t + 30 <= ticks; t += 30)
            line.Append(string.Create(c, $" {Mean(ms.AsSpan(t, 30)):0.00}({near[t + 29] / 10000}/{near[t + 29] % 10000})"));
        Console.WriteLine(line.ToString());
    }

    private static double Mean(ReadOnlySpan<double> xs)
    {
        double s = 0;
        foreach (double x in xs) s += x;
        return s / xs.Length;
    }

    private static string Stats(ReadOnlySpan<double> xs)
    {
        var sorted = xs.ToArray();
        Array.Sort(sorted);
        double P(double q) => sorted[Math.Min(sorted.Length - 1, (int)Math.Ceiling(q * sorted.Length) - 1)];
        return string.Create(CultureInfo.InvariantCulture, $"mean {Mean(xs):0.000} p50 {P(0.5):0.000} p99 {P(0.99):0.000} max {sorted[^1]:0.000} ms");
    }
}
