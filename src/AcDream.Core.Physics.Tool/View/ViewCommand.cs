using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Viewer;

namespace AcDream.Core.Physics.Tool.View;

/// <summary>
/// <c>view SCENE [TRAJ] [--out FILE.html]</c>: writes one self-contained HTML page (the scene's collision shapes and
/// every frame of every mover, with the viewer's script inlined) that opens offline in a browser. Without TRAJ the
/// scene is run first. docs/viewer.md describes the page.
/// </summary>
internal static class ViewCommand
{
    /// <summary>
    /// The most frames (all movers together) a page holds: about 60 MB of page. A longer trajectory is refused
    /// rather than written into a page no browser opens comfortably.
    /// </summary>
    public const int MaxFrames = 200_000;

    /// <summary>The page's script tag that the data replaces (in the embedded page, built from tools/viewer).</summary>
    internal const string DataPlaceholder = "/*acdream-view-data*/";

    /// <summary>The embedded page: the viewer's script and style, with <see cref="DataPlaceholder"/> where the data goes.</summary>
    internal static string PageTemplate()
    {
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream("AcDream.Core.Physics.Tool.viewer.html")
            ?? throw new InvalidOperationException("the viewer page is missing from the tool's resources");
        using var reader = new StreamReader(stream, Encoding.UTF8);
        return reader.ReadToEnd();
    }

    /// <summary>Refuses a trajectory with more than <see cref="MaxFrames"/> frames, naming <paramref name="source"/>.</summary>
    internal static void CheckCaps(Trajectory trajectory, string source)
    {
        long frames = 0;
        foreach (var m in trajectory.Movers)
            frames += m.Frames.Count;
        if (frames > MaxFrames)
            throw new SceneFormatException(string.Empty,
                $"{source}: has {frames} frames; a view page holds at most {MaxFrames} (view a shorter trajectory).");
    }

    /// <summary>The page for a scene and its trajectory.</summary>
    internal static string Page(Scene scene, Trajectory trajectory)
    {
        uint frameCell = ViewData.FrameCell(scene);
        var shapes = ViewShapes.Collect(scene.World, frameCell);
        using var data = new MemoryStream();
        ViewData.Write(data, scene, trajectory, shapes, frameCell);
        // The writer escapes '<', '>' and '&' in strings (its default encoder), so the data cannot close its script tag.
        string json = Encoding.UTF8.GetString(data.ToArray());
        string template = PageTemplate();
        int at = template.IndexOf(DataPlaceholder, StringComparison.Ordinal);
        if (at < 0)
            throw new InvalidOperationException("the viewer page has no data placeholder");
        return string.Concat(template.AsSpan(0, at), json, template.AsSpan(at + DataPlaceholder.Length))
            .Replace("<title>acdream-physics view</title>", $"<title>{System.Net.WebUtility.HtmlEncode(scene.Name)}: acdream-physics view</title>", StringComparison.Ordinal);
    }

    /// <summary>Writes the page; <paramref name="trajectorySource"/> names the trajectory file (null: the scene was run).</summary>
    public static int Run(Scene scene, Trajectory? trajectory, string? trajectorySource, string? outPath, TextWriter stdout)
    {
        trajectory ??= SceneRunner.Run(scene);
        CheckCaps(trajectory, trajectorySource ?? scene.Name);
        if (trajectory.SceneName != scene.Name)
            stdout.WriteLine(Program.Printable($"note: the trajectory was recorded on scene '{trajectory.SceneName}', shown in '{scene.Name}'"));
        foreach (var mover in trajectory.Movers)
            if (!scene.Movers.Any(m => m.Name == mover.Name))
                stdout.WriteLine(Program.Printable($"note: mover '{mover.Name}' is not in the scene: drawn without its spheres"));
        outPath ??= $"{scene.Name}.view.html";
        string page = Page(scene, trajectory);
        byte[] bytes = new UTF8Encoding(false).GetBytes(page);
        File.WriteAllBytes(outPath, bytes);
        int frames = trajectory.Movers.Sum(m => m.Frames.Count);
        string size = (bytes.Length / 1024.0).ToString("0", CultureInfo.InvariantCulture);
        stdout.WriteLine(Program.Printable($"{scene.Name}: {Program.Count(trajectory.Movers.Count, "mover")}, {Program.Count(frames, "frame")}; view written to {outPath} ({size} KB)"));
        return 0;
    }
}
