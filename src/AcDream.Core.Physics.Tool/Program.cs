using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tool;

/// <summary>The acdream-physics command-line tool: run, record and replay scenes.</summary>
public static class Program
{
    /// <summary>The usage text.</summary>
    public const string Usage =
        """
        usage: acdream-physics <command> [options]

        commands:
          list                          list the built-in scenes
          run SCENE [--out TRAJ] [--diag]
                                        run a scene: a per-frame table and a one-line summary;
                                        --out also writes the trajectory
          record SCENE --out TRAJ [--diag]
                                        run a scene and write its trajectory (summary only)
          replay SCENE TRAJ [--tolerance METRES] [--diag]
                                        re-run a recorded trajectory; exit 0 when it matches,
                                        1 with the first difference
          query SCENE floor X Y Z [DROP]
                                        the highest walkable surface at or below the point
                                        (within DROP metres, default 100)
          query SCENE cell X Y Z        the cell that holds the point (indoor first)
          query SCENE near X Y Z R      the objects overlapping a sphere
          query SCENE cast X0 Y0 Z0 X1 Y1 Z1 R
                                        the first contact of a sphere swept from one point
                                        to the other (R 0: a ray)
          plot SCENE [TRAJ] --out FILE.png
                                        draw the scene (top and side views) with each
                                        mover's path coloured by outcome, numbered, and
                                        named in a legend (also printed)
          dat DIR [LANDBLOCK]           summarise the DAT files in DIR (client_portal.dat and
                                        client_cell_1.dat), or one landblock's physics content:
                                        cells, portals, buildings, objects, polygons, BSP depth
          view SCENE [TRAJ] [--out FILE.html]
                                        write one self-contained HTML page that shows the
                                        scene's collision shapes and every frame in 3D
                                        (default file SCENE.view.html; runs the scene when
                                        no TRAJ)
          parity DIR [-v]               check the engine against every parity file (*.json.gz) in
                                        DIR: one short line per file (verdict and counts; -v:
                                        every detail); exit 1 when a file misses its threshold
          help                          this text

        SCENE is a scene file (JSON, docs/scene-format.md) or a built-in scene name.
        Query coordinates are landblock-local to the scene's first landblock.
        --diag prints each frame's structured diagnostics events.
        --dat DIR (run, record, replay, query, plot): the scene's movers walk through a world loaded
        from the DAT files in DIR (the 3 x 3 landblocks around each mover's start) instead of the
        scene's own world.
        Exit codes: 0 success, 1 replay or parity mismatch, 2 usage error or bad file.
        """;

    /// <summary>Runs the tool.</summary>
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    internal sealed class UsageException(string message) : Exception(message);

    private sealed class Options
    {
        public readonly List<string> Positional = new();
        public string? Out;
        public bool Diag;
        public bool Verbose;
        public float Tolerance = TrajectoryReplay.DefaultTolerance;
        public string? Dat;
    }

    /// <summary>Runs a command, writing to the given streams; returns the exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        if (args.Length == 0)
        {
            stderr.WriteLine(Usage);
            return 2;
        }
        string command = args[0];
        Options options;
        try
        {
            options = Parse(args[1..]);
        }
        catch (UsageException ex)
        {
            return Fail(stderr, ex.Message, usage: true);
        }
        try
        {
            switch (command)
            {
                case "help" or "--help" or "-h":
                    stdout.WriteLine(Usage);
                    return 0;
                case "list":
                    Expect(options, 0, "list takes no arguments");
                    // The name column is as wide as the longest name, so every description starts in one column.
                    int width = 0;
                    foreach (string name in SceneLibrary.Names)
                        width = Math.Max(width, name.Length);
                    foreach (string name in SceneLibrary.Names)
                    {
                        var scene = SceneLibrary.Load(name);
                        stdout.WriteLine(Printable($"{name.PadRight(width)}  {scene.Description}"));
                    }
                    return 0;
                case "run":
                    Expect(options, 1, "run needs SCENE");
                    return RunScene(options, stdout, table: true);
                case "record":
                    Expect(options, 1, "record needs SCENE");
                    if (options.Out is null)
                        throw new UsageException("record needs --out TRAJ");
                    return RunScene(options, stdout, table: false);
                case "replay":
                    Expect(options, 2, "replay needs SCENE and TRAJ");
                    return Replay(options, stdout);
                case "query":
                    if (options.Positional.Count < 2)
                        throw new UsageException("query needs SCENE and floor, cell, near or cast");
                    return QueryCommand.Run(LoadScene(options, options.Positional[0]), options.Positional.ToArray().AsSpan(1), stdout);
                case "plot":
                    if (options.Positional.Count is < 1 or > 2)
                        throw new UsageException(options.Positional.Count < 1 ? "plot needs SCENE" : $"unexpected argument '{options.Positional[2]}'");
                    if (options.Out is null)
                        throw new UsageException("plot needs --out FILE.png");
                    return PlotCommand.Run(LoadScene(options, options.Positional[0]), options.Positional.Count > 1 ? LoadTrajectory(options.Positional[1]) : null, options.Out, stdout);
                case "dat":
                    if (options.Positional.Count is < 1 or > 2)
                        throw new UsageException(options.Positional.Count < 1 ? "dat needs DIR" : $"unexpected argument '{options.Positional[2]}'");
                    return DatCommand.Run(options.Positional[0], options.Positional.Count > 1 ? options.Positional[1] : null, stdout);
                case "view":
                    if (options.Positional.Count is < 1 or > 2)
                        throw new UsageException(options.Positional.Count < 1 ? "view needs SCENE" : $"unexpected argument '{options.Positional[2]}'");
                    return View.ViewCommand.Run(LoadScene(options, options.Positional[0]),
                        options.Positional.Count > 1 ? LoadTrajectory(options.Positional[1]) : null,
                        options.Positional.Count > 1 ? options.Positional[1] : null, options.Out, stdout);
                case "parity":
                    Expect(options, 1, "parity needs DIR");
                    return ParityCheck.CheckDirectory(options.Positional[0], stdout, stderr, options.Verbose);
                default:
                    throw new UsageException($"unknown command '{command}'");
            }
        }
        catch (UsageException ex)
        {
            return Fail(stderr, ex.Message, usage: true);
        }
        catch (SceneFormatException ex)
        {
            return Fail(stderr, ex.Message, usage: false);
        }
        catch (IOException ex)
        {
            return Fail(stderr, ex.Message, usage: false);
        }
        catch (InvalidDataException ex)
        {
            // A DAT object the adapter refuses (DatObjectException): the message names the file and object id.
            return Fail(stderr, ex.Message, usage: false);
        }
        catch (UnauthorizedAccessException ex)
        {
            return Fail(stderr, ex.Message, usage: false);
        }
        catch (ArgumentException ex)
        {
            return Fail(stderr, ex.Message, usage: false);
        }
    }

    private static int Fail(TextWriter stderr, string message, bool usage)
    {
        stderr.WriteLine($"acdream-physics: {Printable(message)}" + (usage ? " (run 'acdream-physics help' for usage)" : string.Empty));
        return 2;
    }

    /// <summary>
    /// Text from a file made safe for a terminal, on one line: control characters (newlines, escape
    /// sequences, bells) and invisible format characters (such as bidirectional overrides) are written as
    /// <c>\uXXXX</c>.
    /// </summary>
    public static string Printable(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        StringBuilder? escaped = null;
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            bool unsafeChar = char.IsControl(c) || CharUnicodeInfo.GetUnicodeCategory(c) == UnicodeCategory.Format;
            if (unsafeChar && escaped is null)
                escaped = new StringBuilder(text, 0, i, text.Length + 16);
            if (escaped is null)
                continue;
            if (unsafeChar)
                escaped.Append(CultureInfo.InvariantCulture, $"\\u{(int)c:X4}");
            else
                escaped.Append(c);
        }
        return escaped?.ToString() ?? text;
    }

    private static Options Parse(string[] args)
    {
        var o = new Options();
        for (int i = 0; i < args.Length; i++)
        {
            string a = args[i];
            switch (a)
            {
                case "--out" or "-o":
                    if (i + 1 >= args.Length) throw new UsageException("--out needs a file name");
                    o.Out = args[++i];
                    break;
                case "--diag":
                    o.Diag = true;
                    break;
                case "-v" or "--verbose":
                    o.Verbose = true;
                    break;
                case "--dat":
                    if (i + 1 >= args.Length) throw new UsageException("--dat needs a folder holding the DAT files");
                    o.Dat = args[++i];
                    break;
                case "--tolerance":
                    if (i + 1 >= args.Length || !float.TryParse(args[++i], NumberStyles.Float, CultureInfo.InvariantCulture, out o.Tolerance)
                        || !(o.Tolerance >= 0) || !float.IsFinite(o.Tolerance))
                        throw new UsageException("--tolerance needs a number of metres, zero or more");
                    break;
                default:
                    if (a.StartsWith("--", StringComparison.Ordinal))
                        throw new UsageException($"unknown option '{a}'");
                    o.Positional.Add(a);
                    break;
            }
        }
        return o;
    }

    private static void Expect(Options o, int count, string message)
    {
        if (o.Positional.Count != count)
            throw new UsageException(o.Positional.Count < count ? message : $"unexpected argument '{o.Positional[count]}'");
    }

    /// <summary>Loads SCENE, in the world of the DAT files when --dat names them.</summary>
    private static Scene LoadScene(Options o, string arg)
    {
        var scene = LoadScene(arg);
        return o.Dat is null ? scene : DatCommand.WithDatWorld(scene, o.Dat);
    }

    /// <summary>Loads SCENE: an existing file, else a built-in name.</summary>
    private static Scene LoadScene(string arg)
    {
        if (File.Exists(arg))
        {
            try
            {
                return SceneLoader.LoadFile(arg);
            }
            catch (SceneFormatException ex)
            {
                throw new SceneFormatException(string.Empty, $"{arg}: {ex.Message}", ex);
            }
        }
        if (SceneLibrary.Contains(arg))
            return SceneLibrary.Load(arg);
        throw new UsageException($"scene '{arg}' is neither a file nor a built-in scene ({string.Join(", ", SceneLibrary.Names)})");
    }

    /// <summary>Runs <paramref name="work"/>; a bad value met while running is reported with the scene's file (or built-in name) first.</summary>
    private static T NamingScene<T>(string sceneArg, Func<T> work)
    {
        try
        {
            return work();
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException(string.Empty, $"{sceneArg}: {ex.Message}", ex);
        }
    }

    private static int RunScene(Options o, TextWriter stdout, bool table)
    {
        var scene = LoadScene(o, o.Positional[0]);
        Action<FrameDiagnostics>? diag = o.Diag ? d => PrintDiagnostics(stdout, d) : null;
        var trajectory = NamingScene(o.Positional[0], () => SceneRunner.Run(scene, diag));
        if (table)
            PrintTable(stdout, trajectory);
        if (o.Out is not null)
            File.WriteAllText(o.Out, trajectory.ToJson(), new UTF8Encoding(false));
        stdout.WriteLine(Printable(Summary(scene, trajectory) + (o.Out is null ? string.Empty : $"; trajectory written to {o.Out}")));
        return 0;
    }

    private static int Replay(Options o, TextWriter stdout)
    {
        var scene = LoadScene(o, o.Positional[0]);
        string path = o.Positional[1];
        var trajectory = LoadTrajectory(path);
        Action<FrameDiagnostics>? diag = o.Diag ? d => PrintDiagnostics(stdout, d) : null;
        var result = NamingScene(o.Positional[0], () => TrajectoryReplay.Replay(scene, trajectory, o.Tolerance, diag));
        foreach (string note in result.Notes)
            stdout.WriteLine(Printable($"note: {note}"));
        if (result.Matches)
        {
            stdout.WriteLine(Printable($"{scene.Name}: replay matches ({Count(result.FramesCompared, "frame")}, {Count(trajectory.Movers.Count, "mover")}, tolerance {F(result.Tolerance)} m)"));
            return 0;
        }
        stdout.WriteLine(Printable($"{scene.Name}: replay differs after {Count(result.FramesCompared, "matching frame")}"));
        stdout.WriteLine(Printable($"  {result.FirstDifference}"));
        return 1;
    }

    private static Trajectory LoadTrajectory(string path)
    {
        try
        {
            return Trajectory.LoadFile(path);
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException(string.Empty, $"{path}: {ex.Message}", ex);
        }
    }

    /// <summary>"1 mover", "2 movers": a count with its noun in the singular or the plural.</summary>
    internal static string Count(long n, string one) => $"{n} {one}{(n == 1 ? "" : "s")}";

    private static string F(float v) => v.ToString("0.#####", CultureInfo.InvariantCulture);
    private static string V(Vector3 v) => $"{v.X,10:F4} {v.Y,10:F4} {v.Z,8:F4}";

    private static void PrintTable(TextWriter w, Trajectory t)
    {
        w.WriteLine($"{"mover",-22} {"frame",5} {"x",10} {"y",10} {"z",8} {"cell",-10} {"C",1} {"W",1} {"slide",-6} {"hit",-12} ok");
        foreach (var mover in t.Movers)
            for (int f = 0; f < mover.Frames.Count; f++)
            {
                var fr = mover.Frames[f];
                string hit = fr.CollidedObjects.Count == 0 ? "-" : string.Join(",", Hexes(fr.CollidedObjects));
                string slide = fr.SlidingNormalValid ? $"{fr.SlidingNormal.X:F2},{fr.SlidingNormal.Y:F2}" : "-";
                w.WriteLine($"{Printable(mover.Name),-22} {f,5} {V(fr.Position)} 0x{fr.Cell:X8} {(fr.Contact ? 'C' : '.')} {(fr.OnWalkable ? 'W' : '.')} {slide,-6} {hit,-12} {(fr.Succeeded ? "ok" : "REFUSED")}{MotionColumns(fr)}{MissileHit(fr)}");
            }
    }

    /// <summary>A missile's frame in which its hit was reported: what it hit and in which quantum of the flight.</summary>
    private static string MissileHit(TrajectoryFrame fr) =>
        fr.Hit is { } h ? $"  missile hit: {h.Kind}{(h.ObjectId != 0 ? $" 0x{h.ObjectId:X8}" : "")} (quantum {h.Quantum})" : "";

    /// <summary>A motion mover's frame: its heading (degrees clockwise from +Y) and the command in effect (the interpreted state).</summary>
    private static string MotionColumns(TrajectoryFrame fr)
    {
        if (fr.Motion is not { } m)
            return string.Empty;
        var i = m.Interpreted;
        string Command(uint id, float speed) => id == 0 ? "-" : $"{MotionCommandNames.Name(id)}x{speed.ToString("0.###", CultureInfo.InvariantCulture)}";
        return $" hdg {PlotCommand.Heading(m.Rotation),6:F1} {Command(i.ForwardCommand, i.ForwardSpeed)} {Command(i.SideStepCommand, i.SideStepSpeed)} {Command(i.TurnCommand, i.TurnSpeed)}";
    }

    private static IEnumerable<string> Hexes(IReadOnlyList<uint> ids)
    {
        foreach (uint id in ids) yield return $"0x{id:X8}";
    }

    private static string Summary(Scene scene, Trajectory t)
    {
        int frames = 0, blocked = 0, refused = 0, airborne = 0;
        foreach (var mover in t.Movers)
            foreach (var fr in mover.Frames)
            {
                frames++;
                if (fr.CollisionNormalValid || fr.CollidedObjects.Count > 0) blocked++;
                if (!fr.Succeeded) refused++;
                if (!fr.Contact) airborne++;
            }
        return $"{scene.Name}: {Count(t.Movers.Count, "mover")}, {Count(frames, "frame")}, {blocked} with a collision, {airborne} airborne, {refused} refused";
    }

    private static void PrintDiagnostics(TextWriter w, FrameDiagnostics d)
    {
        w.WriteLine($"# {Printable(d.MoverName)} frame {d.Frame}: {Count(d.Events.Count, "event")}");
        foreach (var e in d.Events)
        {
            string text = e.Kind switch
            {
                TransitionEventKind.SubStep => $"sub-step {e.Index} at {e.Vector} offset {e.Vector2}",
                TransitionEventKind.ShapeTested => $"tested 0x{e.EntityId:X8} {e.ShapeKind}[{e.Index}] -> {e.Result}",
                TransitionEventKind.ShapeSkipped => $"skipped 0x{e.EntityId:X8} {e.ShapeKind}[{e.Index}]: {e.Reason}",
                TransitionEventKind.ObjectNormal => $"normal from 0x{e.EntityId:X8} {e.ShapeKind}: {e.Vector}",
                TransitionEventKind.CellChanged => $"cell 0x{e.FromCell:X8} -> 0x{e.ToCell:X8}",
                TransitionEventKind.StepUp => $"step up against {e.Vector}: {(e.Succeeded ? "succeeded" : "failed")}",
                _ => e.ToString(),
            };
            w.WriteLine($"#   {text}");
        }
    }
}
