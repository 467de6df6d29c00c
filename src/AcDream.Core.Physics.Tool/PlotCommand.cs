using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Scenes;
using ScottPlot;
using AcDream.Core.Physics.Viewer;

namespace AcDream.Core.Physics.Tool;

/// <summary>
/// <c>plot SCENE [TRAJ] --out FILE.png</c>: a top view and a side view (along the main direction of motion)
/// of the scene's indoor cells, buildings and objects, with each mover's path, its frames coloured by
/// outcome and its collision normals drawn where they changed. Without TRAJ the scene is run first.
/// Coordinates are landblock-local to the scene's first cell's landblock.
/// </summary>
internal static class PlotCommand
{
    /// <summary>How close (top view, metres) another mover's number may be to a path's end before the start is tried.</summary>
    private const float LabelGap = 0.75f;

    /// <summary>The drawn length of a collision normal, metres.</summary>
    private const double NormalLength = 0.5;

    private static readonly Color CellColor = Color.FromHex("#555555");
    private static readonly Color BuildingColor = Color.FromHex("#8B5A2B");
    private static readonly Color ObjectColor = Color.FromHex("#1F5FBF");
    private static readonly Color PathColor = Color.FromHex("#BBBBBB");
    private static readonly Color NormalColor = Color.FromHex("#D62728");
    private static readonly Color HeadingColor = Color.FromHex("#000000");

    /// <summary>The colour of each outcome, in <see cref="FrameOutcome"/> order.</summary>
    private static readonly Color[] OutcomeColors =
        [Color.FromHex("#2CA02C"), Color.FromHex("#FF7F0E"), Color.FromHex("#9467BD"), Color.FromHex("#D62728"), Color.FromHex("#17BECF")];

    public static int Run(Scene scene, Trajectory? trajectory, string outPath, TextWriter stdout)
    {
        trajectory ??= SceneRunner.Run(scene);
        uint frameCell = scene.World.Cells.CellIds.FirstOrDefault();
        var paths = Paths(scene, trajectory, frameCell);
        var (min, max) = Region(paths, Reports(scene, frameCell));
        var teleports = Teleports(paths);
        bool alongX = MainAxisIsX(paths);

        var multiplot = new Multiplot();
        multiplot.AddPlots(2);
        multiplot.Layout = new ScottPlot.MultiplotLayouts.Columns();
        var top = multiplot.GetPlot(0);
        var side = multiplot.GetPlot(1);
        DrawWorld(scene.World, frameCell, min, max, top, side, alongX);
        int[] counts = DrawPaths(paths, top, side, alongX);
        var names = LabelPaths(paths, top, side, alongX);
        int ticks = DrawHeadings(paths, top);
        int reports = DrawReports(scene, frameCell, top, side, alongX);

        top.Title($"{scene.Name}: top view");
        top.XLabel("x (m)");
        top.YLabel("y (m)");
        side.Title($"{scene.Name}: side view along {(alongX ? "x" : "y")}");
        side.XLabel($"{(alongX ? "x" : "y")} (m)");
        side.YLabel("z (m)");
        foreach (var plot in new[] { top, side })
        {
            plot.Axes.SquareUnits();
            plot.Legend.Alignment = Alignment.UpperLeft;
        }
        top.Axes.SetLimits(min.X, max.X, min.Y, max.Y);
        side.Axes.SetLimits(alongX ? min.X : min.Y, alongX ? max.X : max.Y, min.Z, max.Z);
        top.ShowLegend();
        side.ShowLegend();
        multiplot.SavePng(outPath, 1600, 800);
        string headings = (ticks > 0 ? $"; {Program.Count(ticks, "heading tick")}" : string.Empty)
            + (reports > 0 ? $"; {Program.Count(reports, "reported position")}" : string.Empty);
        stdout.WriteLine($"{scene.Name}: {Program.Count(paths.Count, "mover")}, {Program.Count(counts.Sum(), "frame")} ({Describe(counts)}){headings}; plot written to {outPath}");
        foreach (string name in names)
            stdout.WriteLine(Program.Printable($"  {name}"));
        foreach (string teleport in teleports)
            stdout.WriteLine(Program.Printable($"  {teleport}"));
        return 0;
    }

    /// <summary>A mover's path: its start, its frames' positions, and the frames before which the path breaks (<see cref="PathBreaks"/>).</summary>
    private sealed record MoverPath(string Name, Vector3 Start, IReadOnlyList<TrajectoryFrame> Frames, Vector3[] Points, HashSet<int> Breaks)
    {
        /// <summary>The path up to its first teleport (a break longer than <see cref="PathBreaks.TeleportDistance"/>): what sets the plot's scale.</summary>
        public IEnumerable<Vector3> Home()
        {
            yield return Start;
            var previous = Start;
            for (int f = 0; f < Points.Length; f++)
            {
                if (Breaks.Contains(f) && Vector3.Distance(previous, Points[f]) > PathBreaks.TeleportDistance)
                    yield break;
                previous = Points[f];
                yield return previous;
            }
        }

        /// <summary>The runs of the path between its breaks (each at least one point).</summary>
        public List<Vector3[]> Runs()
        {
            var runs = new List<Vector3[]>();
            var run = new List<Vector3> { Start };
            for (int f = 0; f < Points.Length; f++)
            {
                if (Breaks.Contains(f))
                {
                    runs.Add(run.ToArray());
                    run.Clear();
                }
                run.Add(Points[f]);
            }
            runs.Add(run.ToArray());
            return runs;
        }
    }

    /// <summary>Each mover's start and frame positions in the plot's frame.</summary>
    private static List<MoverPath> Paths(Scene scene, Trajectory trajectory, uint frameCell)
    {
        var list = new List<MoverPath>();
        foreach (var mover in trajectory.Movers)
        {
            var sceneMover = scene.Movers.FirstOrDefault(m => m.Name == mover.Name);
            var points = mover.Frames.Select(f => f.Position + LandDefs.BlockOffset(frameCell, f.Cell)).ToArray();
            var start = sceneMover is null
                ? (points.Length > 0 ? points[0] : Vector3.Zero)
                : sceneMover.Start.Position.Origin + LandDefs.BlockOffset(frameCell, sceneMover.Start.Position.CellId);
            var all = points.Prepend(start).ToArray();
            list.Add(new MoverPath(mover.Name, start, mover.Frames, points, PathBreaks.Of(mover.Frames, all, frameCell).ToHashSet()));
        }
        return list;
    }

    /// <summary>
    /// The box around every path up to its first teleport (so a 150 m teleport does not set the scale) and the reported
    /// positions within <see cref="PathBreaks.TeleportDistance"/> of it, 3 m of margin sideways and 1 m up and down (at
    /// least 0 to 4 m high).
    /// </summary>
    private static (Vector3 Min, Vector3 Max) Region(List<MoverPath> paths, IEnumerable<Vector3> reports)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var v in paths.SelectMany(p => p.Home()))
        {
            min = Vector3.Min(min, v);
            max = Vector3.Max(max, v);
        }
        foreach (var v in reports)
            if (min.X > max.X || Vector3.Distance(Vector3.Clamp(v, min, max), v) <= PathBreaks.TeleportDistance)
            {
                min = Vector3.Min(min, v);
                max = Vector3.Max(max, v);
            }
        if (min.X > max.X)
            return (new Vector3(0, 0, -1), new Vector3(10, 10, 4));
        min -= new Vector3(3, 3, 1);
        max += new Vector3(3, 3, 1);
        return (new Vector3(min.X, min.Y, MathF.Min(min.Z, 0f)), new Vector3(max.X, max.Y, MathF.Max(max.Z, 4f)));
    }

    private static bool MainAxisIsX(List<MoverPath> paths)
    {
        float dx = 0, dy = 0;
        foreach (var p in paths)
            foreach (var run in p.Runs())
                for (int i = 1; i < run.Length; i++)
                {
                    dx += MathF.Abs(run[i].X - run[i - 1].X);
                    dy += MathF.Abs(run[i].Y - run[i - 1].Y);
                }
        return dx > dy;
    }

    /// <summary>Each teleport (a break longer than <see cref="PathBreaks.TeleportDistance"/>), said in words: the plot's scale leaves out what follows it.</summary>
    private static List<string> Teleports(List<MoverPath> paths)
    {
        var lines = new List<string>();
        foreach (var p in paths)
            foreach (int f in p.Breaks.Order())
            {
                var from = f == 0 ? p.Start : p.Points[f - 1];
                var to = p.Points[f];
                float jump = Vector3.Distance(from, to);
                if (jump > PathBreaks.TeleportDistance)
                    lines.Add(string.Create(System.Globalization.CultureInfo.InvariantCulture,
                        $"{p.Name}: teleported {jump:0.0} m at frame {f} to ({to.X:0.0}, {to.Y:0.0}, {to.Z:0.0}); what follows is outside the plot's scale"));
            }
        return lines;
    }

    private static void DrawWorld(PhysicsWorld world, uint frameCell, Vector3 min, Vector3 max, Plot top, Plot side, bool alongX)
    {
        // Land-cell borders inside the region, and the ground level when there is terrain.
        const float size = PhysicsConstants.LandCellLength;
        for (float x = MathF.Ceiling(min.X / size) * size; x <= max.X; x += size)
            top.Add.VerticalLine(x, 1, Colors.LightGray, LinePattern.Dotted);
        for (float y = MathF.Ceiling(min.Y / size) * size; y <= max.Y; y += size)
            top.Add.HorizontalLine(y, 1, Colors.LightGray, LinePattern.Dotted);
        if (world.Cells.CellIds.Any(LandDefs.IsLandCell))
            side.Add.HorizontalLine(0, 1, Colors.LightGray, LinePattern.Dotted);

        foreach (var shape in WorldOutline.Collect(world, frameCell))
        {
            var color = shape.Source switch { OutlineSource.EnvCell => CellColor, OutlineSource.Building => BuildingColor, _ => ObjectColor };
            // An object's shape that its dispatch rung never collides with (a door's foot cylinder) is dashed.
            var pattern = shape.Collides ? LinePattern.Solid : LinePattern.Dashed;
            switch (shape.Form)
            {
                case OutlineForm.Polygon:
                    DrawPolygon(shape.Vertices, color, pattern, top, side, alongX, min, max);
                    break;
                case OutlineForm.Cylinder:
                    var low = shape.Center;
                    double h = alongX ? low.X : low.Y;
                    Outline(top.Add.Circle(low.X, low.Y, shape.Radius), color, pattern);
                    Outline(side.Add.Rectangle(h - shape.Radius, h + shape.Radius, low.Z, low.Z + shape.Height), color, pattern);
                    break;
                default:
                    var c = shape.Center;
                    Outline(top.Add.Circle(c.X, c.Y, shape.Radius), color, pattern);
                    Outline(side.Add.Circle(alongX ? c.X : c.Y, c.Z, shape.Radius), color, pattern);
                    break;
            }
        }
    }

    private static void Outline(IHasLine shape, Color color, LinePattern pattern)
    {
        shape.LineColor = color;
        shape.LineWidth = 1.5f;
        shape.LinePattern = pattern;
        if (shape is IHasFill fill)
            fill.FillColor = Colors.Transparent;
    }

    /// <summary>A polygon's outline in both views (left out when it lies wholly outside the region).</summary>
    private static void DrawPolygon(ReadOnlySpan<Vector3> v, Color color, LinePattern pattern, Plot top, Plot side, bool alongX, Vector3 min, Vector3 max)
    {
        var xs = new double[v.Length + 1];
        var ys = new double[v.Length + 1];
        var hs = new double[v.Length + 1];
        var zs = new double[v.Length + 1];
        bool inside = false;
        for (int i = 0; i <= v.Length; i++)
        {
            var p = v[i % v.Length];
            (xs[i], ys[i], zs[i]) = (p.X, p.Y, p.Z);
            hs[i] = alongX ? p.X : p.Y;
            inside |= p.X >= min.X && p.X <= max.X && p.Y >= min.Y && p.Y <= max.Y;
        }
        if (!inside)
            return;
        Line(top.Add.Scatter(xs, ys), color, pattern);
        Line(side.Add.Scatter(hs, zs), color, pattern);
    }

    private static void Line(ScottPlot.Plottables.Scatter s, Color color, LinePattern pattern)
    {
        s.Color = color;
        s.LineWidth = 1.5f;
        s.MarkerSize = 0;
        s.LinePattern = pattern;
    }

    /// <summary>The paths, one marker per frame in its outcome's colour, and each changed collision normal; returns the frame count per outcome.</summary>
    private static int[] DrawPaths(List<MoverPath> paths, Plot top, Plot side, bool alongX)
    {
        int outcomes = Enum.GetValues<FrameOutcome>().Length;
        var xs = new List<double>[outcomes];
        var ys = new List<double>[outcomes];
        var hs = new List<double>[outcomes];
        var zs = new List<double>[outcomes];
        for (int k = 0; k < outcomes; k++)
            (xs[k], ys[k], hs[k], zs[k]) = (new(), new(), new(), new());
        foreach (var p in paths)
        {
            // One line per run between breaks: a blip or teleport leaves a gap rather than a line the mover never walked.
            foreach (var run in p.Runs())
            {
                var path = top.Add.Scatter(run.Select(v => (double)v.X).ToArray(), run.Select(v => (double)v.Y).ToArray());
                Line(path, PathColor, LinePattern.Solid);
                var sidePath = side.Add.Scatter(run.Select(v => (double)(alongX ? v.X : v.Y)).ToArray(), run.Select(v => (double)v.Z).ToArray());
                Line(sidePath, PathColor, LinePattern.Solid);
            }
            var previous = p.Start;
            Vector3? lastNormal = null;
            for (int f = 0; f < p.Frames.Count; f++)
            {
                var frame = p.Frames[f];
                var at = p.Points[f];
                int k = (int)FrameOutcomes.Of(frame, previous);
                xs[k].Add(at.X); ys[k].Add(at.Y); hs[k].Add(alongX ? at.X : at.Y); zs[k].Add(at.Z);
                if (frame.CollisionNormalValid && (lastNormal is not { } n || Vector3.DistanceSquared(n, frame.CollisionNormal) > 1e-6f))
                {
                    var tip = at + frame.CollisionNormal * (float)NormalLength;
                    Arrow(top.Add.Arrow(new Coordinates(at.X, at.Y), new Coordinates(tip.X, tip.Y)));
                    Arrow(side.Add.Arrow(new Coordinates(alongX ? at.X : at.Y, at.Z), new Coordinates(alongX ? tip.X : tip.Y, tip.Z)));
                    lastNormal = frame.CollisionNormal;
                }
                previous = at;
            }
        }
        var counts = new int[outcomes];
        for (int k = 0; k < outcomes; k++)
        {
            counts[k] = xs[k].Count;
            var color = OutcomeColors[k];
            var name = ((FrameOutcome)k).ToString().ToLowerInvariant();
            var markers = top.Add.Markers(xs[k].ToArray(), ys[k].ToArray(), MarkerShape.FilledCircle, 5, color);
            markers.LegendText = $"{name} ({counts[k]})";
            side.Add.Markers(hs[k].ToArray(), zs[k].ToArray(), MarkerShape.FilledCircle, 5, color);
        }
        var normalKey = top.Add.Markers(Array.Empty<double>(), Array.Empty<double>(), MarkerShape.FilledTriangleUp, 6, NormalColor);
        normalKey.LegendText = "collision normal (where it changed)";
        return counts;
    }

    /// <summary>
    /// Names the movers: each path is numbered in both views at its end, or at its start when another
    /// number is within <see cref="LabelGap"/> of the end and the start is clearer (movers often share a
    /// start, or end against the same wall), and the side view's legend lists each number with its mover's name.
    /// Returns those legend lines ("1: north"), which the command prints too.
    /// </summary>
    private static List<string> LabelPaths(List<MoverPath> paths, Plot top, Plot side, bool alongX)
    {
        var names = new List<string>(paths.Count);
        var placed = new List<Vector2>();
        for (int i = 0; i < paths.Count; i++)
        {
            var p = paths[i];
            var end = p.Home().Last(); // the last point inside the plot's scale
            float endClear = Clearance(end, placed);
            var at = endClear >= LabelGap || endClear >= Clearance(p.Start, placed) ? end : p.Start;
            placed.Add(new Vector2(at.X, at.Y));
            string number = (i + 1).ToString(System.Globalization.CultureInfo.InvariantCulture);
            Label(top.Add.Text(number, at.X, at.Y));
            Label(side.Add.Text(number, alongX ? at.X : at.Y, at.Z));
            names.Add($"{number}: {p.Name}");
            side.Legend.ManualItems.Add(new LegendItem { LabelText = names[^1] });
        }
        return names;
    }

    /// <summary>How far a point is from the nearest of the labels placed so far, in the top view.</summary>
    private static float Clearance(Vector3 point, List<Vector2> placed)
    {
        float nearest = float.MaxValue;
        foreach (var q in placed)
            nearest = MathF.Min(nearest, Vector2.Distance(q, new Vector2(point.X, point.Y)));
        return nearest;
    }

    private static void Label(ScottPlot.Plottables.Text text)
    {
        text.LabelFontSize = 13;
        text.LabelBold = true;
        text.LabelFontColor = Colors.Black;
        text.LabelBackgroundColor = Colors.White.WithAlpha(0.8);
        text.LabelAlignment = Alignment.LowerLeft;
        text.OffsetX = 4;
        text.OffsetY = -4;
    }

    /// <summary>The frames between heading ticks.</summary>
    private const int HeadingTickEvery = 5;
    /// <summary>A heading tick's length, m.</summary>
    private const float HeadingTickLength = 0.6f;

    /// <summary>A motion mover's heading: a short tick from every fifth frame's position along its forward (+Y of its rotation); returns the count.</summary>
    private static int DrawHeadings(List<MoverPath> paths, Plot top)
    {
        int ticks = 0;
        foreach (var p in paths)
            for (int f = 0; f < p.Frames.Count; f += HeadingTickEvery)
            {
                if (p.Frames[f].Motion is not { } m)
                    continue;
                var at = p.Points[f];
                var tip = at + Vector3.Transform(Vector3.UnitY, m.Rotation) * HeadingTickLength;
                var tick = top.Add.Line(at.X, at.Y, tip.X, tip.Y);
                tick.LineColor = HeadingColor;
                tick.LineWidth = 1.5f;
                tick.MarkerSize = 0;
                ticks++;
            }
        return ticks;
    }

    private static readonly Color ReportColor = Color.FromHex("#E377C2");

    /// <summary>Every mover's reported positions (its interpolateTo commands) in the plot's frame.</summary>
    private static IEnumerable<Vector3> Reports(Scene scene, uint frameCell) =>
        scene.Movers.SelectMany(m => m.ReportedPositions).Select(p => p.Origin + LandDefs.BlockOffset(frameCell, p.CellId));

    /// <summary>
    /// The positions a server reported (the scene's interpolateTo commands) as open diamonds in both views, beside the
    /// smoothed path the position manager made of them (issue 22 part 4); returns their count.
    /// </summary>
    private static int DrawReports(Scene scene, uint frameCell, Plot top, Plot side, bool alongX)
    {
        var points = Reports(scene, frameCell).ToArray();
        if (points.Length == 0)
            return 0;
        var markers = top.Add.Markers(points.Select(v => (double)v.X).ToArray(), points.Select(v => (double)v.Y).ToArray(), MarkerShape.OpenDiamond, 9, ReportColor);
        markers.LegendText = $"reported position, interpolateTo ({points.Length})";
        side.Add.Markers(points.Select(v => (double)(alongX ? v.X : v.Y)).ToArray(), points.Select(v => (double)v.Z).ToArray(), MarkerShape.OpenDiamond, 9, ReportColor);
        return points.Length;
    }

    /// <summary>The compass heading of a rotation: degrees clockwise from +Y (north) of its forward (+Y) axis, 0 to 360.</summary>
    internal static double Heading(Quaternion rotation)
    {
        var forward = Vector3.Transform(Vector3.UnitY, rotation);
        double degrees = Math.Atan2(forward.X, forward.Y) * 180.0 / Math.PI;
        return degrees < 0 ? degrees + 360.0 : degrees;
    }

    private static void Arrow(ScottPlot.Plottables.Arrow arrow)
    {
        arrow.ArrowLineColor = NormalColor;
        arrow.ArrowFillColor = NormalColor;
        arrow.ArrowLineWidth = 0;
        arrow.ArrowWidth = 1.5f;
        arrow.ArrowheadWidth = 7;
        arrow.ArrowheadLength = 9;
        arrow.ArrowheadAxisLength = 9;
    }

    private static string Describe(int[] counts) =>
        string.Join(", ", counts.Select((c, k) => $"{c} {((FrameOutcome)k).ToString().ToLowerInvariant()}"));
}
