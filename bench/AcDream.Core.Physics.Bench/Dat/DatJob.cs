using System.Diagnostics;
using System.IO;
using System.Threading;
using AcDream.Core.Physics.Dat;
using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Parity;
using DatReaderWriter;
using DatReaderWriter.Enums;
using DatReaderWriter.Options;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Bench.Dat;

/// <summary>
/// The dat job: loading and unloading a landblock of Holtburg's size from DAT files through the Dat package. The
/// world is a real-cells set's (real retail Holtburg cottage cells, their building and objects, the 9 × 9 terrain),
/// written as client_portal.dat and client_cell_1.dat in a temporary folder. Reports the opening of the files, the
/// first load in the process (JIT included), the cold loads right after it (code compiled but not yet optimized),
/// then, once a warm-up has let the code tier up (what a client streaming for a while runs), the load and unload
/// time with the converted-object cache empty (cold) and full (warm), the bytes a loaded landblock holds, the first
/// transition after a load against the next ones, and the streaming budget of a runner. Skips (exit 0) when the
/// shared real-cells folder is absent.
/// </summary>
public static class DatJob
{
    // The loads timed right after the first one, before the warm-up.
    private const int StartupLoads = 20;
    // The warm-up: rounds of cold and warm loads and a move, with pauses longer than the runtime's 100 ms tiering
    // delay, until no method has been compiled for a few rounds.
    private const int RoundCycles = 20, PauseMs = 150, SettledRounds = 3;
    private const double MinWarmUpSeconds = 2, MaxWarmUpSeconds = 20;

    // DOTNET_TieredCompilation=0 (or its older COMPlus_ name): every method compiled optimized at its first call.
    private static bool TieredCompilationOff =>
        System.Environment.GetEnvironmentVariable("DOTNET_TieredCompilation") == "0" || System.Environment.GetEnvironmentVariable("COMPlus_TieredCompilation") == "0";

    /// <summary>Runs the job: <c>dat [--file REAL-CELLS-FILE] [--runs N]</c>.</summary>
    public static int Run(string[] args)
    {
        string? file = null;
        int runs = 200;
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--file" && i + 1 < args.Length) file = args[++i];
            else if (args[i] == "--runs" && i + 1 < args.Length && int.TryParse(args[++i], out runs) && runs > 0) { }
            else { Console.Error.WriteLine($"dat: unknown argument '{args[i]}' (usage: dat [--file REAL-CELLS-FILE] [--runs N])"); return 2; }
        }
        file ??= FindSharedFile("real-cells", "cottageA-ramp.json.gz");
        if (file is null || !File.Exists(file))
        {
            Console.WriteLine("dat: no shared/real-cells folder found beside the repository; skipped.");
            return 0;
        }
        var set = ParityReader.ReadFile(file);
        var dat = WorldDat.From(set.World);
        if (dat.Landblocks.Count != 1)
            throw new InvalidOperationException($"{file}: the job loads one landblock, the set has {dat.Landblocks.Count}.");
        uint landblock = dat.Landblocks[0];
        string folder = Path.Combine(Path.GetTempPath(), "acdream-datjob-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        try
        {
            Write(folder, dat);
            return Measure(folder, dat, landblock, set, runs, Path.GetFileName(file));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    private static int Measure(string folder, WorldDat dat, uint landblock, ParitySet set, int runs, string name)
    {
        DatObjectDescriber describe = (lb, index, owner, ownerIndex, placement) =>
        {
            var d = dat.Objects[(owner, ownerIndex)];
            return new DatObjectDescription(d.Id, d.Scale, d.State, d.Flags);
        };
        // The first load in this process: the files opened, the code compiled, the caches empty.
        var clock = Stopwatch.StartNew();
        var files = DatFiles.Open(folder);
        double openMs = clock.Elapsed.TotalMilliseconds;
        var first = new DatWorld(files, describe: describe);
        var block = first.LoadLandblock(landblock);
        double firstMs = clock.Elapsed.TotalMilliseconds - openMs;
        first.UnloadLandblock(landblock);
        int polygons = block.EnvCells.Sum(c => c.PhysicsBsp?.Polygons.Length ?? 0) + block.Buildings.Sum(b => b.Shell.Bsp.Polygons.Length)
            + block.Objects.Sum(o => o.Setup.Parts.Sum(p => p.Model?.Bsp.Polygons.Length ?? 0));
        Console.WriteLine($"dat job: {name}, landblock 0x{landblock:X4}: 64 land cells, {block.EnvCells.Count} env cells, " +
            $"{block.Buildings.Count} buildings, {block.Objects.Count} static objects, {polygons} physics polygons; {runs} runs per measure");
        Console.WriteLine($"  open the two files                        {openMs,9:F3} ms");
        Console.WriteLine($"  first load in the process                 {firstMs,9:F3} ms (JIT included)");
        var run = set.Runs[0];
        var target = run.Start.Position;
        target.Frame.Origin += run.Frames[0].Offset;

        // The loads right after the first: the code now compiled, but only quickly (tiered compilation's tier 0,
        // unoptimized), as a client's first streamed landblocks meet it.
        var startup = new double[StartupLoads];
        for (int i = 0; i < startup.Length; i++)
        {
            files.Converted.Clear();
            (startup[i], _) = Cycle(files, describe, landblock);
        }
        Console.WriteLine($"  cold load right after start-up            {Median(startup),9:F3} ms median of loads 2-{StartupLoads + 1} " +
            $"({Percentile(startup, 0.9):F3} ms p90; {(TieredCompilationOff ? "tiered compilation off: code optimized" : "code mostly unoptimized")})");

        var (seconds, rounds, compiledDuring, compiledLast) = WarmUp(files, describe, landblock, run, target);
        Console.WriteLine($"  warm-up until the code tiered up: {rounds} rounds of {RoundCycles} cold and warm loads and moves, " +
            $"{PauseMs} ms apart, {seconds:F1} s, {compiledDuring} methods compiled; " + (TieredCompilationOff
                ? "tiered compilation off: nothing to tier up, the minimum time run"
                : compiledLast == 0
                ? $"none in the last {SettledRounds} rounds"
                : $"still compiling ({compiledLast} in the last {SettledRounds} rounds) when stopped at {MaxWarmUpSeconds} s"));

        var cold = new double[runs];
        var warm = new double[runs];
        var unload = new double[runs];
        for (int i = 0; i < runs; i++)
        {
            files.Converted.Clear();
            (cold[i], _) = Cycle(files, describe, landblock);
            (warm[i], unload[i]) = Cycle(files, describe, landblock);
        }
        Console.WriteLine($"  cold load, steady state (code tiered up)  {Median(cold),9:F3} ms median ({Percentile(cold, 0.9):F3} ms p90)");
        Console.WriteLine($"  warm load, steady state (code tiered up)  {Median(warm),9:F3} ms median ({Percentile(warm, 0.9):F3} ms p90)");
        Console.WriteLine($"  unload, steady state                      {Median(unload),9:F3} ms median");
        // Bytes allocated by one cold load (the DAT reads, the conversions, the world's cells): unlike the clock,
        // independent of what else the machine runs.
        files.Converted.Clear();
        var allocWorld = new DatWorld(files, describe: describe);
        long allocBefore = GC.GetAllocatedBytesForCurrentThread();
        allocWorld.LoadLandblock(landblock);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - allocBefore;
        Console.WriteLine($"  allocated, cold load                      {allocated / 1024.0,9:F1} KB");
        // The anchor was measured outside, under conditions not stated (whether its code was optimized, what else
        // the machine ran), so no ratio is drawn against it here. Cold = the DAT reads of every Environment and
        // GfxObj and their conversion; warm = the landblock's own reads, its terrain and env cells, the 64 land cells.
        // Where the time goes: docs/performance.md, "Loading landblocks from DAT files".
        Console.WriteLine("  anchor, measured outside under unstated conditions (not comparable with a line above): ACE loaded " +
            "such a landblock's physics with its caches empty in 0.45 ms holding 366 KB, and in 39.5 ms as the first load in its process");

        // Bytes held: a world with the landblock loaded (and the cache it filled), against nothing loaded.
        files.Converted.Clear();
        long before = GC.GetTotalMemory(forceFullCollection: true);
        var held = new DatWorld(files, describe: describe);
        held.LoadLandblock(landblock);
        long withCache = GC.GetTotalMemory(forceFullCollection: true) - before;
        var second = new DatWorld(files, describe: describe);
        long beforeSecond = GC.GetTotalMemory(forceFullCollection: true);
        second.LoadLandblock(landblock);
        long warmHeld = GC.GetTotalMemory(forceFullCollection: true) - beforeSecond;
        Console.WriteLine($"  bytes held, cache cold                    {withCache / 1024.0,9:F1} KB (the world's cells and objects and the converted models)");
        Console.WriteLine($"  bytes held, cache warm                    {warmHeld / 1024.0,9:F1} KB (a second world sharing the models)");

        // The first transition after a load against the following ones (the same move each time).
        var firstMoves = new double[runs];
        var nextMoves = new double[runs];
        for (int i = 0; i < runs; i++)
        {
            var world = new DatWorld(files, describe: describe);
            world.LoadLandblock(landblock);
            var engine = new PhysicsEngine(world.World);
            long t0 = Stopwatch.GetTimestamp();
            engine.Resolve(run.Mover, run.Start, target);
            long t1 = Stopwatch.GetTimestamp();
            for (int k = 0; k < 10; k++)
                engine.Resolve(run.Mover, run.Start, target);
            long t2 = Stopwatch.GetTimestamp();
            firstMoves[i] = Stopwatch.GetElapsedTime(t0, t1).TotalMicroseconds;
            nextMoves[i] = Stopwatch.GetElapsedTime(t1, t2).TotalMicroseconds / 10;
        }
        Console.WriteLine($"  first transition after a load, steady state {Median(firstMoves),7:F2} µs median; the next ones {Median(nextMoves):F2} µs");
        GC.KeepAlive(held);
        GC.KeepAlive(second);

        // A runner at 9.5 m/s crosses a landblock (192 m) every 20.2 s and then needs a new row of 3 loaded and 3 unloaded.
        double row = 3 * (Percentile(cold, 0.9) + Median(unload));
        double budget = 192.0 / 9.5 * 1000.0;
        double firstRow = 3 * (Percentile(startup, 0.9) + Median(unload));
        Console.WriteLine($"  streaming at a run: a row of 3 landblocks (cold p90 + unload) {row:F3} ms every {budget / 1000.0:F1} s: " +
            $"{row / budget * 100.0:F4} % of the time; one frame at 60 Hz is 16.7 ms ({row / 16.7 * 100.0:F1} % of one frame for the whole row; " +
            $"right after start-up, at loads 2-{StartupLoads + 1}'s p90, {firstRow:F3} ms, {firstRow / 16.7 * 100.0:F1} %)");
        files.Dispose();
        return 0;
    }

    /// <summary>
    /// Runs cold and warm loads and moves in rounds with pauses until the code has tiered up: at least
    /// <see cref="MinWarmUpSeconds"/> and no method compiled in the last <see cref="SettledRounds"/> rounds (at most
    /// <see cref="MaxWarmUpSeconds"/>). .NET first compiles a method quickly, unoptimized (tier 0); it counts a
    /// method's calls only once no method has been compiled for 100 ms, and after 30 counted calls recompiles it in
    /// the background, often in two steps (an instrumented version first, then the optimized one). A load calls much
    /// of its code (the unpacking of each DAT type, the conversions) once or a few times, so a short burst of loads
    /// runs it unoptimized; the pauses let the counting start and the background compiles finish, as a client that
    /// streams a landblock every few seconds lets them. On the 2-core test machine under load, the load's own
    /// <c>DatWorld</c> reading reached its optimized code only after about 3.5 s of these rounds.
    /// </summary>
    /// <returns>The seconds spent, the rounds run, the methods compiled during it and in its last rounds (0 when settled).</returns>
    private static (double Seconds, int Rounds, long CompiledDuring, long CompiledLast) WarmUp(DatFiles files, DatObjectDescriber describe, uint landblock, ParityRun run, Position target)
    {
        var clock = Stopwatch.StartNew();
        long start = System.Runtime.JitInfo.GetCompiledMethodCount();
        var counts = new long[SettledRounds]; // a ring: the count after each of the last rounds, start first
        Array.Fill(counts, -1);
        counts[0] = start;
        for (int rounds = 1; ; rounds++)
        {
            for (int i = 0; i < RoundCycles; i++)
            {
                files.Converted.Clear();
                Cycle(files, describe, landblock);
                Cycle(files, describe, landblock);
                var world = new DatWorld(files, describe: describe);
                world.LoadLandblock(landblock);
                new PhysicsEngine(world.World).Resolve(run.Mover, run.Start, target);
            }
            Thread.Sleep(PauseMs);
            long now = System.Runtime.JitInfo.GetCompiledMethodCount();
            long oldest = counts[rounds % counts.Length];
            counts[rounds % counts.Length] = now;
            double seconds = clock.Elapsed.TotalSeconds;
            // With tiered compilation off nothing is recompiled, and DatReaderWriter's reflection stub (it makes each
            // Setup's placement frames through Activator.CreateInstance) is compiled again every round or so.
            bool settled = TieredCompilationOff || (oldest >= 0 && now == oldest);
            if ((seconds >= MinWarmUpSeconds && settled) || seconds >= MaxWarmUpSeconds)
                return (seconds, rounds, now - start, oldest >= 0 ? now - oldest : now - start);
        }
    }

    private static (double LoadMs, double UnloadMs) Cycle(DatFiles files, DatObjectDescriber describe, uint landblock)
    {
        var world = new DatWorld(files, describe: describe);
        long t0 = Stopwatch.GetTimestamp();
        world.LoadLandblock(landblock);
        long t1 = Stopwatch.GetTimestamp();
        world.UnloadLandblock(landblock);
        long t2 = Stopwatch.GetTimestamp();
        return (Stopwatch.GetElapsedTime(t0, t1).TotalMilliseconds, Stopwatch.GetElapsedTime(t1, t2).TotalMilliseconds);
    }

    private static void Write(string folder, WorldDat dat)
    {
        var region = new DatReaderWriter.DBObjs.Region
        {
            Id = DatWorld.RegionId, LandDefs = dat.LandDefs, GameTime = new GameTime(),
            TerrainInfo = new TerrainDesc { LandSurfaces = new LandSurf { TexMerge = new TexMerge() } },
        };
        WriteFile(Path.Combine(folder, DatFiles.PortalFileName), DatFileType.Portal,
            dat.GfxObjs.Cast<DBObj>().Concat(dat.Setups).Concat(dat.Environments).Append(region));
        WriteFile(Path.Combine(folder, DatFiles.CellFileName), DatFileType.Cell,
            dat.LandBlocks.Cast<DBObj>().Concat(dat.Infos).Concat(dat.EnvCells));
    }

    private static void WriteFile(string path, DatFileType type, IEnumerable<DBObj> objects)
    {
        using var db = new DatDatabase(o => { o.FilePath = path; o.AccessType = DatAccessType.ReadWrite; });
        db.BlockAllocator.InitNew(type, 0);
        foreach (var obj in objects)
            if (!db.TryWriteFile(obj).Success)
                throw new InvalidOperationException($"cannot write 0x{obj.Id:X8}");
    }

    private static double Median(double[] values) => Percentile(values, 0.5);

    private static double Percentile(double[] values, double p)
    {
        var sorted = values.OrderBy(v => v).ToArray();
        return sorted[Math.Min(sorted.Length - 1, (int)(p * sorted.Length))];
    }

    private static string? FindSharedFile(string folder, string file)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.FullName, "shared", folder, file);
            if (File.Exists(candidate))
                return candidate;
        }
        return null;
    }
}
