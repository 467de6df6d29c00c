using System.Diagnostics;
using System.IO;
using AcDream.Core.Physics.Bench.Accuracy;
using AcDream.Core.Physics.Bench.Benchmarks;
using AcDream.Core.Physics.Bench.Reporting;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// The door job: measures every method's accuracy against the reference sweep over the approach grid,
/// times it (a Stopwatch loop with warm-up by default; BenchmarkDotNet proper with <c>--full</c>), and
/// writes the tables, CSVs, the speed/accuracy chart and the stability map.
/// </summary>
public static class DoorJob
{
    /// <summary>
    /// Runs the job. Options: <c>--out DIR</c> (default out/door); <c>--full</c> (BenchmarkDotNet's default
    /// job over every benchmark class, its door-transition means replacing the Stopwatch ones);
    /// <c>--full-short</c> (the same with BenchmarkDotNet's short job, a few minutes).
    /// </summary>
    public static int Run(string[] args)
    {
        string outDir = Path.Combine("out", "door");
        bool full = false, shortJob = false;
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--out" when i + 1 < args.Length:
                    outDir = args[++i];
                    break;
                case "--full":
                    full = true;
                    break;
                case "--full-short":
                    full = shortJob = true;
                    break;
                default:
                    Console.Error.WriteLine($"door: unknown option '{args[i]}'. Usage: door [--out DIR] [--full | --full-short]");
                    return 2;
            }
        }
        Directory.CreateDirectory(outDir);
        var clock = Stopwatch.StartNew();
        void Progress(string message) => Console.WriteLine($"[{clock.Elapsed:mm\\:ss}] {message}");

        Progress($"door job: {Reports.Machine()}");
        var scene = DoorScene.Create();
        var approaches = DoorApproaches.Grid();
        Progress($"{approaches.Length} approaches per method ({DoorApproaches.Headings.Length} headings × {DoorApproaches.Laterals.Length} offsets × {DoorApproaches.Speeds.Length} speeds × {DoorApproaches.Rates.Length} frame rates)");

        var results = new List<MethodResult>();
        foreach (var method in DoorMethods.All)
        {
            var outcomes = AccuracyRunner.Run(scene, method, approaches, recordWorkload: true);
            var summary = AccuracySummary.Of(method, outcomes);
            results.Add(new MethodResult { Method = method, Accuracy = summary, Outcomes = outcomes });
            Progress($"accuracy {DoorMethods.Label(method),-10}: {summary.Frames} frames, frame error p99 {summary.FrameError.P99 * 1000:0.###} mm, max penetration {summary.MaxPenetration * 1000:0.###} mm, tunnelling {summary.TunnelFrames}, stuck {summary.StuckFrames}, jitter {summary.JitterFrames}, NaN {summary.NaNFrames}");
        }

        Progress("warming up every method's timed workloads until the JIT has compiled nothing new for a second");
        Progress($"warmed up in {Warmup(scene, results):0.0} s");
        foreach (var r in results)
        {
            TimeMethod(scene, r);
            Progress($"speed    {DoorMethods.Label(r.Method),-10}: transition {r.Timing.TransitionNs:0} ns ({r.Timing.BytesPerTransition:0} B), approach {r.Timing.ApproachNs:0} ns/frame, slide {r.Timing.SlideNs:0} ns/frame, mix {r.Timing.MixNs:0} ns/frame, all cores {r.Timing.BatchPerSecond:N0} transitions/s");
        }

        // The door transition with props: one in a hundred in the door's cell (the rest elsewhere), none in
        // it, and a thousand all in it (4 m or more from the door).
        var scale = new List<(int, int, double)>();
        var rows = new List<(int Objects, bool NearShare, bool AllIn)>();
        foreach (int objects in new[] { 0, 10, 1_000, 10_000 })
            rows.Add((objects, true, false));
        foreach (int objects in new[] { 10, 1_000, 10_000 })
            rows.Add((objects, false, false));
        rows.Add((100, false, true));
        rows.Add((1_000, false, true));
        // Every row's world is built and warmed before the first is timed: the props' paths (the cull, the
        // object tests) are code the door alone never runs, and were timed in first-tier code in the first rows.
        var scaleSteppers = rows.ConvertAll(r => new DoorStepper(DoorScene.Create(r.Objects, nearShare: r.NearShare, allInDoorCell: r.AllIn), DoorMethod.Retail));
        RowTimer.WarmUntilJitSettles(() =>
        {
            foreach (var s in scaleSteppers)
                for (int i = 0; i < 50; i++)
                    s.Resolve(DoorWorkloads.TransitionStart, DoorWorkloads.TransitionTarget);
        });
        for (int k = 0; k < rows.Count; k++)
        {
            var (objects, nearShare, allIn) = rows[k];
            var stepper = scaleSteppers[k];
            var start = DoorWorkloads.TransitionStart;
            var target = DoorWorkloads.TransitionTarget;
            double ns = Measure(n => { for (int i = 0; i < n; i++) stepper.Resolve(start, target); }, 1, 0.3);
            int inDoorCell = allIn ? objects : nearShare ? (objects + 99) / 100 : 0;
            scale.Add((objects, inDoorCell, ns));
            Progress($"scale    {objects,6} other objects, {inDoorCell,5} of them in the door's cell: transition {ns:0} ns");
        }

        if (full)
        {
            Progress($"running BenchmarkDotNet ({(shortJob ? "short" : "default")} job) over every benchmark class; this takes a while");
            IConfig config = DefaultConfig.Instance;
            if (shortJob)
                config = config.AddJob(Job.ShortRun);
            var summaries = BenchmarkRunner.Run(typeof(DoorJob).Assembly, config);
            ApplyBenchmarkDotNet(summaries, results);
        }

        Progress($"writing {Path.GetFullPath(outDir)}");
        File.WriteAllText(Path.Combine(outDir, "door.csv"), Reports.SpeedAccuracyCsv(results));
        File.WriteAllText(Path.Combine(outDir, "stability.csv"), Reports.StabilityCsv(results));
        File.WriteAllText(Path.Combine(outDir, "door.md"),
            "# Door benchmark\n\n" + $"Machine: {Reports.Machine()}.\n\n" +
            $"Timing: {(full ? "BenchmarkDotNet for the door transition, Stopwatch for the rest" : "Stopwatch loops after a warm-up (fastest of 60 samples)")}. " +
            $"Accuracy: {approaches.Length} approaches per method, {results[0].Accuracy.Frames} frames for Retail.\n\n" +
            Reports.MethodsAndReference() + Reports.ColumnDefinitions() + Reports.FailureDefinitions() + "## Results\n\n" +
            Reports.SpeedAccuracyTable(results) + "\n" + Reports.ScaleTable(scale) + "\n![speed vs accuracy](door-speed-accuracy.png)\n");
        File.WriteAllText(Path.Combine(outDir, "stability.md"), "# Door stability map\n\n" + Reports.MethodsAndReference() +
            Reports.FailureDefinitions() + "## Results\n\n" + Reports.StabilityTables(results) + "\n![stability map](stability-map.png)\n");
        Charts.SpeedVsAccuracy(results, Path.Combine(outDir, "door-speed-accuracy.png"));
        Charts.StabilityMap(results, Path.Combine(outDir, "stability-map.png"));
        Console.WriteLine();
        Console.WriteLine(Reports.SpeedAccuracyTable(results));
        Console.WriteLine(Reports.ScaleTable(scale));
        Progress("done");
        return 0;
    }

    /// <summary>
    /// Runs every method's timed workloads until the JIT has promoted the hot code to its final tier (it
    /// compiles nothing new for a second); returns the seconds taken. A fixed warm-up left rows timed in
    /// first-tier code on a loaded machine, and even on a quiet one for code only the later rows run.
    /// </summary>
    private static double Warmup(DoorScene scene, List<MethodResult> results)
    {
        var steppers = results.ConvertAll(r => new DoorStepper(scene, r.Method));
        // Each method's approach mix too: its frames (fast ones, the props beyond the door) run code the
        // three short workloads do not.
        var mixes = results.ConvertAll(r => r.Outcomes.SelectMany(o => o.Workload ?? []).ToArray());
        var start = DoorWorkloads.TransitionStart;
        var target = DoorWorkloads.TransitionTarget;
        return RowTimer.WarmUntilJitSettles(() =>
        {
            for (int m = 0; m < steppers.Count; m++)
            {
                var stepper = steppers[m];
                for (int i = 0; i < 50; i++)
                    stepper.Resolve(start, target);
                DoorWorkloads.Approach(stepper);
                DoorWorkloads.SlideNorthEast(stepper);
                foreach (var (state, goal) in mixes[m])
                    stepper.Resolve(state, goal);
            }
        }).Seconds;
    }

    private static void TimeMethod(DoorScene scene, MethodResult result)
    {
        var method = result.Method;
        var stepper = new DoorStepper(scene, method);
        var timing = result.Timing;
        var start = DoorWorkloads.TransitionStart;
        var target = DoorWorkloads.TransitionTarget;
        timing.TransitionNs = Measure(n => { for (int i = 0; i < n; i++) stepper.Resolve(start, target); }, 1, 0.4);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 1000; i++)
            stepper.Resolve(start, target);
        timing.BytesPerTransition = (GC.GetAllocatedBytesForCurrentThread() - before) / 1000.0;
        timing.ApproachNs = Measure(n => { for (int i = 0; i < n; i++) DoorWorkloads.Approach(stepper); }, DoorWorkloads.ApproachFrames, 0.3);
        timing.SlideNs = Measure(n => { for (int i = 0; i < n; i++) DoorWorkloads.SlideNorthEast(stepper); }, DoorWorkloads.ApproachFrames, 0.3);

        var workload = result.Outcomes.SelectMany(o => o.Workload ?? []).ToArray();
        double best = double.PositiveInfinity;
        for (int pass = 0; pass < 3; pass++)
        {
            var sw = Stopwatch.StartNew();
            foreach (var (state, goal) in workload)
                stepper.Resolve(state, goal);
            best = Math.Min(best, sw.Elapsed.TotalNanoseconds / workload.Length);
        }
        timing.MixNs = best;

        int workers = Environment.ProcessorCount;
        DoorWorkloads.Batch(scene, method, workers);
        var batchClock = Stopwatch.StartNew();
        int batches = 0;
        while (batchClock.Elapsed.TotalSeconds < 0.3 || batches < 2)
        {
            DoorWorkloads.Batch(scene, method, workers);
            batches++;
        }
        timing.BatchPerSecond = batches * (double)DoorWorkloads.BatchTransitions / batchClock.Elapsed.TotalSeconds;
    }

    /// <summary>
    /// Nanoseconds per operation: warms up for 100 ms, picks a repetition count so one sample takes about a
    /// sixtieth of <paramref name="seconds"/>, and returns the fastest of sixty samples (the least disturbed
    /// by other work on a shared machine: short samples often run between two preemptions).
    /// </summary>
    public static double Measure(Action<int> run, int opsPerRun, double seconds)
    {
        var sw = Stopwatch.StartNew();
        int warm = 0;
        while (sw.Elapsed.TotalMilliseconds < 100 || warm < 3)
        {
            run(1);
            warm++;
        }
        double perRun = sw.Elapsed.TotalSeconds / warm;
        int reps = Math.Max(1, (int)(seconds / 60 / perRun));
        var samples = new double[60];
        for (int s = 0; s < samples.Length; s++)
        {
            sw.Restart();
            run(reps);
            samples[s] = sw.Elapsed.TotalNanoseconds / ((double)reps * opsPerRun);
        }
        Array.Sort(samples);
        return samples[0];
    }

    private static void ApplyBenchmarkDotNet(IEnumerable<Summary> summaries, List<MethodResult> results)
    {
        foreach (var summary in summaries)
            foreach (var report in summary.Reports)
            {
                var bench = report.BenchmarkCase;
                if (bench.Descriptor.Type != typeof(DoorTransitionBenchmarks) || report.ResultStatistics is null)
                    continue;
                if (bench.Parameters["Resolver"] is not DoorMethod method)
                    continue;
                var r = results.FirstOrDefault(x => x.Method == method);
                if (r is null)
                    continue;
                r.Timing.TransitionNs = report.ResultStatistics.Mean;
                r.Timing.Source = "BenchmarkDotNet";
            }
    }
}
