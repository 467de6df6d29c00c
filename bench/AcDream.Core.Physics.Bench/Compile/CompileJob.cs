using System.Diagnostics;

namespace AcDream.Core.Physics.Bench.Compile;

/// <summary>
/// <c>compile</c>: how the BSP compiler's time grows with the face count, for the meshes of
/// <see cref="CompileMeshes"/>. Prints one line per mesh: faces, nodes, milliseconds.
/// </summary>
public static class CompileJob
{
    /// <summary>Runs the job; <c>--max N</c> stops at N faces (default: InputLimits.MaxCompilePolygons).</summary>
    public static int Run(string[] args)
    {
        int max = args.Length == 2 && args[0] == "--max" ? int.Parse(args[1], System.Globalization.CultureInfo.InvariantCulture) : Validation.InputLimits.MaxCompilePolygons;
        Console.WriteLine($"{"mesh",-12} {"faces",6} {"nodes",7} {"ms",9}");
        BspCompiler.Compile(CompileMeshes.Soup(50, 1)); // warm-up
        foreach (int n in new[] { 100, 200, 400, 800, 1600, Validation.InputLimits.MaxCompilePolygons })
        {
            if (n > max)
                break;
            Time("soup", CompileMeshes.Soup(n, n));
            Time("heightfield", CompileMeshes.HeightField((int)Math.Sqrt(n / 2.0), n));
            if (n / 3 < Validation.InputLimits.MaxBspDepth - 2)
                Time("prism", CompileMeshes.Prism(n / 3));
        }
        return 0;
    }

    private static void Time(string name, Polygon[] mesh)
    {
        var clock = Stopwatch.StartNew();
        var tree = BspCompiler.Compile(mesh);
        clock.Stop();
        Console.WriteLine($"{name,-12} {mesh.Length,6} {tree.Nodes.Length,7} {clock.Elapsed.TotalMilliseconds,9:F0}");
    }
}
