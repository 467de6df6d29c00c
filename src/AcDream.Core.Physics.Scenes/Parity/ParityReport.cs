using System.Globalization;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// The outcome of checking one parity file: how many frames agree with the reference, by how much the
/// positions differ, how many frames have a differing flag, and whether the file meets its threshold.
/// </summary>
public sealed class ParityReport
{
    internal ParityReport(string file, bool requireBitIdentical, int runs, int frames, int withinTolerance, int bitIdentical,
        double maxDifference, int flagMismatches, string? firstFailure, string? departures = null)
    {
        Departures = departures;
        File = file;
        RequireBitIdentical = requireBitIdentical;
        Runs = runs;
        Frames = frames;
        WithinTolerance = withinTolerance;
        BitIdentical = bitIdentical;
        MaxDifference = maxDifference;
        FlagMismatches = flagMismatches;
        FirstFailure = firstFailure;
    }

    /// <summary>The file's name.</summary>
    public string File { get; }
    /// <summary>The file must match to the last bit (otherwise within <see cref="ParityCheck.Tolerance"/>).</summary>
    public bool RequireBitIdentical { get; }
    /// <summary>Movers or approaches walked.</summary>
    public int Runs { get; }
    /// <summary>Frames compared.</summary>
    public int Frames { get; }
    /// <summary>Frames whose position is within <see cref="ParityCheck.Tolerance"/> of the reference.</summary>
    public int WithinTolerance { get; }
    /// <summary>Frames whose position is bit-identical to the reference.</summary>
    public int BitIdentical { get; }
    /// <summary>The largest distance between a resolved and a reference position, in metres.</summary>
    public double MaxDifference { get; }
    /// <summary>Frames where a flag, the cell, the hit list (or, for real cells, the contact plane) differs.</summary>
    public int FlagMismatches { get; }
    /// <summary>The first frame that misses the threshold, described (file, mover or approach, frame, field); null when the file passes.</summary>
    public string? FirstFailure { get; }
    /// <summary>
    /// The named ACE departures whose frames were compared with their own documented bound instead of the
    /// tolerance (docs/open-questions.md, "Differences from ACE in the motion layer"), described; null when none.
    /// </summary>
    public string? Departures { get; }
    /// <summary>The file meets its threshold.</summary>
    public bool Passed => FirstFailure is null;

    /// <summary>
    /// A line that replaces the counts for a file not compared as a whole (a named departure from the reference, or
    /// another engineer's file): it says why, and never says ok. Null for a compared file.
    /// </summary>
    internal string? Verdict { get; init; }

    /// <summary>The threshold for <see cref="Summary"/> when it is not the file's default (for example "within 1e-3 m, headings within 1e-3 deg").</summary>
    internal string? Threshold { get; init; }

    /// <summary>The named departure from the reference the file is compared under (docs/open-questions.md), for <see cref="Summary"/>.</summary>
    internal string? Departure { get; init; }

    /// <summary>The check counts bit-identical frames (the position managers' files do not).</summary>
    internal bool CountsBitIdentical { get; init; } = true;

    /// <summary>Nothing is compared: the file departs from the reference as a whole (<see cref="Verdict"/> says how).</summary>
    internal bool NothingCompared { get; init; }

    /// <summary>
    /// One short line: the file, the verdict (ok, FAIL or departs, with the threshold and the named departure), the
    /// counts, and the first failure; "(more with -v)" when <see cref="ToString"/> says more (a departure's or a
    /// note's detail).
    /// </summary>
    public string Summary()
    {
        var c = CultureInfo.InvariantCulture;
        if (NothingCompared && Passed)
            return $"{File}: departs (nothing compared) (more with -v)";
        string need = Threshold ?? (RequireBitIdentical ? "bit-identical" : $"within {ParityCheck.Tolerance.ToString("0e0", c)} m");
        string line = string.Format(c, "{0}: {1} ({2}){3}; {4}, {5}, {6} within{7}, max {8} m, {9}",
            File, Passed ? "ok" : "FAIL", need, Departure is null ? string.Empty : $" under departure {Departure}",
            Count(Runs, "run"), Count(Frames, "frame"), WithinTolerance, CountsBitIdentical ? $", {BitIdentical} bit-identical" : string.Empty,
            MaxDifference == 0 ? "0" : MaxDifference.ToString("0.###e0", c), Count(FlagMismatches, "flag mismatch", "flag mismatches"));
        if (!Passed)
            line = $"{line}; first: {FirstFailure}";
        return Verdict is not null || Departures is not null ? $"{line} (more with -v)" : line;
    }

    /// <summary>One line with every detail (the -v line of the tool's parity command): the file, pass or fail, the counts, the named departures and notes, and the first failure.</summary>
    public override string ToString()
    {
        var c = CultureInfo.InvariantCulture;
        if (Verdict is not null)
            return Passed ? $"{File}: {Verdict}" : $"{File}: FAIL {Verdict}; first: {FirstFailure}";
        double percent = Frames == 0 ? 0 : 100.0 * WithinTolerance / Frames;
        string need = RequireBitIdentical ? "bit-identical" : $"within {ParityCheck.Tolerance.ToString("0e0", c)} m";
        string line = string.Format(c,
            "{0}: {1} ({2}) {3}, {4}, {5:0.00} % within {6} m, {7} bit-identical, max difference {8} m, {9}",
            File, Passed ? "ok" : "FAIL", need, Count(Runs, "run"), Count(Frames, "frame"), percent, ParityCheck.Tolerance.ToString("0e0", c), BitIdentical,
            MaxDifference == 0 ? "0" : MaxDifference.ToString("0.###e0", c), Count(FlagMismatches, "flag mismatch", "flag mismatches"));
        if (Departures is not null)
            line = $"{line}; {Departures}";
        return Passed ? line : $"{line}; first: {FirstFailure}";
    }

    /// <summary>"1 run", "2 runs": a count with its noun in the singular or the plural.</summary>
    internal static string Count(long n, string one, string? many = null) =>
        string.Create(CultureInfo.InvariantCulture, $"{n} {(n == 1 ? one : many ?? one + "s")}");
}
