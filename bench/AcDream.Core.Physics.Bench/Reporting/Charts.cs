using System.Linq;
using AcDream.Core.Physics.Bench.Accuracy;
using ScottPlot;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>PNG charts of the door job (ScottPlot).</summary>
public static class Charts
{
    /// <summary>
    /// Speed (the approach mix's ns per frame, log scale) against accuracy: one panel for the position error
    /// (mean and p99 per frame against the reference), one for the deepest penetration; one labelled point
    /// per method. The x axis is in ns throughout (ticks too); the y axes start at 0, as errors and depths do.
    /// </summary>
    public static void SpeedVsAccuracy(IReadOnlyList<MethodResult> results, string path)
    {
        var multiplot = new Multiplot();
        multiplot.AddPlots(2);
        multiplot.Layout = new ScottPlot.MultiplotLayouts.Columns();
        var error = multiplot.GetPlot(0);
        var penetration = multiplot.GetPlot(1);
        var logs = results.Select(r => Math.Log10(Math.Max(1, r.Timing.MixNs))).ToArray();
        double left = logs.Min() - 0.08, right = logs.Max() + 0.22;
        var errorLabels = new LabelPlacer(left, right, results.Max(r => r.Accuracy.FrameError.P99 * 1000));
        var depthLabels = new LabelPlacer(left, right, Math.Max(PhysicsConstants.Epsilon * 1000, results.Max(r => r.Accuracy.MaxPenetration * 1000)));
        for (int i = 0; i < results.Count; i++)
        {
            var r = results[i];
            double x = Math.Log10(Math.Max(1, r.Timing.MixNs));
            var color = MethodColor(r.Method);
            var p99 = error.Add.Marker(x, r.Accuracy.FrameError.P99 * 1000, MarkerShape.FilledCircle, 10, color);
            error.Add.Marker(x, r.Accuracy.FrameError.Mean * 1000, MarkerShape.OpenCircle, 10, color);
            errorLabels.Add(error, DoorMethods.Label(r.Method), x, r.Accuracy.FrameError.P99 * 1000, color);
            penetration.Add.Marker(x, r.Accuracy.MaxPenetration * 1000, MarkerShape.FilledSquare, 10, color);
            depthLabels.Add(penetration, DoorMethods.Label(r.Method), x, r.Accuracy.MaxPenetration * 1000, color);
        }
        error.Title("Position error per frame vs reference (filled: p99, open: mean)");
        error.YLabel("position error (mm)");
        penetration.Title("Deepest penetration of the slab after a frame");
        penetration.YLabel("penetration (mm)");
        penetration.Add.HorizontalLine(PhysicsConstants.Epsilon * 1000, 1, Colors.Gray, LinePattern.Dashed);
        var epsLabel = penetration.Add.Text("EPSILON (0.2 mm)", Math.Log10(Math.Max(1, results.Min(r => r.Timing.MixNs))), PhysicsConstants.Epsilon * 1000);
        epsLabel.LabelFontColor = Colors.Gray;
        epsLabel.LabelFontSize = 12;
        epsLabel.OffsetY = -4;
        epsLabel.LabelAlignment = Alignment.LowerLeft;
        foreach (var plot in new[] { error, penetration })
        {
            plot.XLabel("approach mix: ns per frame (log scale; door.csv mix_ns_per_frame)");
            LogTicks(plot, left, right);
            plot.Axes.AutoScale();
            plot.Axes.SetLimitsX(left, right);
            // Errors and depths are never negative: the axis starts at 0 (auto-scaling pads below it).
            plot.Axes.SetLimitsY(0, plot.Axes.GetLimits().Top);
        }
        multiplot.SavePng(path, 1600, 650);
    }

    /// <summary>
    /// Places each method's label beside its point where it covers no label placed before it: above the point
    /// first, then below (unless the point sits near the bottom of the axis, where a label below would be cut),
    /// then higher above. Label boxes are estimated in the panel's pixels (1600 × 650 image, two panels).
    /// </summary>
    private sealed class LabelPlacer(double left, double right, double top)
    {
        private const double PanelWidthPx = 700, PanelHeightPx = 520, CharWidthPx = 7.5, HeightPx = 16;
        private static readonly double[] Offsets = [-18, 4, -34, 20, -50];
        private readonly List<(double X0, double X1, double Y0, double Y1)> _placed = [];

        public void Add(Plot plot, string text, double x, double y, Color color)
        {
            double px = (x - left) / (right - left) * PanelWidthPx + 8;
            double py = PanelHeightPx - y / (top * 1.1) * PanelHeightPx;
            double width = text.Length * CharWidthPx;
            double chosen = Offsets[0];
            foreach (double offset in Offsets)
            {
                var box = (px, px + width, py + offset, py + offset + HeightPx);
                bool cut = box.Item3 < 0 || box.Item4 > PanelHeightPx;
                if (!cut && !_placed.Any(b => b.X0 < box.Item2 && box.px < b.X1 && b.Y0 < box.Item4 && box.Item3 < b.Y1))
                {
                    chosen = offset;
                    break;
                }
            }
            _placed.Add((px, px + width, py + chosen, py + chosen + HeightPx));
            var label = plot.Add.Text(text, x, y);
            label.LabelFontColor = color;
            label.LabelFontSize = 13;
            label.OffsetX = 8;
            label.OffsetY = (float)chosen;
        }
    }

    /// <summary>
    /// Ticks in ns on a log10 axis from <paramref name="left"/> to <paramref name="right"/>: 1, 2, 3, 4, 5 and 7
    /// times each power of ten that falls inside, labelled as plain numbers of ns (the axis title names the unit).
    /// </summary>
    private static void LogTicks(Plot plot, double left, double right)
    {
        var positions = new List<double>();
        var labels = new List<string>();
        for (int d = (int)Math.Floor(left); d <= (int)Math.Ceiling(right); d++)
            foreach (int m in new[] { 1, 2, 3, 4, 5, 7 })
            {
                double v = m * Math.Pow(10, d);
                if (Math.Log10(v) < left || Math.Log10(v) > right)
                    continue;
                positions.Add(Math.Log10(v));
                labels.Add(v.ToString("#,0", System.Globalization.CultureInfo.InvariantCulture));
            }
        plot.Axes.Bottom.SetTicks(positions.ToArray(), labels.ToArray());
    }

    /// <summary>A fixed colour per method.</summary>
    public static Color MethodColor(DoorMethod method) => method switch
    {
        DoorMethod.Retail => Colors.Blue,
        DoorMethod.Scale0_25 => Colors.Teal,
        DoorMethod.Scale0_5 => Colors.Green,
        DoorMethod.Scale2 => Colors.Orange,
        DoorMethod.Scale4 => Colors.Red,
        DoorMethod.Reference => Colors.Black,
        _ => Colors.Gray,
    };

    /// <summary>The colour of a failure in the stability map.</summary>
    public static Color FailureColor(DoorFailure failure) => failure switch
    {
        DoorFailure.Jitter => Colors.Gold,
        DoorFailure.Stuck => Colors.DarkOrange,
        DoorFailure.Penetration => Colors.Red,
        DoorFailure.Tunnel => Colors.Purple,
        DoorFailure.NaN => Colors.Black,
        _ => Colors.WhiteSmoke,
    };

    /// <summary>
    /// The stability map: one block per method (columns: headings −85°..85°), rows grouped by frame rate
    /// and speed, one row per lateral offset; each cell coloured by the approach's most severe failure.
    /// </summary>
    public static void StabilityMap(IReadOnlyList<MethodResult> results, string path)
    {
        var plot = new Plot();
        int headings = DoorApproaches.Headings.Length, laterals = DoorApproaches.Laterals.Length;
        const int gapX = 4, gapY = 2;
        var yTicks = new List<double>();
        var yLabels = new List<string>();
        int rowBlocks = 0;
        foreach (int hz in DoorApproaches.Rates)
            foreach (float speed in DoorApproaches.Speeds)
            {
                double top = -rowBlocks * (laterals + gapY);
                yTicks.Add(top - laterals / 2.0);
                yLabels.Add($"{hz} Hz {speed:0} m/s");
                rowBlocks++;
            }
        for (int m = 0; m < results.Count; m++)
        {
            double left = m * (headings + gapX);
            double top = 0, bottom = -rowBlocks * (laterals + gapY) + gapY;
            var bg = plot.Add.Rectangle(left, left + headings, bottom, top);
            bg.FillStyle.Color = FailureColor(DoorFailure.None);
            bg.LineStyle.Width = 0;
            var name = plot.Add.Text(DoorMethods.Label(results[m].Method), left + headings / 2.0, top + 1.5);
            name.LabelFontSize = 16;
            name.LabelAlignment = Alignment.LowerCenter;
            foreach (var o in results[m].Outcomes)
            {
                var worst = AccuracySummary.Worst(o.Failures);
                if (worst == DoorFailure.None)
                    continue;
                var a = o.Approach;
                int col = Array.IndexOf(DoorApproaches.Headings, a.Heading);
                int block = Array.IndexOf(DoorApproaches.Rates, a.Hz) * DoorApproaches.Speeds.Length + Array.IndexOf(DoorApproaches.Speeds, a.Speed);
                int row = Array.IndexOf(DoorApproaches.Laterals, a.Lateral);
                if (col < 0 || block < 0 || row < 0)
                    continue;
                double y = -block * (laterals + gapY) - row;
                var cell = plot.Add.Rectangle(left + col, left + col + 1, y - 1, y);
                cell.FillStyle.Color = FailureColor(worst);
                cell.LineStyle.Width = 0;
            }
        }
        plot.Axes.Left.SetTicks(yTicks.ToArray(), yLabels.ToArray());
        var xTicks = new List<double>();
        var xLabels = new List<string>();
        for (int m = 0; m < results.Count; m++)
            foreach (int h in new[] { -85, 0, 85 })
            {
                xTicks.Add(m * (headings + gapX) + Array.IndexOf(DoorApproaches.Headings, h) + 0.5);
                xLabels.Add($"{h}°");
            }
        plot.Axes.Bottom.SetTicks(xTicks.ToArray(), xLabels.ToArray());
        plot.Title("Stability map: most severe failure per approach (columns: heading; rows: lateral offset −0.7..0.7 m, top to bottom)");
        plot.XLabel("heading from straight at the face");
        foreach (var kind in new[] { DoorFailure.None, DoorFailure.Jitter, DoorFailure.Stuck, DoorFailure.Penetration, DoorFailure.Tunnel, DoorFailure.NaN })
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = kind == DoorFailure.None ? "ok" : kind.ToString(), FillColor = FailureColor(kind) });
        plot.Legend.Alignment = Alignment.LowerRight;
        plot.ShowLegend(Edge.Bottom);
        plot.Grid.IsVisible = false;
        plot.Axes.Margins(0.01, 0.03);
        plot.SavePng(path, 2200, 1400);
    }
}
