using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics;

namespace AcDream.Core.Physics.Bench.RealCells;

/// <summary>One recorded frame of a real-cell reference file: the requested offset and the reference's result.</summary>
public readonly record struct RealCellsFrame(Vector3 Offset, Vector3 Position, uint Cell, bool Contact, bool Walkable, bool Sliding, bool Accepted);

/// <summary>A mover of a real-cell reference file: its scene name, its full start state and its frames.</summary>
public sealed record RealCellsMover(string Name, MoverState Start, RealCellsFrame[] Frames);

/// <summary>
/// A reference trajectory file of the shared real-cells set (<c>"format": "ace-parity-real"</c>, gzip JSON;
/// its README describes the fields): the scene file it names and, per mover, the start state and frames.
/// Only what the benchmark needs is read.
/// </summary>
public sealed class RealCellsFile
{
    private RealCellsFile(string name, string scenePath, IReadOnlyList<RealCellsMover> movers)
    {
        Name = name;
        ScenePath = scenePath;
        Movers = movers;
    }

    /// <summary>The file name without <c>.json.gz</c>.</summary>
    public string Name { get; }
    /// <summary>The scene file beside it (<c>scenes/&lt;scene&gt;</c>).</summary>
    public string ScenePath { get; }
    /// <summary>The movers that are not excluded, in file order.</summary>
    public IReadOnlyList<RealCellsMover> Movers { get; }

    /// <summary>
    /// The real-cells folder: <c>shared/real-cells</c> beside the repository (or beside any folder above the
    /// current directory), or null when there is none.
    /// </summary>
    public static string? FindSharedFolder()
    {
        for (var dir = new DirectoryInfo(Directory.GetCurrentDirectory()); dir is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.FullName, "shared", "real-cells");
            if (Directory.Exists(candidate))
                return candidate;
        }
        return null;
    }

    /// <summary>Reads one reference file.</summary>
    public static RealCellsFile Load(string path)
    {
        using var stream = new GZipStream(File.OpenRead(path), CompressionMode.Decompress);
        using var doc = JsonDocument.Parse(stream);
        var root = doc.RootElement;
        string scene = Path.Combine(Path.GetDirectoryName(path)!, "scenes", root.GetProperty("scene").GetString()!);
        var movers = new List<RealCellsMover>();
        foreach (var m in root.GetProperty("movers").EnumerateArray())
        {
            var frames = new List<RealCellsFrame>();
            foreach (var f in m.GetProperty("frames").EnumerateArray())
                frames.Add(new RealCellsFrame(Vec(f.GetProperty("offset")), Vec(f.GetProperty("pos")), Hex(f.GetProperty("cell")),
                    f.GetProperty("c").GetInt32() == 1, f.GetProperty("w").GetInt32() == 1, f.TryGetProperty("sl", out _),
                    f.GetProperty("ok").GetInt32() == 1));
            movers.Add(new RealCellsMover(m.GetProperty("name").GetString()!, StartState(m.GetProperty("start")), frames.ToArray()));
        }
        return new RealCellsFile(Path.GetFileName(path).Replace(".json.gz", "", StringComparison.Ordinal), scene, movers);
    }

    private static MoverState StartState(JsonElement start)
    {
        var r = start.GetProperty("rotation");
        var state = new MoverState
        {
            Position = new Position(Hex(start.GetProperty("cell")),
                new Frame(Vec(start.GetProperty("position")), new Quaternion(r[1].GetSingle(), r[2].GetSingle(), r[3].GetSingle(), r[0].GetSingle()))),
            Contact = start.GetProperty("contact").GetInt32() == 1,
            OnWalkable = start.GetProperty("walkable").GetInt32() == 1,
        };
        if (start.TryGetProperty("contactPlane", out var plane) && plane.ValueKind == JsonValueKind.Array)
        {
            state.ContactPlane = new Plane(Vec(plane), plane[3].GetSingle());
            state.ContactPlaneCellId = Hex(start.GetProperty("contactPlaneCell"));
        }
        if (start.TryGetProperty("sliding", out var sliding) && sliding.ValueKind == JsonValueKind.Array)
        {
            state.SlidingNormalValid = true;
            state.SlidingNormal = Vec(sliding);
        }
        return state;
    }

    private static Vector3 Vec(JsonElement e) => new(e[0].GetSingle(), e[1].GetSingle(), e[2].GetSingle());

    private static uint Hex(JsonElement e) => uint.Parse(e.GetString()!.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);
}
