using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tool;

/// <summary>
/// <c>query SCENE floor|cell|near|cast …</c>: one world query against a scene, one line of output.
/// Coordinates are landblock-local to the scene's first cell's landblock, as everywhere in the tool.
/// </summary>
internal static class QueryCommand
{
    /// <summary>How far below the point <c>floor</c> looks when no drop is given, metres.</summary>
    public const float DefaultDrop = 100f;

    public static int Run(Scene scene, ReadOnlySpan<string> args, TextWriter stdout)
    {
        if (args.Length == 0)
            throw new Program.UsageException("query needs floor, cell, near or cast");
        uint frameCell = scene.World.Cells.CellIds.FirstOrDefault();
        if (frameCell == 0)
            throw new Program.UsageException($"scene '{scene.Name}' has no cells");
        var q = new WorldQuery(scene.World);
        var world = scene.World;
        string kind = args[0];
        var numbers = args[1..];
        switch (kind)
        {
            case "floor":
            {
                Count(kind, numbers, 3, 4, "X Y Z [DROP]");
                var at = Start(world, frameCell, Vec(numbers, 0));
                float drop = numbers.Length > 3 ? Number(numbers[3], "DROP") : DefaultDrop;
                stdout.WriteLine(q.TryFindFloor(at, drop, out var floor)
                    ? $"floor z={F(floor.Point.Z)} normal={V(floor.Normal)} {Surface(floor)}"
                    : $"floor none within {F(drop)} m");
                return 0;
            }
            case "cell":
            {
                Count(kind, numbers, 3, 3, "X Y Z");
                stdout.WriteLine(q.TryFindCell(Start(world, frameCell, Vec(numbers, 0)), out var cell)
                    ? $"cell 0x{cell.CellId:X8} ({(LandDefs.IsLandCell(cell.CellId) ? "outdoor" : "indoor")}) at {V(cell.Origin)}"
                    : "cell none (no loaded cell holds the point)");
                return 0;
            }
            case "near":
            {
                Count(kind, numbers, 4, 4, "X Y Z R");
                Span<ObjectOverlap> found = stackalloc ObjectOverlap[64];
                int n = q.OverlapSphere(Start(world, frameCell, Vec(numbers, 0)), Number(numbers[3], "R"), found);
                var list = new string[n];
                for (int i = 0; i < n; i++)
                    list[i] = $"0x{found[i].ObjectId:X8} {found[i].Kind}[{found[i].ShapeIndex}]";
                stdout.WriteLine(n == 0 ? "near none" : $"near {Program.Count(n, "object")}: {string.Join(", ", list)}");
                return 0;
            }
            case "cast":
            {
                Count(kind, numbers, 7, 7, "X0 Y0 Z0 X1 Y1 Z1 R");
                var from = Start(world, frameCell, Vec(numbers, 0));
                var to = Vec(numbers, 3) - LandDefs.BlockOffset(frameCell, from.CellId);
                stdout.WriteLine(q.SphereCast(from, to, Number(numbers[6], "R"), out var hit)
                    ? $"cast hit fraction={F(hit.Fraction)} centre={V(hit.Center)} point={V(hit.Point)} normal={V(hit.Normal)} {Surface(hit)}"
                    : "cast clear");
                return 0;
            }
            default:
                throw new Program.UsageException($"unknown query '{kind}' (floor, cell, near or cast)");
        }
    }

    /// <summary>
    /// The query's start: labelled with the indoor cell that contains the point when one does (a scene's
    /// cells need not be reachable through a building), else with the scene's first cell.
    /// </summary>
    private static Position Start(PhysicsWorld world, uint frameCell, Vector3 point)
    {
        foreach (uint id in world.Cells.CellIds)
            if (world.Cells.Get(id) is EnvCell env && env.ContainsPoint(point - LandDefs.BlockOffset(frameCell, id)))
                return new Position(id, point - LandDefs.BlockOffset(frameCell, id));
        return new Position(frameCell, point);
    }

    private static void Count(string kind, ReadOnlySpan<string> numbers, int min, int max, string usage)
    {
        if (numbers.Length < min || numbers.Length > max)
            throw new Program.UsageException($"query {kind} needs {usage}");
    }

    private static Vector3 Vec(ReadOnlySpan<string> a, int i) =>
        new(Number(a[i], "coordinate"), Number(a[i + 1], "coordinate"), Number(a[i + 2], "coordinate"));

    private static float Number(string s, string what) =>
        float.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) && float.IsFinite(v)
            ? v
            : throw new Program.UsageException($"{what} '{s}' is not a number");

    private static string Surface(in SurfaceHit hit) =>
        hit.Kind == SurfaceKind.Object ? $"object 0x{hit.ObjectId:X8} cell 0x{hit.CellId:X8}" : $"{hit.Kind.ToString().ToLowerInvariant()} cell 0x{hit.CellId:X8}";

    private static string F(float v) => v.ToString("0.####", CultureInfo.InvariantCulture);
    private static string V(Vector3 v) => $"({F(v.X)}, {F(v.Y)}, {F(v.Z)})";
}
