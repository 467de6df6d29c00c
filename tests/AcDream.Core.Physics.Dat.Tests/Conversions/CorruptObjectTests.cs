using System.Buffers.Binary;
using System.Diagnostics;
using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;
using DatReaderWriter;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using System.Threading.Tasks;
using DatReaderWriter.Lib.IO;
using DatReaderWriter.Options;
using Xunit.Abstractions;

namespace AcDream.Core.Physics.Dat.Tests.Conversions;

/// <summary>
/// DAT files whose object bytes are damaged: the cottage written once, then per case one object of either file
/// rewritten with its bytes flipped, a dword overwritten with a huge count or truncated, and its landblock loaded.
/// Each case must end in a whole load or a refusal naming the DAT file and the object (a <see cref="DatReadException"/>
/// or <see cref="DatObjectException"/>, or the world's own <see cref="ArgumentException"/> when it refuses what a
/// damaged object converted to), within a time limit, with the world as it was. A case that ends otherwise fails
/// the test naming its seed, object, mutation and offset, so it can be replayed alone.
/// </summary>
public class CorruptObjectTests
{
    private const int Seed = 20261206, Cases = 1200;
    private static readonly TimeSpan PerCase = TimeSpan.FromSeconds(5);
    // A clean landblock loaded before each damaged one: a refused load must leave it, and nothing else, in the world.
    private const uint Neighbour = 0x0101;

    private readonly ITestOutputHelper _output;

    public CorruptObjectTests(ITestOutputHelper output) => _output = output;

    private enum Mutation { FlipBytes, HugeDword, Truncate }

    // The fields of the world's refusals of a reference to a cell that is not there (each message also names the cell).
    private static readonly string[] WorldReferences = [".otherCell: cell 0x", "building.entranceCells: 0x", ".position.cell: unknown cell 0x"];

    private static readonly uint[] HugeValues = [0x7FFF_FFFF, 0xFFFF_FFFF, 0x0001_0000, 0x8000_0000];

    /// <param name="HookEnd">For a Setup, the bytes up to the end of its placement frames' hook count, which this
    /// test leaves alone (docs/robustness.md, "DAT files": DatReaderWriter's unknown-hook loop); 0 for other objects.</param>
    private sealed record Target(bool Cell, uint Id, byte[] Bytes, int HookEnd = 0);

    [Fact]
    public void DamagedObjects_AreLoadedWholeOrRefusedNamingTheFileAndObject_AndTheWorldIsUnchanged()
    {
        var dat = WorldDat.From(SceneLibrary.Load("cottage").World);
        uint landblock = Assert.Single(dat.Landblocks);
        using var clean = new TempDats(
            dat.GfxObjs.Cast<DBObj>().Concat(dat.Setups).Concat(dat.Environments).Append(WorldWriter.Region(dat.LandDefs)),
            dat.LandBlocks.Cast<DBObj>().Concat(dat.Infos).Concat(dat.EnvCells).Append(WorldWriter.Land(Neighbour)));
        var targets = Targets(clean, dat);
        var rng = new Random(Seed);
        var outcomes = new Dictionary<string, int>();
        var failures = new List<string>();
        var clock = Stopwatch.StartNew();
        for (int n = 0; n < Cases; n++)
        {
            var target = targets[rng.Next(targets.Count)];
            var mutation = (Mutation)rng.Next(3);
            var (bytes, length, offset, lowest) = Damage(target.Bytes, mutation, rng);
            if (lowest < target.HookEnd)
            {
                // The documented limit: a damaged Setup head can have DatReaderWriter read a placement frame's hook
                // count over bytes that are no hook, and its loop then adds nothing-read hooks until memory runs out.
                outcomes["skipped: Setup head (documented limit)"] = outcomes.GetValueOrDefault("skipped: Setup head (documented limit)") + 1;
                continue;
            }
            string name = $"case {n} (seed {Seed}): {(target.Cell ? DatFiles.CellFileName : DatFiles.PortalFileName)} 0x{target.Id:X8}, {mutation} at {offset} of {target.Bytes.Length} bytes";
            string outcome = Run(clean, dat, landblock, target, bytes, length, name, failures);
            outcomes[outcome] = outcomes.GetValueOrDefault(outcome) + 1;
        }
        foreach (var (outcome, count) in outcomes.OrderBy(o => o.Key, StringComparer.Ordinal))
            _output.WriteLine($"{count,5} {outcome}");
        _output.WriteLine($"{Cases} cases in {clock.Elapsed.TotalSeconds:F1} s");
        Assert.True(failures.Count == 0, $"{failures.Count} of {Cases} damaged objects were not refused cleanly:\n" + string.Join("\n", failures.Take(20)));
        // The mutations reach the reader: some damaged objects are refused, some still load.
        Assert.True(outcomes.GetValueOrDefault("loaded") > 0 && outcomes.Keys.Any(k => k.StartsWith("DatReadException", StringComparison.Ordinal)),
            string.Join(", ", outcomes.Select(o => $"{o.Key}: {o.Value}")));
    }

    // Every object the cottage's load reads, with its clean bytes.
    private static List<Target> Targets(TempDats clean, WorldDat dat)
    {
        var result = new List<Target>();
        using (var portal = OpenRaw(clean.PortalPath, DatAccessType.Read))
            foreach (uint id in dat.GfxObjs.Select(o => o.Id).Concat(dat.Setups.Select(o => o.Id)).Concat(dat.Environments.Select(o => o.Id)).Append(DatWorld.RegionId))
                result.Add(new Target(false, id, Bytes(portal, id), HookEnd(dat.Setups.Find(s => s.Id == id))));
        using (var cell = OpenRaw(clean.CellPath, DatAccessType.Read))
            foreach (uint id in dat.LandBlocks.Select(o => o.Id).Concat(dat.Infos.Select(o => o.Id)).Concat(dat.EnvCells.Select(o => o.Id)))
                result.Add(new Target(true, id, Bytes(cell, id)));
        return result;
    }

    // Where a Setup as the writer makes it ends its placement frames' hook count: id, flags, part count, the parts,
    // their default scales, the (empty) holding and connection locations, the placement count; then, when it has
    // parts, the one placement's key, a frame (origin and rotation) per part and the hook count.
    private static int HookEnd(Setup? setup)
    {
        if (setup is null)
            return 0;
        int parts = setup.Parts.Count, scales = setup.Flags.HasFlag(SetupFlags.HasDefaultScale) ? parts : 0;
        int head = 4 + 4 + 4 + 4 * parts + 12 * scales + 4 + 4 + 4;
        return parts == 0 ? head : head + 4 + 28 * parts + 4;
    }

    private static byte[] Bytes(DatDatabase database, uint id) =>
        database.TryGetFileBytes(id, out var bytes) ? bytes : throw new InvalidOperationException($"0x{id:X8} is not in {database.Options.FilePath}.");

    private static DatDatabase OpenRaw(string path, DatAccessType access) => new(o =>
    {
        o.FilePath = path;
        o.AccessType = access;
        o.FileCachingStrategy = FileCachingStrategy.Never;
    });

    // The damaged bytes, how many of them the object keeps, where the damage starts and the lowest byte changed
    // (a truncation changes none).
    private static (byte[] Bytes, int Length, int Offset, int Lowest) Damage(byte[] clean, Mutation mutation, Random rng)
    {
        var bytes = (byte[])clean.Clone();
        switch (mutation)
        {
            case Mutation.FlipBytes:
            {
                int first = rng.Next(bytes.Length), count = 1 + rng.Next(4), lowest = first;
                for (int i = 0; i < count; i++)
                {
                    int at = i == 0 ? first : rng.Next(bytes.Length);
                    bytes[at] ^= (byte)(1 + rng.Next(255));
                    lowest = Math.Min(lowest, at);
                }
                return (bytes, bytes.Length, first, lowest);
            }
            case Mutation.HugeDword:
            {
                int at = rng.Next(bytes.Length / 4) * 4;
                BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(at), HugeValues[rng.Next(HugeValues.Length)]);
                return (bytes, bytes.Length, at, at);
            }
            default:
            {
                int length = rng.Next(bytes.Length);
                return (bytes, length, length, int.MaxValue);
            }
        }
    }

    private string Run(TempDats clean, WorldDat dat, uint landblock, Target target, byte[] bytes, int length, string name, List<string> failures)
    {
        string folder = Path.Combine(Path.GetTempPath(), "acdream-datfuzz-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        try
        {
            string portal = Path.Combine(folder, DatFiles.PortalFileName), cell = Path.Combine(folder, DatFiles.CellFileName);
            File.Copy(clean.PortalPath, portal);
            File.Copy(clean.CellPath, cell);
            using (var raw = OpenRaw(target.Cell ? cell : portal, DatAccessType.ReadWrite))
            {
                Assert.True(raw.Tree.TryGetFile(target.Id, out var entry));
                var written = raw.TryWriteFileBytes(target.Id, bytes, length, entry);
                Assert.True(written.Success, written.Error);
            }
            using var files = DatFiles.Open(folder);
            var loader = DatPath.Loader(files, dat);
            // The Region is read by a world's first load, so a damaged Region is met with the world still empty.
            bool neighbour = target.Id != DatWorld.RegionId;
            if (neighbour)
                loader.LoadLandblock(Neighbour);
            var cellsBefore = loader.World.Cells.CellIds.Order().ToList();
            int objectsBefore = loader.World.Objects.Count;
            Exception? error = null;
            bool adding = false;
            var task = Task.Run(() =>
            {
                var block = loader.Read(landblock);
                adding = true;
                loader.Add(block);
            });
            try
            {
                if (!task.Wait(PerCase))
                {
                    failures.Add($"{name}: still loading after {PerCase.TotalSeconds} s");
                    return "hang";
                }
            }
            catch (AggregateException ex)
            {
                error = ex.InnerException;
            }
            if (error is null)
                return "loaded";
            string file = target.Cell ? DatFiles.CellFileName : DatFiles.PortalFileName;
            bool named = error switch
            {
                DatReadException read => read.File.Length > 0 && read.ObjectId is not null && error.Message.Contains($"0x{read.ObjectId:X8}", StringComparison.Ordinal),
                DatObjectException refused => refused.File is not null && error.Message.Contains($"0x{refused.ObjectId:X8}", StringComparison.Ordinal),
                // The world's own refusal, when the landblock is added, of what refers to a cell not there (an env
                // cell's portal, a building's entrance, an object placed over an unloaded neighbour): it names the cell.
                ArgumentException world => adding && WorldReferences.Any(r => world.Message.Contains(r, StringComparison.Ordinal)),
                _ => false,
            };
            if (!named)
                failures.Add($"{name}: {error.GetType().Name}: {error.Message}");
            else if (!cellsBefore.SequenceEqual(loader.World.Cells.CellIds.Order()) || loader.World.Objects.Count != objectsBefore
                || !loader.Loaded.SequenceEqual(neighbour ? [Neighbour] : []))
                failures.Add($"{name}: {error.GetType().Name} left the world changed: {error.Message}");
            return named ? error.GetType().Name : "other: " + error.GetType().Name;
        }
        finally
        {
            try { Directory.Delete(folder, recursive: true); } catch (IOException) { }
        }
    }
}
