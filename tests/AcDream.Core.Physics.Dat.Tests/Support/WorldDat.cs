using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatCylSphere = DatReaderWriter.Types.CylSphere;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;
using DatFrame = DatReaderWriter.Types.Frame;
using DatLandDefs = DatReaderWriter.Types.LandDefs;
using DatSphere = DatReaderWriter.Types.Sphere;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>
/// A world we trust (a scene's, loaded by the scene loader) written out as the DAT objects retail would
/// hold for it: every model a GfxObj, every setup a Setup, every env cell an EnvCell on an Environment of
/// its own, every landblock a LandBlock (heights through a height table made of the heights it uses) and
/// a LandBlockInfo (its outdoor objects and buildings). The objects' game-side descriptions are kept beside,
/// keyed by where the DAT places them (the LandBlockInfo's or the env cell's id and the index in its list).
/// </summary>
internal sealed class WorldDat
{
    public List<GfxObj> GfxObjs { get; } = new();
    public List<Setup> Setups { get; } = new();
    public List<DatEnvironment> Environments { get; } = new();
    public List<LandBlock> LandBlocks { get; } = new();
    public List<LandBlockInfo> Infos { get; } = new();
    public List<DatEnvCell> EnvCells { get; } = new();
    public DatLandDefs LandDefs { get; } = new() { LandHeightTable = new float[256], NumBlockLength = 255, NumBlockWidth = 255, SquareLength = 24, LBlockLength = 8, VertexPerCell = 1 };
    public List<uint> Landblocks { get; } = new();
    public Dictionary<(uint Owner, int Index), ObjectDescription> Objects { get; } = new();

    private readonly Dictionary<PhysicsModel, uint> _models = new(ReferenceEqualityComparer.Instance);
    private readonly Dictionary<PhysicsSetup, uint> _setups = new(ReferenceEqualityComparer.Instance);
    private uint _noPhysics;
    private DatEnvironment? _filler;

    /// <summary>
    /// Writes <paramref name="world"/>. The runtime keeps no terrain words once a landblock's cells are built, so
    /// they are read from the scene's text when given (a landblock's "terrainType" or "terrainTypes", each type
    /// as a word's bits 2–6); without it, or for a landblock that gives none, every word is 0 (dry).
    /// </summary>
    public static WorldDat From(PhysicsWorld world, string? sceneJson = null)
    {
        var dat = new WorldDat();
        var blocks = world.Cells.CellIds.Select(id => id >> 16).Distinct().OrderBy(b => b).ToList();
        var heights = new SortedSet<float>();
        var grids = blocks.ToDictionary(b => b, b => Heights(world, b));
        foreach (var grid in grids.Values)
            foreach (float h in grid)
                heights.Add(h);
        if (heights.Count > 256)
            throw new InvalidOperationException($"{heights.Count} distinct heights do not fit a 256-entry height table.");
        var table = heights.ToArray();
        table.CopyTo(dat.LandDefs.LandHeightTable, 0);

        var records = world.Objects.Records.ToList();
        var words = sceneJson is null ? new Dictionary<uint, ushort[]>() : TerrainWords(sceneJson);
        foreach (uint block in blocks)
        {
            dat.Landblocks.Add(block);
            var land = new LandBlock { Id = (block << 16) | 0xFFFF };
            for (int i = 0; i < 81; i++)
            {
                land.Height[i] = (byte)Array.IndexOf(table, grids[block][i]);
                land.Terrain[i] = words.TryGetValue(block, out var w) ? w[i] : (ushort)0;
            }
            dat.LandBlocks.Add(land);

            var info = new LandBlockInfo { Id = (block << 16) | 0xFFFE };
            var envCells = world.Cells.EnvCellsOf(block).ToArray().OrderBy(c => c.Id).ToList();
            // A DAT holds every env cell of a landblock, 0x0100 up to 0x0100 + numCells - 1; a world holding only
            // some of them under their real ids (the real-cells scenes) gets a filler cell in each gap.
            uint last = envCells.Count == 0 ? 0x00FFu : envCells[^1].Id & 0xFFFF;
            info.NumCells = last - 0x00FFu;
            foreach (var record in records.Where(r => r.Position.CellId >> 16 == block && AcDream.Core.Physics.LandDefs.IsLandCell(r.Position.CellId)))
            {
                dat.Objects.Add((info.Id, info.Objects.Count), new ObjectDescription(record.Id, record.Scale, record.State, record.Flags));
                info.Objects.Add(new Stab { Id = dat.SetupId(record.Setup!), Frame = Frame(record.Position.Frame) });
            }
            for (uint i = 1; i <= 64; i++)
                if (world.Cells.Get((block << 16) | i) is LandCell { Building: { } building })
                {
                    var b = new BuildingInfo { ModelId = dat.ModelId(building.Shell), Frame = Frame(building.Position.Frame) };
                    foreach (uint entrance in building.EntranceCells)
                        b.Portals.Add(new BuildingPortal { OtherCellId = (ushort)entrance });
                    info.Buildings.Add(b);
                }
            // Retail's LandBlock says whether its LandBlockInfo exists (lbi_exists); one is written for every landblock.
            land.HasObjects = true;
            dat.Infos.Add(info);

            foreach (var cell in envCells)
                dat.EnvCells.Add(dat.Write(cell, records.Where(r => r.Position.CellId == cell.Id).ToList()));
            for (uint i = 0x0100; i <= last; i++)
                if (world.Cells.Get((block << 16) | i) is null)
                    dat.EnvCells.Add(dat.Filler((block << 16) | i));
        }
        return dat;
    }

    private static Dictionary<uint, ushort[]> TerrainWords(string sceneJson)
    {
        var result = new Dictionary<uint, ushort[]>();
        using var doc = System.Text.Json.JsonDocument.Parse(sceneJson, new System.Text.Json.JsonDocumentOptions
        {
            CommentHandling = System.Text.Json.JsonCommentHandling.Skip,
            AllowTrailingCommas = true,
        });
        foreach (var block in doc.RootElement.GetProperty("landblocks").EnumerateArray())
        {
            var idElement = block.GetProperty("id");
            uint id = idElement.ValueKind == System.Text.Json.JsonValueKind.Number
                ? idElement.GetUInt32()
                : Convert.ToUInt32(idElement.GetString()!.Replace("_", "", StringComparison.Ordinal), 16);
            if (block.TryGetProperty("terrainType", out var one))
                result[id] = Enumerable.Repeat((ushort)(one.GetInt32() << 2), 81).ToArray();
            else if (block.TryGetProperty("terrainTypes", out var each))
                result[id] = each.EnumerateArray().Select(t => (ushort)(t.GetInt32() << 2)).ToArray();
        }
        return result;
    }

    /// <summary>The 81 vertex heights of a landblock, read off its land cells' triangles (vertex x * 9 + y).</summary>
    private static float[] Heights(PhysicsWorld world, uint block)
    {
        var grid = new float[81];
        var seen = new bool[81];
        for (uint i = 1; i <= 64; i++)
        {
            var cell = (LandCell)world.Cells.Get((block << 16) | i)!;
            var (first, second) = cell.Triangles;
            foreach (var polygon in new[] { first, second })
                foreach (var v in polygon.Vertices)
                {
                    int x = (int)MathF.Round(v.X / 24f), y = (int)MathF.Round(v.Y / 24f);
                    grid[x * 9 + y] = v.Z;
                    seen[x * 9 + y] = true;
                }
        }
        if (seen.Contains(false))
            throw new InvalidOperationException($"landblock 0x{block:X4}: a terrain vertex was not found.");
        return grid;
    }

    private static DatFrame Frame(AcDream.Core.Physics.Frame frame) => new() { Origin = frame.Origin, Orientation = frame.Orientation };

    private DatEnvCell Write(EnvCell cell, List<ShadowObjectRegistry.Record> statics)
    {
        var vertices = DatObjects.NewVertexArray();
        var structure = new CellStruct { VertexArray = vertices, CellBSP = DatObjects.CellTree(cell.CellBsp) };
        if (cell.PhysicsBsp is null)
            throw new InvalidOperationException($"cell 0x{cell.Id:X8} has no physics tree; a DAT cell structure always has one.");
        structure.PhysicsBSP = DatObjects.PhysicsTree(cell.PhysicsBsp, vertices, structure.PhysicsPolygons);
        var env = new DatEnvironment { Id = 0x0D00_0000u | (uint)(Environments.Count + 1) };
        env.Cells.Add(0, structure);
        Environments.Add(env);
        var result = new DatEnvCell
        {
            Id = cell.Id,
            EnvironmentId = (ushort)env.Id,
            CellStructure = 0,
            Position = Frame(cell.Position.Frame),
            Flags = statics.Count > 0 ? EnvCellFlags.HasStaticObjs : 0,
        };
        foreach (var portal in cell.Portals)
        {
            ushort polygonId = (ushort)structure.Polygons.Count;
            structure.Polygons.Add(polygonId, DatObjects.Polygon(portal.Polygon, vertices));
            structure.Portals.Add(polygonId);
            result.CellPortals.Add(new DatReaderWriter.Types.CellPortal
            {
                // Retail decodes portal_side = !(flags & PortalSide).
                Flags = portal.PortalSide ? 0 : PortalFlags.PortalSide,
                PolygonId = polygonId,
                OtherCellId = (ushort)portal.OtherCellId,
            });
        }
        foreach (var record in statics)
        {
            Objects.Add((cell.Id, result.StaticObjects.Count), new ObjectDescription(record.Id, record.Scale, record.State, record.Flags));
            result.StaticObjects.Add(new Stab { Id = SetupId(record.Setup!), Frame = Frame(record.Position.Frame) });
        }
        return result;
    }

    /// <summary>
    /// A cell standing in for one the world does not hold: a 1 m box 100 m under the landblock's origin, with no
    /// portal and no object, so no cell search reaches it (cells are found through portals only) and it changes
    /// no collision. All fillers share one Environment.
    /// </summary>
    private DatEnvCell Filler(uint id)
    {
        if (_filler is null)
        {
            var vertices = DatObjects.NewVertexArray();
            var structure = new CellStruct { VertexArray = vertices, CellBSP = DatObjects.CellTree(BspShapes.CellBox(Vector3.Zero, Vector3.One)) };
            structure.PhysicsBSP = DatObjects.PhysicsTree(BspShapes.Box(Vector3.Zero, Vector3.One), vertices, structure.PhysicsPolygons);
            _filler = new DatEnvironment { Id = 0x0D00_0000u | (uint)(Environments.Count + 1) };
            _filler.Cells.Add(0, structure);
            Environments.Add(_filler);
        }
        return new DatEnvCell
        {
            Id = id,
            EnvironmentId = (ushort)_filler.Id,
            CellStructure = 0,
            Position = new DatFrame { Origin = new Vector3(0f, 0f, -100f), Orientation = Quaternion.Identity },
        };
    }

    private uint ModelId(PhysicsModel? model)
    {
        if (model is null)
        {
            if (_noPhysics == 0)
            {
                _noPhysics = 0x0100_0000u | (uint)(GfxObjs.Count + 1);
                GfxObjs.Add(DatObjects.GfxObj(_noPhysics, null));
            }
            return _noPhysics;
        }
        if (_models.TryGetValue(model, out uint id))
            return id;
        // The DAT has no bounding sphere of its own for a part: retail's is the root node's.
        if (!SameSphere(model.BoundingSphere, model.Bsp.Bounds))
            throw new InvalidOperationException($"model {model.Name}: its bounding sphere is not its tree's root sphere, which a GfxObj cannot hold.");
        id = 0x0100_0000u | (uint)(GfxObjs.Count + 1);
        _models.Add(model, id);
        GfxObjs.Add(DatObjects.GfxObj(id, model.Bsp));
        return id;
    }

    private static bool SameSphere(Sphere a, Sphere b) => a.Center.Equals(b.Center) && a.Radius.Equals(b.Radius);

    private uint SetupId(PhysicsSetup setup)
    {
        if (_setups.TryGetValue(setup, out uint id))
            return id;
        id = 0x0200_0000u | (uint)(Setups.Count + 1);
        _setups.Add(setup, id);
        int count = setup.Parts.Count;
        var frames = new AnimationFrame((uint)count);
        var result = new Setup
        {
            Id = id,
            Height = setup.Height,
            Radius = setup.Radius,
            StepUpHeight = setup.StepUpHeight,
            StepDownHeight = setup.StepDownHeight,
            SortingSphere = new DatSphere(),
            SelectionSphere = new DatSphere(),
        };
        bool scaled = setup.Parts.Any(p => p.DefaultScale != 1f);
        result.Flags = (scaled ? SetupFlags.HasDefaultScale : 0) | (setup.HasPhysicsBsp ? SetupFlags.HasPhysicsBSP : 0);
        foreach (var part in setup.Parts)
        {
            result.Parts.Add(ModelId(part.Model));
            frames.Frames.Add(Frame(part.Frame));
            if (scaled)
                result.DefaultScale.Add(new System.Numerics.Vector3(part.DefaultScale));
        }
        if (count > 0)
            result.PlacementFrames.Add(Placement.Default, frames);
        foreach (var c in setup.CylSpheres)
            result.CylSpheres.Add(new DatCylSphere { Origin = c.LowPoint, Radius = c.Radius, Height = c.Height });
        foreach (var s in setup.Spheres)
            result.Spheres.Add(new DatSphere { Origin = s.Center, Radius = s.Radius });
        Setups.Add(result);
        return id;
    }
}
