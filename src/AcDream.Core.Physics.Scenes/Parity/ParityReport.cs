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

    /// <summary>One line: the file, pass or fail, the counts, and the first failure.</summary>
    public override string ToString()
    {
        var c = CultureInfo.InvariantCulture;
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
