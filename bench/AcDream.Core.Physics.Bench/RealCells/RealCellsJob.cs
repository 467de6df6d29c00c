using System.Globalization;
using System.IO;
using System.Text;
using System.IO.Compression;
using System.Text.Json;
using System.Text.Json.Nodes;
using AcDream.Core.Physics.Bench.Benchmarks;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Bench.RealCells;

/// <summary>
/// The real-cells job: the cost per resolve on real Holtburg cells (the shared real-cells set), next to
/// the door, with each model's physics BSP as shipped in the set (every polygon in one leaf) and as
/// <see cref="BspCompiler"/> builds it from the same polygons; and whether the compiled trees change
/// any result. Skips with a message (exit 0) when the shared folder is absent.
/// </summary>
public static class RealCellsJob
{
    private const double Tolerance = 1e-4;

    /// <summary>Runs the job: <c>realcells [--dir DIR] [--out DIR]</c>.</summary>
    public static int Run(string[] args)
    {
        string? dir = null;
        string outDir = Path.Combine("out", "realcells");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--dir" && i + 1 < args.Length) dir = args[++i];
            else if (args[i] == "--out" && i + 1 < args.Length) outDir = args[++i];
            else { Console.Error.WriteLine($"realcells: unknown argument '{args[i]}' (usage: realcells [--dir DIR] [--out DIR])"); return 2; }
        }
        dir ??= FindSharedFolder();
        if (dir is null || !Directory.Exists(dir))
        {
            Console.WriteLine("realcells: no shared/real-cells folder found beside the repository; skipped.");
            return 0;
        }

        var door = DoorScene.Create();
        var doorEngine = new PhysicsEngine(door.World);
        var doorStart = DoorWorkloads.TransitionStart;
        var doorTarget = doorStart.Position;
        doorTarget.Frame.Origin = DoorWorkloads.TransitionTarget;
        Action<int> doorRun = n => { for (int i = 0; i < n; i++) doorEngine.Resolve(DoorScene.Player, doorStart, doorTarget); };

        var files = new List<FileRun>();
        foreach (string path in Directory.GetFiles(dir, "*.json.gz").OrderBy(p => p, StringComparer.Ordinal))
        {
            var set = ParityReader.ReadFile(path);
            string name = Path.GetFileName(path).Replace(".json.gz", "", StringComparison.Ordinal);
            string text = File.ReadAllText(Path.Combine(dir, "scenes", SceneFileOf(path)));
            var compiled = SceneLoader.Load(WithCompiledTrees(text), name);
            var run = Compare(name, set, compiled);
            files.Add(run);
            Console.WriteLine($"{name}: compared ({run.Row.Frames} frames)");
        }

        // Timing in rounds, every workload once per round, keeping each one's fastest: the machine is shared,
        // and interleaving spreads a busy spell over all of them instead of one.
        double doorNs = double.PositiveInfinity;
        for (int round = 0; round < Rounds; round++)
        {
            doorNs = Math.Min(doorNs, DoorJob.Measure(doorRun, 1, 0.2));
            foreach (var run in files)
                run.Time();
            Console.WriteLine($"timing round {round + 1} of {Rounds} done");
        }
        var rows = files.Select(f => f.Row).ToList();
        foreach (var row in rows)
            Console.WriteLine(row.Line());

        string report = Report(rows, doorNs);
        Directory.CreateDirectory(outDir);
        File.WriteAllText(Path.Combine(outDir, "realcells.md"), report);
        Console.WriteLine();
        Console.WriteLine(report);
        return 0;
    }

    /// <summary>
    /// The real-cells folder: <c>shared/real-cells</c> beside the repository (or beside any folder above the
    /// current directory), or null when there is none.
    /// </summary>
    public static string? FindSharedFolder()
    {
        for (var dir = new DirectoryInfo(Directory.GetCurrentDirectory()); dir is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.FullName, "shared", "real-cells");
            if (Directory.Exists(candidate))
                return candidate;
        }
        return null;
    }

    /// <summary>The scene file a reference file's header names.</summary>
    private static string SceneFileOf(string path)
    {
        using var stream = new GZipStream(File.OpenRead(path), CompressionMode.Decompress);
        using var doc = JsonDocument.Parse(stream);
        return doc.RootElement.GetProperty("scene").GetString()!;
    }

    /// <summary>The scene text with every physics model's explicit tree dropped, so the loader compiles it (containment trees are kept).</summary>
    public static string WithCompiledTrees(string sceneText)
    {
        var root = JsonNode.Parse(sceneText)!.AsObject();
        if (root["models"] is JsonObject models)
            foreach (var (_, model) in models)
                if (model is JsonObject m && m["nodes"] is not null && m["polygons"] is JsonArray polygons && polygons.Count > 0)
                    m.Remove("nodes");
        return root.ToJsonString();
    }

    private const int Rounds = 3;

    private sealed class Row(string file, int movers, int frames, int shippedWithin, int compiledWithin, int compiledSame, double compiledMaxDiff)
    {
        public string File { get; } = file;
        public int Movers { get; } = movers;
        public int Frames { get; } = frames;
        public double ShippedNs { get; set; } = double.PositiveInfinity;
        public double CompiledNs { get; set; } = double.PositiveInfinity;
        public int ShippedWithin { get; } = shippedWithin;
        public int CompiledWithin { get; } = compiledWithin;
        public int CompiledSame { get; } = compiledSame;
        public double CompiledMaxDiff { get; } = compiledMaxDiff;

        public string Line() => string.Create(CultureInfo.InvariantCulture,
            $"{File}: {Movers} movers, {Frames} frames; one leaf {ShippedNs / 1000:F2} µs, compiled {CompiledNs / 1000:F2} µs per resolve; " +
            $"within 1e-4 of the reference: {ShippedWithin} / {CompiledWithin}; compiled identical to one leaf on {CompiledSame} frames (max {CompiledMaxDiff:E1} m)");
    }

    /// <summary>One file's comparison and its timed workload: the one-leaf run's per-frame inputs, resolved by both worlds.</summary>
    private sealed class FileRun(Row row, PhysicsEngine shipped, PhysicsEngine compiled, (MoverDescription Mover, MoverState State, Position Target)[] work)
    {
        public Row Row { get; } = row;

        public void Time()
        {
            Row.ShippedNs = Math.Min(Row.ShippedNs, DoorJob.Measure(n => Replay(shipped, work, n), work.Length, 0.25));
            Row.CompiledNs = Math.Min(Row.CompiledNs, DoorJob.Measure(n => Replay(compiled, work, n), work.Length, 0.25));
        }
    }

    private static FileRun Compare(string name, ParitySet set, Scene compiled)
    {
        var shippedEngine = new PhysicsEngine(set.World);
        var compiledEngine = new PhysicsEngine(compiled.World);
        var inputs = new List<(MoverDescription Mover, MoverState State, Position Target)>();
        int frames = 0, shippedWithin = 0, compiledWithin = 0, same = 0;
        double maxDiff = 0;
        foreach (var run in set.Runs)
        {
            var compiledDescription = compiled.Movers.First(m => m.Name == run.Name).Description;
            var a = run.Start;
            var b = run.Start;
            foreach (var frame in run.Frames)
            {
                var ta = a.Position; ta.Frame.Origin += frame.Offset;
                var tb = b.Position; tb.Frame.Origin += frame.Offset;
                inputs.Add((run.Mover, a, ta));
                var ra = shippedEngine.Resolve(run.Mover, a, ta);
                var rb = compiledEngine.Resolve(compiledDescription, b, tb);
                a = ra.Next;
                b = rb.Next;
                frames++;
                if (Matches(frame, ra)) shippedWithin++;
                if (Matches(frame, rb)) compiledWithin++;
                if (Same(ra, rb)) same++;
                maxDiff = Math.Max(maxDiff, Vector3.Distance(a.Position.Frame.Origin, b.Position.Frame.Origin));
            }
        }
        var row = new Row(name, set.Runs.Count, frames, shippedWithin, compiledWithin, same, maxDiff);
        return new FileRun(row, shippedEngine, compiledEngine, inputs.ToArray());
    }

    private static void Replay(PhysicsEngine engine, (MoverDescription Mover, MoverState State, Position Target)[] work, int times)
    {
        for (int t = 0; t < times; t++)
            foreach (var (mover, state, target) in work)
                engine.Resolve(mover, state, target);
    }

    private static bool Matches(in ParityFrame expected, in MoveResult r)
    {
        var n = r.Next;
        return Vector3.Distance(expected.Position, n.Position.Frame.Origin) <= Tolerance && expected.Cell == n.Position.CellId
            && expected.Contact == n.Contact && expected.Walkable == n.OnWalkable && expected.Sliding == n.SlidingNormalValid
            && expected.Accepted == r.Succeeded;
    }

    private static bool Same(in MoveResult a, in MoveResult b)
    {
        var x = a.Next;
        var y = b.Next;
        return a.Succeeded == b.Succeeded && x.Position.CellId == y.Position.CellId && x.Position.Frame.Origin == y.Position.Frame.Origin
            && x.Contact == y.Contact && x.OnWalkable == y.OnWalkable && x.ContactPlane == y.ContactPlane && x.ContactPlaneCellId == y.ContactPlaneCellId
            && x.SlidingNormalValid == y.SlidingNormalValid && x.SlidingNormal == y.SlidingNormal
            && a.CollidedObjects.Span.SequenceEqual(b.CollidedObjects.Span);
    }

    private static string Report(List<Row> rows, double doorNs)
    {
        var sb = new StringBuilder();
        var inv = CultureInfo.InvariantCulture;
        sb.AppendLine(string.Create(inv, $"Door transition (retail, same run): {doorNs:F0} ns."));
        sb.AppendLine();
        sb.AppendLine("| file | movers | frames | one leaf (µs/resolve) | compiled (µs/resolve) | compiled / one leaf | within 1e-4 of the reference: one leaf | compiled | compiled identical to one leaf | max distance compiled vs one leaf (m) |");
        sb.AppendLine("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var r in rows)
            sb.AppendLine(string.Create(inv,
                $"| `{r.File}` | {r.Movers} | {r.Frames:N0} | {r.ShippedNs / 1000:F2} | {r.CompiledNs / 1000:F2} | {r.CompiledNs / r.ShippedNs:F2} | {r.ShippedWithin:N0} | {r.CompiledWithin:N0} | {r.CompiledSame:N0} | {r.CompiledMaxDiff:G3} |"));
        return sb.ToString();
    }
}
