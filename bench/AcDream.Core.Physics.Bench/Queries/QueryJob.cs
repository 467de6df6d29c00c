using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace AcDream.Core.Physics.Bench.Queries;

/// <summary>
/// <c>queries [--out DIR]</c>: times each world query (median of 15 rounds of 2000 calls, after warm-up)
/// and counts its allocations, printing a markdown table and writing it to DIR/queries.md (default out/queries).
/// A quick job; <c>-- --filter '*QueryBenchmarks*'</c> runs the same workloads under BenchmarkDotNet.
/// </summary>
public static class QueryJob
{
    private const int Rounds = 15, Calls = 2000;

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
        // Tiered compilation optimizes a method on a background thread after it has run a while: run every
        // workload, pause for the optimizing compiler, twice, so no row is timed in unoptimized code.
        for (int pass = 0; pass < 2; pass++)
        {
            for (int w = 0; w < QueryWorkloads.Names.Length; w++)
                for (int i = 0; i < 500; i++)
                    workloads.Run(w);
            System.Threading.Thread.Sleep(500);
        }
        var table = new StringBuilder();
        table.AppendLine("| query | ns per call (median) | bytes allocated per call |");
        table.AppendLine("|---|---:|---:|");
        for (int w = 0; w < QueryWorkloads.Names.Length; w++)
        {
            var ns = new double[Rounds];
            float sink = 0;
            for (int r = 0; r < Rounds; r++)
            {
                var watch = Stopwatch.StartNew();
                for (int i = 0; i < Calls; i++)
                    sink += workloads.Run(w);
                ns[r] = watch.Elapsed.TotalNanoseconds / Calls;
            }
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < Calls; i++)
                sink += workloads.Run(w);
            double bytes = (GC.GetAllocatedBytesForCurrentThread() - before) / (double)Calls;
            Array.Sort(ns);
            string row = string.Create(CultureInfo.InvariantCulture, $"| {QueryWorkloads.Names[w]} | {ns[Rounds / 2]:F0} | {bytes:0.#} |");
            table.AppendLine(row);
            Console.WriteLine(row + (float.IsNaN(sink) ? " " : ""));
        }
        Directory.CreateDirectory(outDir);
        string path = Path.Combine(outDir, "queries.md");
        File.WriteAllText(path, table.ToString());
        Console.WriteLine($"written to {path}");
        return 0;
    }
}
