using System.Diagnostics;
using System.Runtime;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>
/// Times a few calls side by side with Stopwatch loops: a warm-up (JIT tiering, in two passes), then the rows sampled in turn,
/// round after round, so a change of load on a shared machine hits them alike; each keeps its fastest round.
/// Bytes per call are read after the timing.
/// </summary>
public static class RowTimer
{
    /// <summary>Nanoseconds (fastest round's mean) and bytes per call of each row, in order.</summary>
    public static (double Ns, double Bytes)[] Measure(ReadOnlySpan<Action> rows, int warmUp = 20_000, int reps = 2000, int rounds = 15)
    {
        // Twice, with a pause between: on a loaded machine the runtime's background compiler may not have
        // installed the optimized code by the end of the first pass, and the timing would measure the rest.
        for (int pass = 0; pass < 2; pass++)
        {
            foreach (var row in rows)
                for (int i = 0; i < warmUp; i++)
                    row();
            System.Threading.Thread.Sleep(300);
        }
        var best = new double[rows.Length];
        Array.Fill(best, double.PositiveInfinity);
        var sw = new Stopwatch();
        for (int round = 0; round < rounds; round++)
            for (int r = 0; r < rows.Length; r++)
            {
                var call = rows[r];
                sw.Restart();
                for (int i = 0; i < reps; i++)
                    call();
                best[r] = Math.Min(best[r], sw.Elapsed.TotalNanoseconds / reps);
            }
        var results = new (double Ns, double Bytes)[rows.Length];
        for (int r = 0; r < rows.Length; r++)
        {
            var call = rows[r];
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; i++)
                call();
            results[r] = (best[r], (GC.GetAllocatedBytesForCurrentThread() - before) / 1000.0);
        }
        return results;
    }

    /// <summary>
    /// Runs <paramref name="round"/> until the JIT has compiled no method for a full second of rounds (at
    /// least three rounds, at most 60 s); returns the time taken and the methods compiled meanwhile.
    /// </summary>
    public static (double Seconds, long Compiled) WarmUntilJitSettles(Action round)
    {
        var total = Stopwatch.StartNew();
        long start = JitInfo.GetCompiledMethodCount(), last = start;
        var quiet = Stopwatch.StartNew();
        int quietRounds = 0;
        while (total.Elapsed.TotalSeconds < 60)
        {
            round();
            long now = JitInfo.GetCompiledMethodCount();
            if (now != last)
            {
                last = now;
                quiet.Restart();
                quietRounds = 0;
            }
            else if (++quietRounds >= 3 && quiet.Elapsed.TotalSeconds >= 1)
                break;
        }
        return (total.Elapsed.TotalSeconds, last - start);
    }
}
