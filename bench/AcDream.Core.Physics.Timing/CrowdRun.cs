using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// Times a <see cref="Crowd"/> tick by tick: <c>crowd [--ticks T] [--threads 1|2|both] N...</c>. Per creature
/// count and thread count, one line of the forming phase (the first third of the ticks, while the crowd
/// converges and piles up), one of the settled phase (the last third), the worst 30-tick mean, the bytes
/// allocated per settled tick and the fingerprint of every position of every tick. <c>both</c> runs one and
/// two threads in lockstep with a loop that shares nothing, for the two-core ceiling (see <see cref="Lockstep"/>).
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
        {
            if (threadCounts.Count == 2)
                Lockstep(n, ticks);
            else
                Report(n, threadCounts[0], ticks);
        }
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
                using var crowd = new Crowd(120, threads);
                for (int t = 0; t < 240; t++) crowd.Tick();
            }
            long now = System.Runtime.JitInfo.GetCompiledMethodCount();
            if (now != compiled) { compiled = now; quiet.Restart(); }
            else if (quiet.Elapsed.TotalSeconds >= 1) break;
        }
    }

    private static void Report(int n, int threads, int ticks)
    {
        using var crowd = new Crowd(n, threads);
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
        Print(n, threads, ticks, crowd.Fingerprint, ms, near, settledBytes / (double)(ticks - settledFrom));
    }

    private static void Print(int n, int threads, int ticks, ulong fingerprint, double[] ms, int[] near, double settledBytesPerTick)
    {
        var forming = ms.AsSpan(0, ticks / 3);
        int settledFrom = ticks - ticks / 3;
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
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} ticks {ticks} fingerprint {fingerprint:X16}"));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} forming ticks 1-{ticks / 3} {Stats(forming)}"));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} settled ticks {settledFrom + 1}-{ticks} {Stats(settled)} B/tick {settledBytesPerTick:0.#}"));
        Console.WriteLine(string.Create(c, $"crowd {n} threads {threads} worst 30-tick mean {worst:0.000} ms at ticks {worstAt + 1}-{worstAt + 30} = {worst / settledMean:0.00}x settled"));
        var line = new System.Text.StringBuilder(string.Create(c, $"crowd {n} threads {threads} 30-tick means ms (creatures within 8 m / 16 m at the window's end):"));
        for (int t = 0; t + 30 <= ticks; t += 30)
            line.Append(string.Create(c, $" {Mean(ms.AsSpan(t, 30)):0.00}({near[t + 29] / 10000}/{near[t + 29] % 10000})"));
        Console.WriteLine(line.ToString());
    }

    /// <summary>
    /// One thread against two in lockstep: the same crowd run on one thread and on two (the same bits), and in
    /// every tick a loop that shares nothing (each thread its own registers and stack), as long as that tick's
    /// one-thread step phase, run on one thread and split over two the same way. The loop's ratio is what this
    /// machine gives two threads now; the tick's, split into its step phase (parallel) and its one-writer
    /// phase (the registry moves), is set against it.
    /// </summary>
    private static void Lockstep(int n, int ticks)
    {
        using var one = new Crowd(n, 1);
        using var two = new Crowd(n, 2);
        using var pair = new TwoThreads();
        double perMs = LoopsPerMs();
        var ms1 = new double[ticks];
        var ms2 = new double[ticks];
        var near = new int[ticks];
        double step1 = 0, step2 = 0, loop1 = 0, loop2 = 0, busyMax = 0, busySum = 0, loopBusyMax = 0, loopBusySum = 0;
        long bytes = 0, bytes1 = 0;
        int settledFrom = ticks - ticks / 3;
        for (int t = 0; t < ticks; t++)
        {
            long before = t >= settledFrom ? GC.GetTotalAllocatedBytes(precise: true) : 0;
            long t0 = Stopwatch.GetTimestamp();
            one.Tick();
            ms1[t] = Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
            if (t >= settledFrom) bytes1 += GC.GetTotalAllocatedBytes(precise: true) - before;
            before = t >= settledFrom ? GC.GetTotalAllocatedBytes(precise: true) : 0;
            t0 = Stopwatch.GetTimestamp();
            two.Tick();
            ms2[t] = Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
            if (t >= settledFrom) bytes += GC.GetTotalAllocatedBytes(precise: true) - before;
            step1 += one.StepMs;
            step2 += two.StepMs;
            var busy = two.Busy;
            busyMax += Math.Max(busy.Caller, busy.Second);
            busySum += busy.Caller + busy.Second;
            near[t] = one.NearPlayer(8f) * 10000 + one.NearPlayer(16f);
            // The loop that shares nothing, as long as this tick's one-thread step phase.
            long loops = Math.Max(1000, (long)(one.StepMs * perMs));
            t0 = Stopwatch.GetTimestamp();
            _sink += Spin(loops);
            loop1 += Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
            _half = loops / 2;
            t0 = Stopwatch.GetTimestamp();
            pair.Run(SpinHalf);
            loop2 += Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
            loopBusyMax += Math.Max(pair.Busy.Caller, pair.Busy.Second);
            loopBusySum += pair.Busy.Caller + pair.Busy.Second;
        }
        if (one.Fingerprint != two.Fingerprint)
            Console.WriteLine($"crowd {n}: ONE AND TWO THREADS DIFFER: {one.Fingerprint:X16} against {two.Fingerprint:X16}");
        Print(n, 1, ticks, one.Fingerprint, ms1, near, bytes1 / (double)(ticks - settledFrom));
        Print(n, 2, ticks, two.Fingerprint, ms2, near, bytes / (double)(ticks - settledFrom));
        double total1 = Sum(ms1), total2 = Sum(ms2);
        var c = CultureInfo.InvariantCulture;
        Console.WriteLine(string.Create(c, $"crowd {n} two cores: load average {Load()}; over {ticks} ticks, 1 -> 2 threads"));
        Console.WriteLine(string.Create(c, $"crowd {n} two cores: loop sharing nothing {loop1:0} -> {loop2:0} ms = {loop1 / loop2:0.00}x (the ceiling; its threads' imbalance {loopBusyMax / (loopBusySum / 2):0.00})"));
        Console.WriteLine(string.Create(c, $"crowd {n} two cores: tick {total1:0} -> {total2:0} ms = {total1 / total2:0.00}x = {total1 / total2 / (loop1 / loop2) * 100:0}% of the ceiling"));
        Console.WriteLine(string.Create(c, $"crowd {n} two cores: step phase {step1:0} -> {step2:0} ms = {step1 / step2:0.00}x (threads' imbalance {busyMax / (busySum / 2):0.00}, busy {busySum:0} ms against {step1:0} on one); one-writer phase {total1 - step1:0} -> {total2 - step2:0} ms ({(total1 - step1) / total1 * 100:0.0}% of the one-thread tick)"));
    }

    private static long _half;
    private static float _sink;
    private static readonly Action<int> SpinHalf = t => Slot(t) = Spin(_half);
    private static readonly float[] Sinks = new float[64];

    // Each thread writes its result once, 128 bytes from the other's.
    private static ref float Slot(int t) => ref Sinks[t * 32];

    /// <summary>A loop that touches no memory: four independent float chains.</summary>
    private static float Spin(long loops)
    {
        float a = 1, b = 2, c = 3, d = 4;
        for (long i = 0; i < loops; i++)
        {
            a = a * 0.999999f + 0.5f;
            b = b * 0.999998f + 0.25f;
            c = c * 0.999997f + 0.125f;
            d = d * 0.999996f + 0.0625f;
        }
        return a + b + c + d;
    }

    private static double LoopsPerMs()
    {
        _sink += Spin(1_000_000);
        double best = double.PositiveInfinity;
        for (int i = 0; i < 5; i++)
        {
            long t0 = Stopwatch.GetTimestamp();
            _sink += Spin(2_000_000);
            best = Math.Min(best, Stopwatch.GetElapsedTime(t0).TotalMilliseconds);
        }
        return 2_000_000 / best;
    }

    private static double Sum(double[] xs)
    {
        double s = 0;
        foreach (double x in xs) s += x;
        return s;
    }

    private static string Load()
    {
        try { return System.IO.File.Exists("/proc/loadavg") ? string.Join(' ', System.IO.File.ReadAllText("/proc/loadavg").Split(' ')[..3]) : "unknown"; }
        catch (System.IO.IOException) { return "unknown"; }
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
