using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Runtime;
using System.Text;
using AcDream.Core.Physics.Bench.Reporting;

namespace AcDream.Core.Physics.Bench.Queries;

/// <summary>
/// <c>queries [--out DIR]</c>: times each world query against a player's <c>Resolve</c> of the same scene
/// and counts its allocations, printing a markdown table and writing it to DIR/queries.md (default
/// out/queries). A quick job; <c>-- --filter '*QueryBenchmarks*'</c> runs the same workloads under
/// BenchmarkDotNet.
/// </summary>
/// <remarks>
/// Built to give the same ratios on a loaded machine as on a quiet one. Tiered compilation optimizes a
/// method on a background thread once it has been called often enough; on a busy machine that thread
/// waits for a core, and a fixed warm-up (the earlier 2 × 500 calls and a pause) can end while queries
/// still run their first-tier or on-stack-replaced code: the job then printed 15–64× a Resolve. So the
/// warm-up runs every workload, round after round, until the JIT has compiled nothing new for a whole
/// second (<see cref="JitInfo.GetCompiledMethodCount"/>), and the timed rounds sample the rows in turn
/// (a query, then the next, then Resolve, round after round), each row keeping its fastest round, so a
/// change of load hits the queries and the Resolve alike.
/// </remarks>
public static class QueryJob
{
    private const int Rounds = 31, Calls = 500;

    /// <summary>Runs the job; returns the exit code.</summary>
    public static int Run(string[] args)
    {
        string outDir = "out/queries";
        for (int i = 0; i < args.Length; i++)
            if (args[i] == "--out" && i + 1 < args.Length)
                outDir = args[++i];
            else
            {
                Console.Error.WriteLine($"queries: unknown argument '{args[i]}' (usage: queries [--out DIR])");
                return 2;
            }
        var workloads = new QueryWorkloads();
        int count = QueryWorkloads.Names.Length, resolve = count - 1;
        float sink = 0;
        var (warmSeconds, compiled) = RowTimer.WarmUntilJitSettles(() =>
        {
            for (int w = 0; w < count; w++)
                for (int i = 0; i < 200; i++)
                    sink += workloads.Run(w);
        });
        var best = new double[count];
        Array.Fill(best, double.PositiveInfinity);
        for (int r = 0; r < Rounds; r++)
            for (int w = 0; w < count; w++)
            {
                long t0 = Stopwatch.GetTimestamp();
                for (int i = 0; i < Calls; i++)
                    sink += workloads.Run(w);
                best[w] = Math.Min(best[w], Stopwatch.GetElapsedTime(t0).TotalNanoseconds / Calls);
            }
        var table = new StringBuilder();
        table.AppendLine(Reports.Machine());
        table.AppendLine(string.Create(CultureInfo.InvariantCulture,
            $"Warm-up: {warmSeconds:0.0} s until the JIT settled ({compiled} methods compiled); then {Rounds} rounds of {Calls} calls per row, rows in turn, each row's fastest round."));
        table.AppendLine();
        table.AppendLine("| query | ns per call (fastest round) | × Resolve | bytes allocated per call |");
        table.AppendLine("|---|---:|---:|---:|");
        Console.Write(table.ToString());
        for (int w = 0; w < count; w++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < Calls; i++)
                sink += workloads.Run(w);
            double bytes = (GC.GetAllocatedBytesForCurrentThread() - before) / (double)Calls;
            string row = string.Create(CultureInfo.InvariantCulture,
                $"| {QueryWorkloads.Names[w]} | {best[w]:F0} | {best[w] / best[resolve]:F2} | {bytes:0.#} |");
            table.AppendLine(row);
            Console.WriteLine(row);
        }
        if (float.IsNaN(sink))
            Console.WriteLine("(a workload returned NaN)");
        Directory.CreateDirectory(outDir);
        string path = Path.Combine(outDir, "queries.md");
        File.WriteAllText(path, table.ToString());
        Console.WriteLine($"written to {path}");
        return 0;
    }
}
