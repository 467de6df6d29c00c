using System.Globalization;
using System.IO;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>
/// <c>chart DOOR.CSV [--out FILE.png]</c>: redraws the speed/accuracy chart from a door job's door.csv without
/// measuring again, so a chart can follow a change of its drawing while keeping the numbers of the table it
/// sits beside. Reads the columns it plots by name (method, mix_ns_per_frame, frame_error_mean_m,
/// frame_error_p99_m, max_penetration_m); any others may be absent.
/// </summary>
public static class ChartJob
{
    /// <summary>Runs the command; 0 when the chart was written, 2 for a usage or file error.</summary>
    public static int Run(string[] args)
    {
        if (args.Length is not (1 or 3) || (args.Length == 3 && args[1] != "--out"))
        {
            Console.Error.WriteLine("usage: chart DOOR.CSV [--out FILE.png]");
            return 2;
        }
        string output = args.Length == 3 ? args[2] : Path.Combine(Path.GetDirectoryName(Path.GetFullPath(args[0]))!, "door-speed-accuracy.png");
        try
        {
            var results = Read(File.ReadAllLines(args[0]));
            Charts.SpeedVsAccuracy(results, output);
        }
        catch (Exception ex) when (ex is IOException or FormatException or UnauthorizedAccessException)
        {
            Console.Error.WriteLine($"chart: {args[0]}: {ex.Message}");
            return 2;
        }
        Console.WriteLine($"chart written to {output}");
        return 0;
    }

    /// <summary>One result per data row, holding what the chart plots.</summary>
    private static List<MethodResult> Read(string[] lines)
    {
        if (lines.Length < 2)
            throw new FormatException("expected a header line and at least one row.");
        var header = lines[0].Split(',');
        int Column(string name) => Array.IndexOf(header, name) is int i and >= 0 ? i : throw new FormatException($"no column \"{name}\".");
        int method = Column("method"), mix = Column("mix_ns_per_frame"), mean = Column("frame_error_mean_m"),
            p99 = Column("frame_error_p99_m"), penetration = Column("max_penetration_m");
        var results = new List<MethodResult>();
        foreach (string line in lines.Skip(1).Where(l => l.Length > 0))
        {
            var cells = line.Split(',');
            if (cells.Length != header.Length)
                throw new FormatException($"a row has {cells.Length} cells, the header {header.Length}.");
            double Number(int i) => double.Parse(cells[i], NumberStyles.Float, CultureInfo.InvariantCulture);
            var m = Enum.Parse<DoorMethod>(cells[method]);
            var result = new MethodResult
            {
                Method = m,
                Accuracy = new AccuracySummary { Method = m, FrameError = new Spread(Number(mean), Number(p99), 0), MaxPenetration = Number(penetration) },
                Outcomes = [],
            };
            result.Timing.MixNs = Number(mix);
            results.Add(result);
        }
        return results;
    }
}
