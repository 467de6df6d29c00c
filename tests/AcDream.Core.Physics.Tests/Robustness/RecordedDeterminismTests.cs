using System.Globalization;
using System.IO;
using System.Runtime.InteropServices;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Determinism against committed data, on every architecture: each built-in scene's movers against
/// recorded per-mover hashes (a difference is localized by replaying the committed trajectory exactly),
/// and each fuzz area's cases against recorded per-frame values (a difference names the case, frame and
/// field). Data lives in Robustness/Determinism/, one file per scene or area and architecture; an
/// architecture with no file of its own is compared with X64's. Record (after a deliberate change, or for
/// a new architecture) with ACDREAM_RECORD_DETERMINISM=1 and commit the files (docs/robustness.md).
/// </summary>
public class RecordedDeterminismTests
{
    public static TheoryData<string> AreaNames()
    {
        var data = new TheoryData<string>();
        foreach (var a in DeterminismRecord.Areas) data.Add(a.Name);
        return data;
    }

    private static string Arch => RuntimeInformation.ProcessArchitecture.ToString();
    private static bool Recording => Environment.GetEnvironmentVariable("ACDREAM_RECORD_DETERMINISM") == "1";
    private static readonly string DataDirectory = Path.Combine(AppContext.BaseDirectory, "Robustness", "Determinism");

    private static string SourceDataDirectory()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "AcDream.sln")))
                return Path.Combine(dir.FullName, "tests", "AcDream.Core.Physics.Tests", "Robustness", "Determinism");
        throw new InvalidOperationException("recording: the repository root (AcDream.sln) was not found above the test binaries");
    }

    /// <summary>The committed lines for a file stem on this architecture (falling back to X64), and which file they came from.</summary>
    private static (string[] Lines, string File) Load(string stem, List<string> produced)
    {
        if (Recording)
        {
            string dir = SourceDataDirectory();
            Directory.CreateDirectory(dir);
            string path = Path.Combine(dir, $"{stem}.{Arch}.txt");
            File.WriteAllText(path, string.Join("\n", produced) + "\n");
            return (produced.ToArray(), path);
        }
        foreach (string arch in new[] { Arch, "X64" })
        {
            string path = Path.Combine(DataDirectory, $"{stem}.{arch}.txt");
            if (File.Exists(path))
                return (File.ReadAllLines(path).Where(l => l.Length > 0).ToArray(), Path.GetFileName(path));
        }
        throw new Xunit.Sdk.XunitException($"no recorded determinism data for '{stem}'; record it with ACDREAM_RECORD_DETERMINISM=1 (docs/robustness.md)");
    }

    private static string ArchNote(string file) => file.Contains($".{Arch}.", StringComparison.Ordinal) ? ""
        : $" (no data recorded for {Arch}; compared with {file}. If {Arch} legitimately differs in the last bits, record its own files with ACDREAM_RECORD_DETERMINISM=1 and commit them)";

    /// <summary>The first difference between a committed frame line and the produced one, in field order; null when equal.</summary>
    internal static string? FirstDifference(string expected, string actual)
    {
        var e = expected.Split('\t');
        var a = actual.Split('\t');
        if (e[0] != a[0] || e[1] != a[1])
            return $"case/frame: expected case seed {e[0]} frame {e[1]}, actual case seed {a[0]} frame {a[1]} (the generator or the frame count changed)";
        var ev = e[2].Split(' ');
        var av = a[2].Split(' ');
        for (int i = 0; i < DeterminismRecord.FieldNames.Length; i++)
            if (ev[i] != av[i])
                return $"case seed {e[0]} (SceneFuzzer.Make), frame {e[1]}, field {DeterminismRecord.FieldNames[i]}: expected 0x{ev[i]} ({Show(DeterminismRecord.FieldNames[i], ev[i])}), actual 0x{av[i]} ({Show(DeterminismRecord.FieldNames[i], av[i])})";
        if (e[3] != a[3])
            return $"case seed {e[0]} (SceneFuzzer.Make), frame {e[1]}, field collided: expected [{e[3]}], actual [{a[3]}]";
        return null;
    }

    private static string Show(string field, string hex)
    {
        uint v = uint.Parse(hex, NumberStyles.HexNumber, CultureInfo.InvariantCulture);
        bool isFloat = field.Contains('.') && !field.EndsWith(".valid", StringComparison.Ordinal) && field != "contactPlane.cell";
        return isFloat ? BitConverter.UInt32BitsToSingle(v).ToString("R", CultureInfo.InvariantCulture) : v.ToString(CultureInfo.InvariantCulture);
    }

    [Theory]
    [MemberData(nameof(AreaNames))]
    public void FuzzArea_ResolvesEveryFrameAsRecorded(string name)
    {
        var area = DeterminismRecord.Areas.Single(a => a.Name == name);
        var produced = DeterminismRecord.AreaLines(area);
        var (recorded, file) = Load($"area.{name}", produced);
        for (int i = 0; i < Math.Min(recorded.Length, produced.Count); i++)
        {
            var d = FirstDifference(recorded[i], produced[i]);
            if (d is not null)
                Assert.Fail($"area '{name}' ({area.Features}, run seed {area.Seed}): {d}{ArchNote(file)}");
        }
        Assert.True(recorded.Length == produced.Count, $"area '{name}': {produced.Count} frames produced, {recorded.Length} recorded{ArchNote(file)}");
        Assert.True(produced.Count >= DeterminismRecord.CasesPerArea, $"area '{name}': only {produced.Count} frames");
    }

    [Theory]
    [MemberData(nameof(SceneFiles.ReplayTests.BuiltInScenes), MemberType = typeof(SceneFiles.ReplayTests))]
    public void BuiltInScene_EveryMoverMatchesItsRecordedHash(string name)
    {
        var scene = SceneLibrary.Load(name);
        var produced = DeterminismRecord.SceneLines(name);
        var (recorded, file) = Load($"scene.{name}", produced);
        Assert.True(recorded.Length == produced.Count, $"scene '{name}': {produced.Count} movers, {recorded.Length} recorded{ArchNote(file)}");
        for (int m = 0; m < produced.Count; m++)
        {
            if (recorded[m] == produced[m])
                continue;
            // Localize: replay the committed trajectory exactly (tolerance 0) to find the first differing field.
            string replay = Path.Combine(AppContext.BaseDirectory, "Replays", name + ".trajectory.json");
            string where = "no committed trajectory to localize it";
            if (File.Exists(replay))
            {
                var result = TrajectoryReplay.Replay(scene, Trajectory.LoadFile(replay), SceneFiles.ReplayTests.Exact);
                where = result.Matches
                    ? "the committed trajectory still replays exactly, so the difference is in a field it does not record (orientation or collidedWithEnvironment)"
                    : $"first exact difference from the committed trajectory: {result.FirstDifference}";
            }
            Assert.Fail($"scene '{name}', mover #{m}: expected '{recorded[m]}', actual '{produced[m]}'; {where}{ArchNote(file)}");
        }
    }

    [Fact]
    public void AnAlteredRecord_IsReported_WithCaseFrameAndField()
    {
        var line = DeterminismRecord.AreaLines(DeterminismRecord.Areas[0])[0];
        var parts = line.Split('\t');
        var values = parts[2].Split(' ');
        values[2] = (uint.Parse(values[2], NumberStyles.HexNumber, CultureInfo.InvariantCulture) ^ 1u).ToString("X8", CultureInfo.InvariantCulture); // origin.y, last bit
        var altered = $"{parts[0]}\t{parts[1]}\t{string.Join(' ', values)}\t{parts[3]}";
        var d = FirstDifference(altered, line);
        Assert.NotNull(d);
        Assert.Contains($"case seed {parts[0]}", d);
        Assert.Contains("frame 0, field origin.y", d);
        Assert.Null(FirstDifference(line, line));
    }
}
