using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Checks the engine against a parity file: every mover (or approach) walks alone from its recorded
/// start state, each frame requesting its own current position plus the frame's offset (same cell label
/// and rotation), and the outcome is compared with the reference frame by frame — position, cell, contact,
/// walkable, sliding, accepted and the objects hit, plus the contact plane and its cell when in contact
/// for the real-cell files. Thresholds: the ACE door file must match to the last bit; every other file
/// within <see cref="Tolerance"/> on every frame, with every flag equal.
/// </summary>
public static class ParityCheck
{
    /// <summary>The position tolerance of every file but the bit-identical one, in metres.</summary>
    public const double Tolerance = 1e-4;

    /// <summary>Reads and checks one file (gzip JSON).</summary>
    /// <param name="path">The file.</param>
    /// <param name="progress">Called after each run with the runs done and the total (for progress output).</param>
    /// <exception cref="Scenes.SceneFormatException">The file is malformed; the message names the JSON path.</exception>
    /// <exception cref="System.IO.IOException">The file cannot be read.</exception>
    public static ParityReport CheckFile(string path, Action<int, int>? progress = null)
    {
        var set = ParityReader.ReadFile(path);
        if (set.Positions is { } positions)
            return PositionManagerParityCheck.Check(positions);
        if (set.MoveTo is not null)
            return MoveToParityCheck.Check(set);
        return set.Motion is not null ? MotionParityCheck.Check(set.Motion) : Check(set, progress);
    }

    /// <summary>
    /// Checks every <c>*.json.gz</c> in <paramref name="directory"/> (sorted by name): one short line per file on
    /// <paramref name="stdout"/> (<see cref="ParityReport.Summary"/>); a malformed file is one line on <paramref name="stderr"/>
    /// naming the file and the JSON path. Progress goes to <paramref name="stderr"/> when a file takes more than a few seconds.
    /// </summary>
    /// <returns>0 when every file passes, 1 when a file misses its threshold, 2 when a file is malformed or
    /// the directory holds none (2 wins over 1).</returns>
    public static int CheckDirectory(string directory, TextWriter stdout, TextWriter stderr) =>
        CheckDirectory(directory, stdout, stderr, verbose: false);

    /// <summary>
    /// As <see cref="CheckDirectory(string, TextWriter, TextWriter)"/>; with <paramref name="verbose"/> each file's
    /// line carries every detail (<see cref="ParityReport.ToString"/>: the named departures, notes and percentages).
    /// </summary>
    /// <returns>0 when every file passes, 1 when a file misses its threshold, 2 when a file is malformed or
    /// the directory holds none (2 wins over 1).</returns>
    public static int CheckDirectory(string directory, TextWriter stdout, TextWriter stderr, bool verbose)
    {
        ArgumentNullException.ThrowIfNull(directory);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        if (!Directory.Exists(directory))
        {
            stderr.WriteLine($"acdream-physics: {directory}: no such directory");
            return 2;
        }
        var files = Directory.GetFiles(directory, "*.json.gz");
        Array.Sort(files, StringComparer.Ordinal);
        if (files.Length == 0)
        {
            stderr.WriteLine($"acdream-physics: {directory}: holds no *.json.gz parity file");
            return 2;
        }
        int exit = 0;
        foreach (string file in files)
        {
            string name = Path.GetFileName(file);
            var clock = Stopwatch.StartNew();
            long lastReport = 0;
            try
            {
                var report = CheckFile(file, (done, total) =>
                {
                    long ms = clock.ElapsedMilliseconds;
                    if (ms >= 3000 && ms - lastReport >= 3000 && done < total)
                    {
                        lastReport = ms;
                        stderr.WriteLine($"{name}: {done} of {ParityReport.Count(total, "run")} ({ms / 1000} s)");
                    }
                });
                stdout.WriteLine(verbose ? report.ToString() : report.Summary());
                if (!report.Passed) exit = Math.Max(exit, 1);
            }
            catch (SceneFormatException ex)
            {
                stderr.WriteLine($"acdream-physics: {name}: {(ex.JsonPath.Length == 0 ? "(file)" : ex.JsonPath)}: {ex.Detail}");
                exit = 2;
            }
            catch (IOException ex)
            {
                stderr.WriteLine($"acdream-physics: {name}: {ex.Message}");
                exit = 2;
            }
        }
        return exit;
    }

    internal static ParityReport Check(ParitySet set, Action<int, int>? progress = null)
    {
        var engine = new PhysicsEngine(set.World);
        int frames = 0, within = 0, identical = 0, flagMismatches = 0;
        double maxDifference = 0;
        string? firstFailure = null;
        for (int r = 0; r < set.Runs.Count; r++)
        {
            var run = set.Runs[r];
            var state = run.Start;
            for (int f = 0; f < run.Frames.Length; f++)
            {
                ref readonly var expected = ref run.Frames[f];
                var target = state.Position;
                target.Frame.Origin += expected.Offset;
                MoveResult result;
                try
                {
                    result = engine.Resolve(run.Mover, state, target);
                }
                catch (ArgumentException ex)
                {
                    firstFailure ??= Describe(set, run, f, $"the engine refused the input: {ex.Message}");
                    flagMismatches += run.Frames.Length - f;
                    frames += run.Frames.Length - f;
                    break;
                }
                frames++;
                var actual = result.Next;
                var position = actual.Position.Frame.Origin;
                double difference = Distance(position, expected.Position);
                bool bitIdentical = Geometry.VectorMath.SameBits(position, expected.Position);
                maxDifference = Math.Max(maxDifference, difference);
                if (difference <= Tolerance) within++;
                if (bitIdentical) identical++;
                string? flag = FlagDifference(expected, result);
                if (flag is not null) flagMismatches++;
                if (firstFailure is null)
                {
                    if (flag is not null)
                        firstFailure = Describe(set, run, f, flag);
                    else if (set.RequireBitIdentical ? !bitIdentical : !(difference <= Tolerance))
                        firstFailure = Describe(set, run, f, string.Format(CultureInfo.InvariantCulture,
                            "position: expected {0}, actual {1} (difference {2:0.###e0} m)", Format(expected.Position), Format(position), difference));
                }
                state = actual;
            }
            progress?.Invoke(r + 1, set.Runs.Count);
        }
        return new ParityReport(set.Name, set.RequireBitIdentical, set.Runs.Count, frames, within, identical, maxDifference, flagMismatches, firstFailure);
    }

    private static string Describe(ParitySet set, ParityRun run, int frame, string what) =>
        $"{set.Name}: '{run.Name}', frame {frame}: {what}";

    // The first field that differs, described; null when every compared field agrees.
    private static string? FlagDifference(in ParityFrame e, in MoveResult result)
    {
        var a = result.Next;
        if (a.Position.CellId != e.Cell) return $"cell: expected 0x{e.Cell:X8}, actual 0x{a.Position.CellId:X8}";
        if (a.Contact != e.Contact) return $"contact: expected {e.Contact}, actual {a.Contact}";
        if (a.OnWalkable != e.Walkable) return $"walkable: expected {e.Walkable}, actual {a.OnWalkable}";
        if (a.SlidingNormalValid != e.Sliding) return $"sliding: expected {e.Sliding}, actual {a.SlidingNormalValid}";
        if (result.Succeeded != e.Accepted) return $"accepted: expected {e.Accepted}, actual {result.Succeeded}";
        var hits = result.CollidedObjects.Span;
        if (!hits.SequenceEqual(e.Hits)) return $"hits: expected [{Ids(e.Hits)}], actual [{Ids(hits)}]";
        if (e.HasContactPlane)
        {
            if (a.ContactPlaneCellId != e.ContactPlaneCell)
                return $"contact plane cell: expected 0x{e.ContactPlaneCell:X8}, actual 0x{a.ContactPlaneCellId:X8}";
            if (!SamePlane(a.ContactPlane, e.ContactPlane))
                return $"contact plane: expected {Format(e.ContactPlane)}, actual {Format(a.ContactPlane)}";
        }
        return null;
    }

    /// <summary>The normal's largest component difference a contact plane may show and still be "equal".</summary>
    public const float PlaneNormalTolerance = 1e-6f;

    // Equal within the last bits: ACE turns a polygon's plane into landblock space through the quaternion,
    // retail (and the engine) through the frame's matrix, so a plane of a rotated cell or object can
    // differ in the normal's last bit (0.99999994 against 1) and the offset's (one float step at 90 m).
    private static bool SamePlane(in Plane a, in Plane b) =>
        MathF.Abs(a.Normal.X - b.Normal.X) <= PlaneNormalTolerance
        && MathF.Abs(a.Normal.Y - b.Normal.Y) <= PlaneNormalTolerance
        && MathF.Abs(a.Normal.Z - b.Normal.Z) <= PlaneNormalTolerance
        && Math.Abs((double)a.D - b.D) <= Tolerance;

    private static double Distance(Vector3 a, Vector3 b)
    {
        double dx = (double)a.X - b.X, dy = (double)a.Y - b.Y, dz = (double)a.Z - b.Z;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    private static string Ids(ReadOnlySpan<uint> ids)
    {
        var parts = new string[ids.Length];
        for (int i = 0; i < ids.Length; i++)
            parts[i] = $"0x{ids[i]:X8}";
        return string.Join(", ", parts);
    }

    private static string F(float v) => v.ToString("R", CultureInfo.InvariantCulture);
    private static string Format(Vector3 v) => $"({F(v.X)}, {F(v.Y)}, {F(v.Z)})";
    private static string Format(Plane p) => $"({F(p.Normal.X)}, {F(p.Normal.Y)}, {F(p.Normal.Z)}, {F(p.D)})";
}
