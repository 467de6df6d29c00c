using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using AcDream.Core.Physics.Dat;
using AcDream.Core.Physics.Scenes;
using GfxObj = DatReaderWriter.DBObjs.GfxObj;
using LandBlock = DatReaderWriter.DBObjs.LandBlock;
using LandBlockInfo = DatReaderWriter.DBObjs.LandBlockInfo;
using Setup = DatReaderWriter.DBObjs.Setup;
using DatReaderWriter.Types;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;

namespace AcDream.Core.Physics.Tool;

/// <summary>
/// The tool's DAT side: <c>dat DIR [LANDBLOCK]</c> summarises the files or one landblock's physics content, and
/// <c>--dat DIR</c> gives run, query and plot a world loaded from the files instead of the scene's own.
/// </summary>
internal static class DatCommand
{
    /// <summary>The most landblocks the summary of the files lists by name.</summary>
    private const int ListedLandblocks = 32;

    public static int Run(string directory, string? landblockArg, TextWriter stdout)
    {
        using var files = DatFiles.Open(directory);
        if (landblockArg is null)
            return Files(files, stdout);
        uint landblock = ParseLandblock(landblockArg);
        var world = new DatWorld(files);
        var block = world.Read(landblock);
        Summarise(files, block, stdout);
        return 0;
    }

    /// <summary>A landblock id: 0xXXYY or XXYY in hex, or a cell id 0xXXYYCCCC (its landblock).</summary>
    internal static uint ParseLandblock(string text)
    {
        string hex = text.StartsWith("0x", StringComparison.OrdinalIgnoreCase) ? text[2..] : text;
        if (hex.Length is < 1 or > 8 || !uint.TryParse(hex, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint value))
            throw new Program.UsageException($"LANDBLOCK '{text}' is not a hex landblock id (0xXXYY) or cell id (0xXXYYCCCC)");
        return hex.Length > 4 ? value >> 16 : value;
    }

    private static int Files(DatFiles files, TextWriter stdout)
    {
        stdout.WriteLine(Program.Printable($"{files.PortalName}: {new FileInfo(files.PortalPath).Length} bytes; {files.CellName}: {new FileInfo(files.CellPath).Length} bytes"));
        var present = new List<uint>();
        for (uint lb = 0; lb <= 0xFFFF; lb++)
            if (files.CellContains(lb << 16 | 0xFFFF))
                present.Add(lb);
        string names = string.Join(" ", present.Take(ListedLandblocks).Select(lb => $"0x{lb:X4}"));
        stdout.WriteLine($"{Program.Count(present.Count, "landblock")}{(present.Count == 0 ? "" : ": " + names)}{(present.Count > ListedLandblocks ? " …" : "")}");
        return 0;
    }

    private static void Summarise(DatFiles files, DatLandblock block, TextWriter stdout)
    {
        int portals = 0, outside = 0, entrances = 0;
        int cellPolygons = 0, shellPolygons = 0, objectPolygons = 0;
        foreach (var cell in block.EnvCells)
        {
            portals += cell.Portals.Length;
            foreach (var p in cell.Portals)
                if (p.LeadsOutside) outside++;
            cellPolygons += cell.PhysicsBsp?.Polygons.Length ?? 0;
        }
        foreach (var b in block.Buildings)
        {
            entrances += b.EntranceCells.Length;
            shellPolygons += b.Shell.Bsp.Polygons.Length;
        }
        foreach (var o in block.Objects)
            foreach (var part in o.Setup.Parts)
                objectPolygons += part.Model?.Bsp.Polygons.Length ?? 0;

        // The deepest physics tree, measured on the DAT's own trees (leaves at depth 1).
        var (depth, owner) = (0, "none");
        void Consider(PhysicsBSPNode? root, string name)
        {
            int d = Depth(root);
            if (d > depth) (depth, owner) = (d, name);
        }
        uint prefix = block.Landblock << 16;
        foreach (var cell in block.EnvCells)
        {
            var datCell = files.ReadCell<DatEnvCell>(cell.Id);
            var environment = files.ReadPortal<DatEnvironment>(DatCells.EnvironmentIdOf(datCell));
            if (environment.Cells.TryGetValue(datCell.CellStructure, out var structure))
                Consider(structure.PhysicsBSP?.Root, $"env cell 0x{cell.Id:X8}");
        }
        // The LandBlockInfo the load read: only when the LandBlock's flag is set (retail's lbi_exists).
        bool hasInfo = files.ReadCell<LandBlock>(prefix | 0xFFFF).HasObjects;
        var models = new SortedSet<uint>();
        if (hasInfo)
            foreach (var b in files.ReadCell<LandBlockInfo>(prefix | 0xFFFE).Buildings)
                models.Add(b.ModelId);
        foreach (var o in block.Objects)
        {
            if (o.ModelId >> 24 == 0x01)
                models.Add(o.ModelId);
            else
                foreach (var part in files.ReadPortal<Setup>(o.ModelId).Parts)
                    models.Add(part.DataId);
        }
        foreach (uint model in models)
            Consider(files.ReadPortal<GfxObj>(model).PhysicsBSP?.Root, $"GfxObj 0x{model:X8}");

        float low = float.MaxValue, high = float.MinValue;
        for (int x = 0; x < Terrain.VerticesPerSide; x++)
            for (int y = 0; y < Terrain.VerticesPerSide; y++)
            {
                low = MathF.Min(low, block.Terrain.HeightAt(x, y));
                high = MathF.Max(high, block.Terrain.HeightAt(x, y));
            }
        int distinctModels = block.Objects.Select(o => o.ModelId).Distinct().Count();
        stdout.WriteLine($"landblock 0x{block.Landblock:X4}: 64 land cells (terrain {F(low)} to {F(high)} m), {Program.Count(block.EnvCells.Count, "env cell")} " +
            $"({Program.Count(portals, "portal")}, {outside} to outside), {Program.Count(block.Buildings.Count, "building")} ({Program.Count(entrances, "entrance cell")}), " +
            $"{Program.Count(block.Objects.Count, "static object")} ({Program.Count(distinctModels, "model")})");
        stdout.WriteLine($"physics polygons: {cellPolygons} in env cells, {shellPolygons} in building shells, {objectPolygons} in object parts; " +
            $"deepest physics BSP {depth} ({owner})");
        stdout.WriteLine(hasInfo
            ? $"hasObjects set: LandBlockInfo 0x{prefix | 0xFFFE:X8} read"
            : files.CellContains(prefix | 0xFFFE)
                ? $"hasObjects clear: LandBlockInfo 0x{prefix | 0xFFFE:X8} in the file, not read (retail reads it only when the flag is set)"
                : "hasObjects clear: no LandBlockInfo");
    }

    private static int Depth(PhysicsBSPNode? node)
    {
        if (node is null)
            return 0;
        // The trees were checked when converted (no cycle, at most the runtime's depth): plain recursion is safe.
        return 1 + Math.Max(Depth(node.PosNode), Depth(node.NegNode));
    }

    /// <summary>
    /// A scene's movers in a world loaded from the DAT files: the 3 × 3 landblocks around each mover's start
    /// (those the cell DAT holds), the first mover's landblock loaded first.
    /// </summary>
    public static Scene WithDatWorld(Scene scene, string directory)
    {
        using var files = DatFiles.Open(directory);
        var world = new DatWorld(files);
        foreach (var mover in scene.Movers)
        {
            uint centre = mover.Start.Position.CellId >> 16;
            if (!world.Loaded.Contains(centre) && !files.CellContains(centre << 16 | 0xFFFF))
                throw new InvalidDataException($"{files.CellName}: mover {mover.Name} starts in landblock 0x{centre:X4}, which the file does not hold.");
            LoadWindow(world, files, centre);
        }
        return scene.WithWorld(world.World);
    }

    private static void LoadWindow(DatWorld world, DatFiles files, uint centre)
    {
        // The centre first: query coordinates are local to the world's first landblock, the first mover's.
        if (!world.Loaded.Contains(centre))
            world.LoadLandblock(centre);
        for (int dx = -1; dx <= 1; dx++)
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = (int)(centre >> 8) + dx, y = (int)(centre & 0xFF) + dy;
                if (x is < 0 or > 0xFF || y is < 0 or > 0xFF)
                    continue;
                uint lb = (uint)(x << 8 | y);
                if (!world.Loaded.Contains(lb) && files.CellContains(lb << 16 | 0xFFFF))
                    world.LoadLandblock(lb);
            }
    }

    private static string F(float v) => v.ToString("0.##", CultureInfo.InvariantCulture);
}
