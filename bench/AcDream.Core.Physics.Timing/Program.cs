using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Runtime.InteropServices;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// The timing driver behind bench/compare.sh (wall-clock ratios, and instruction counts with --callgrind):
/// <c>list</c> prints the workloads (name, transitions per run, description); <c>time [--rounds N] [--ms N] [NAME...]</c> prints, per workload, the
/// fastest sample's nanoseconds and the bytes allocated per transition; <c>count NAME N</c> resolves a
/// workload 20 times, then N times between two marks for callgrind (see <see cref="Mark"/>);
/// <c>fingerprint</c> prints a hash of every result on a grid of approaches (see <see cref="Workload.Fingerprint"/>), then
/// one of every body step's result on the same kind of grid (<see cref="Workload.BodyFingerprint"/>). Body workloads
/// (named <c>body-…</c>) time one <c>PhysicsEngine.Step</c> per frame.
/// </summary>
public static class Program
{
    /// <summary>Runs a command; exit 2 on a usage error.</summary>
    public static int Main(string[] args)
    {
        var workloads = Workload.All();
        string command = args.Length > 0 ? args[0] : "time";
        switch (command)
        {
            case "list":
                foreach (var w in workloads)
                    Console.WriteLine($"{w.Name,-14} {w.Frames,3} {w.Description} ({w.BlockedFrames()} of {w.Frames} frames blocked)");
                return 0;
            case "count" when args.Length == 3 && int.TryParse(args[2], out int n) && n >= 0:
                var one = workloads.FirstOrDefault(w => w.Name == args[1]);
                if (one is null)
                    return Usage($"unknown workload '{args[1]}'");
                float sum = 0;
                for (int i = 0; i < 20; i++)
                    sum += one.Run();
                Mark();
                for (int i = 0; i < n; i++)
                    sum += one.Run();
                Mark();
                Console.WriteLine($"{one.Name}: {n} runs, {n * (long)one.Frames} transitions, checksum {sum.ToString("R", CultureInfo.InvariantCulture)}");
                return 0;
            case "fingerprint":
                Console.WriteLine($"fingerprint {Workload.Fingerprint():X16}");
                Console.WriteLine($"body-fingerprint {Workload.BodyFingerprint():X16}");
                return 0;
            case "time":
                return Time(workloads, args.Skip(1).ToArray());
            case "crowd-count" when args.Length == 4 && int.TryParse(args[1], out int creatures) && int.TryParse(args[2], out int skip)
                                    && int.TryParse(args[3], out int counted):
                var crowd = new Crowd(creatures, 1);
                for (int i = 0; i < skip; i++)
                    crowd.Tick();
                Mark();
                for (int i = 0; i < counted; i++)
                    crowd.Tick();
                Mark();
                Console.WriteLine($"crowd {creatures}: ticks {skip + 1}-{skip + counted} counted, fingerprint {crowd.Fingerprint:X16}");
                return 0;
            case "crowd":
                return CrowdRun.Run(args.Skip(1).ToArray());
            default:
                return Usage($"unknown command '{command}'");
        }
    }

    /// <summary>
    /// Marks the start and end of the counted runs for callgrind (<c>--dump-before=getpgrp</c> writes a
    /// profile part at each call, so the middle part holds exactly the counted runs). A harmless libc call.
    /// </summary>
    private static void Mark()
    {
        if (OperatingSystem.IsLinux())
            _ = getpgrp();
    }

    [DllImport("libc")]
    private static extern int getpgrp();

    private static int Usage(string message)
    {
        Console.Error.WriteLine($"timing: {message}. Usage: list | time [--rounds N] [--ms N] [NAME...] | count NAME N | fingerprint");
        return 2;
    }

    /// <summary>
    /// Warms every selected workload up for 0.5 s (the JIT's tiers) and then all of them in turn until the JIT
    /// settles, then takes <c>rounds</c> samples of
    /// about <c>ms</c> milliseconds of each, round-robin, and reports the fastest (the least disturbed on
    /// a shared machine).
    /// </summary>
    private static int Time(IReadOnlyList<Workload> all, string[] args)
    {
        int rounds = 60;
        double ms = 2;
        var names = new List<string>();
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--rounds" && i + 1 < args.Length && int.TryParse(args[i + 1], out rounds) && rounds > 0) i++;
            else if (args[i] == "--ms" && i + 1 < args.Length && double.TryParse(args[i + 1], CultureInfo.InvariantCulture, out ms) && ms > 0) i++;
            else if (all.Any(w => w.Name == args[i])) names.Add(args[i]);
            else return Usage($"bad argument '{args[i]}'");
        }
        var selected = names.Count == 0 ? all.ToList() : all.Where(w => names.Contains(w.Name)).ToList();
        var reps = new int[selected.Count];
        var best = new double[selected.Count];
        var bytes = new double[selected.Count];
        float sink = 0;
        for (int k = 0; k < selected.Count; k++)
        {
            var w = selected[k];
            var sw = Stopwatch.StartNew();
            int runs = 0;
            while (sw.Elapsed.TotalMilliseconds < 500)
            {
                sink += w.Run();
                runs++;
            }
            reps[k] = Math.Max(1, (int)(runs * ms / sw.Elapsed.TotalMilliseconds));
            best[k] = double.PositiveInfinity;
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < reps[k]; i++)
                sink += w.Run();
            bytes[k] = (GC.GetAllocatedBytesForCurrentThread() - before) / ((double)reps[k] * w.Frames);
        }
        // Then round after round of all of them until the JIT has compiled nothing for a full second (at most
        // 60 s): on a loaded machine the background compiler waits for a core, and a sample of first-tier code
        // is not the code that will run (the queries job found the same).
        var total = Stopwatch.StartNew();
        var quiet = Stopwatch.StartNew();
        long compiled = System.Runtime.JitInfo.GetCompiledMethodCount();
        int quietRounds = 0;
        while (total.Elapsed.TotalSeconds < 60)
        {
            for (int k = 0; k < selected.Count; k++)
                for (int i = 0; i < reps[k]; i++)
                    sink += selected[k].Run();
            long now = System.Runtime.JitInfo.GetCompiledMethodCount();
            if (now != compiled)
            {
                compiled = now;
                quiet.Restart();
                quietRounds = 0;
            }
            else if (++quietRounds >= 3 && quiet.Elapsed.TotalSeconds >= 1)
                break;
        }
        for (int r = 0; r < rounds; r++)
            for (int k = 0; k < selected.Count; k++)
            {
                var w = selected[k];
                long t0 = Stopwatch.GetTimestamp();
                for (int i = 0; i < reps[k]; i++)
                    sink += w.Run();
                double ns = Stopwatch.GetElapsedTime(t0).TotalNanoseconds / ((double)reps[k] * w.Frames);
                best[k] = Math.Min(best[k], ns);
            }
        for (int k = 0; k < selected.Count; k++)
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{selected[k].Name} {best[k]:0.0} {bytes[k]:0.0}"));
        return float.IsNaN(sink) ? 1 : 0;
    }
}
