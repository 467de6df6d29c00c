using System;
using System.Collections.Generic;
using DatReaderWriter.DBObjs;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// A <see cref="PhysicsWorld"/> filled from the retail DAT files, landblock by landblock: the terrain (LandBlock
/// 0xXXYYFFFF through the Region's height table), the env cells (0xXXYY0100 up, as many as the LandBlockInfo counts,
/// every one present) on their Environments' structures, the buildings and the static objects (LandBlockInfo 0xXXYYFFFE and
/// the env cells'). The LandBlockInfo is read when the LandBlock's <c>HasObjects</c> flag is set (and must then be there),
/// and not at all when it is clear, as retail does. A landblock is loaded whole or not at all: anything missing or refused throws (a
/// <see cref="DatReadException"/> or <see cref="DatObjectException"/> naming the DAT file and object id) and the
/// world is left as it was. Models, setups and cell structures are converted once and kept in
/// <see cref="DatFiles.Converted"/>, shared with every other world made from the same files; the Region's height
/// table, a constant of the whole world, is read once per opened <see cref="DatFiles"/> and kept apart from them.
/// </summary>
/// <remarks>
/// Threads: <see cref="Read"/> (the DAT reads and conversions, nearly all of a load's time) may run on any thread
/// while engines and queries use the world; <see cref="Add"/>, <see cref="LoadLandblock"/>,
/// <see cref="UnloadLandblock"/> and <see cref="StreamAround"/> change the world and follow its single-writer rule
/// (no engine or query meanwhile), as <see cref="PhysicsWorld.LoadLandblock"/> does.
/// </remarks>
public sealed class DatWorld
{
    /// <summary>The Region object of the portal DAT (its LandDefs hold the height table).</summary>
    public const uint RegionId = 0x1300_0000;

    /// <summary>The most static objects a landblock may place in all (its LandBlockInfo's and its env cells'): the ids of <see cref="DefaultDescription"/> number them in 12 bits.</summary>
    public const int MaxStaticObjects = 4096;

    private readonly DatObjectDescriber _describe;
    private readonly Dictionary<uint, DatLandblock> _loaded = new();

    /// <summary>Makes a world over the files (an empty <see cref="PhysicsWorld"/> unless one is given).</summary>
    /// <param name="files">The open DAT files; several worlds may share them.</param>
    /// <param name="world">The world to fill (it may hold landblocks and objects of the host's too).</param>
    /// <param name="describe">The game's description of each static object; <see cref="DefaultDescription"/> when null.</param>
    public DatWorld(DatFiles files, PhysicsWorld? world = null, DatObjectDescriber? describe = null)
    {
        Files = files ?? throw new ArgumentNullException(nameof(files));
        World = world ?? new PhysicsWorld();
        _describe = describe ?? DefaultDescription;
    }

    /// <summary>The DAT files read.</summary>
    public DatFiles Files { get; }
    /// <summary>The world filled.</summary>
    public PhysicsWorld World { get; }
    /// <summary>The landblocks loaded through this instance.</summary>
    public IReadOnlyCollection<uint> Loaded => _loaded.Keys;

    /// <summary>The landblock loaded through this instance, or null.</summary>
    public DatLandblock? LoadedLandblock(uint landblock) => _loaded.GetValueOrDefault(landblock);

    /// <summary>
    /// The default description of a DAT static object: id <c>0x7000_0000 | landblock &lt;&lt; 12 | index</c> (unique per
    /// landblock and index, outside the ranges the game gives its dynamic objects), scale 1, state
    /// <see cref="PhysicsState.Static"/>, no flags.
    /// </summary>
    public static DatObjectDescription DefaultDescription(uint landblock, int index, uint owner, int ownerIndex, DatPlacement placement) =>
        new(0x7000_0000u | (landblock & 0xFFFF) << 12 | (uint)index, 1f, PhysicsState.Static, ShadowFlags.None);

    /// <summary>Reads and converts a landblock without touching the world; any thread.</summary>
    /// <param name="landblock">The landblock id (0xXXYY).</param>
    /// <exception cref="DatReadException">A file or an object is absent, of another type or unreadable; the message names the file and id.</exception>
    /// <exception cref="DatObjectException">An object is refused (a polygon, a tree, a count, a frame); the message names the file and id.</exception>
    public DatLandblock Read(uint landblock)
    {
        if (landblock > 0xFFFF)
            throw new ArgumentOutOfRangeException(nameof(landblock), $"landblock 0x{landblock:X}: a landblock id is 16 bits (0xXXYY).");
        try
        {
            return ReadUnchecked(landblock);
        }
        catch (DatObjectException ex) when (ex.File is null)
        {
            throw ex.InFile(IsPortalId(ex.ObjectId) ? Files.PortalName : Files.CellName);
        }
    }

    private DatLandblock ReadUnchecked(uint landblock)
    {
        uint prefix = landblock << 16;
        var land = Files.ReadCell<LandBlock>(prefix | 0xFFFF);
        var terrain = DatTerrain.ToTerrain(land, Files.RegionLandDefs());
        var info = Info(land, prefix);

        int cellCount = (int)Math.Min(info?.NumCells ?? 0, 0xFFFE - 0x0100u);
        if (info is not null && info.NumCells != cellCount)
            throw new DatObjectException(info.Id, $"numCells: {info.NumCells} cells do not fit a landblock (at most {0xFFFE - 0x0100}).");
        var datCells = new DatEnvCell[cellCount];
        var envCells = new EnvCell[cellCount];
        // The Environments this load has read. A landblock's cells share them (the cells of one building are
        // structures of one Environment) and DatReaderWriter unpacks an Environment whole, every structure of it,
        // so each is read at most once per load. Made on the first structure not yet converted: a load whose
        // structures are all converted already reads none and makes none.
        Dictionary<uint, DatEnvironment>? environments = null;
        // A landblock's env cells are 0x0100 to 0x0100 + num_cells - 1, every one present (CLandBlockInfo::num_cells,
        // the first field CLandBlockInfo::UnPack reads; ACE's Landblock.get_envcells and AdjustCell read them so).
        for (int i = 0; i < cellCount; i++)
        {
            uint id = prefix | (0x0100u + (uint)i);
            if (!Files.CellContains(id))
                throw new DatObjectException(info!.Id, $"numCells: {info.NumCells} cells (0x{prefix | 0x0100:X8} up), but {Files.CellName} has no env cell 0x{id:X8}.");
            var datCell = datCells[i] = Files.ReadCell<DatEnvCell>(id);
            envCells[i] = DatCells.ToEnvCell(datCell, CellStructure(DatCells.EnvironmentIdOf(datCell), datCell.CellStructure, ref environments));
        }

        int buildingCount = info?.Buildings?.Count ?? 0;
        var buildings = new Building[buildingCount];
        for (int i = 0; i < buildingCount; i++)
        {
            uint modelId = info!.Buildings[i].ModelId;
            buildings[i] = (modelId >> 24) == 0x02
                ? DatLandblocks.ToBuilding(info, i, Setup(modelId))
                : DatLandblocks.ToBuilding(info, i, Model(modelId) ?? throw new DatObjectException(info.Id, $"buildings[{i}].modelId: GfxObj 0x{modelId:X8} has no physics, so no shell."));
        }

        var placements = new List<(uint Owner, int Index, DatPlacement Placement)>();
        if (info is not null)
            Collect(placements, info.Id, DatLandblocks.Objects(info));
        foreach (var datCell in datCells)
            Collect(placements, datCell.Id, DatCells.StaticObjects(datCell));
        if (placements.Count > MaxStaticObjects)
            throw new DatObjectException(prefix | 0xFFFE, $"objects: a landblock places at most {MaxStaticObjects} static objects (with its cells'), got {placements.Count}.");
        var objects = new DatStaticObject[placements.Count];
        var ids = new HashSet<uint>();
        for (int i = 0; i < objects.Length; i++)
        {
            var (owner, ownerIndex, p) = placements[i];
            var description = _describe(landblock, i, owner, ownerIndex, p);
            if (!ids.Add(description.Id))
                throw new DatObjectException(prefix | 0xFFFE, $"objects[{i}]: the describer gave id 0x{description.Id:X8} twice.");
            objects[i] = new DatStaticObject(description, p.ModelId, Setup(p.ModelId), p.Position);
        }
        return new DatLandblock(landblock, terrain, envCells, buildings, objects);
    }

    /// <summary>
    /// The landblock's LandBlockInfo as retail finds it: only when the LandBlock's flag says it has one
    /// (<c>HasObjects</c>, retail <c>CLandBlock::lbi_exists</c>, the first field <c>CLandBlock::UnPack</c> reads,
    /// acclient.c 351520). <c>CLandBlock::InitLoad</c> (acclient.c 352062) fetches 0xXXYYFFFE only then, and fails
    /// the landblock when it is absent; with the flag clear it loads the landblock without one, whatever the file
    /// holds, so no buildings (<c>init_buildings</c>, 352113), no static objects (<c>init_static_objs</c>, 352786)
    /// and no env cells counted.
    /// </summary>
    private LandBlockInfo? Info(LandBlock land, uint prefix)
    {
        if (!land.HasObjects)
            return null;
        uint infoId = prefix | 0xFFFE;
        if (!Files.CellContains(infoId))
            throw new DatObjectException(prefix | 0xFFFF, $"hasObjects: set (the landblock has a LandBlockInfo), but {Files.CellName} has no LandBlockInfo 0x{infoId:X8}.");
        return Files.ReadCell<LandBlockInfo>(infoId);
    }

    private static void Collect(List<(uint, int, DatPlacement)> into, uint owner, IReadOnlyList<DatPlacement> placements)
    {
        for (int i = 0; i < placements.Count; i++)
            into.Add((owner, i, placements[i]));
    }

    /// <summary>
    /// Adds a landblock read by <see cref="Read"/>: its cells and buildings (<see cref="PhysicsWorld.LoadLandblock"/>),
    /// then its objects, skipping those still registered (an object that kept rows in a loaded neighbour). All or
    /// nothing: if anything is refused, what was added is taken out again and the exception is rethrown.
    /// </summary>
    /// <exception cref="ArgumentException">The landblock is already loaded, or the world refuses a cell, portal, building or object; the message names it.</exception>
    public void Add(DatLandblock block)
    {
        ArgumentNullException.ThrowIfNull(block);
        World.LoadLandblock(block.Terrain, block.EnvCells, block.Buildings);
        var registered = new List<uint>(block.Objects.Count);
        try
        {
            foreach (var o in block.Objects)
            {
                var d = o.Description;
                if (World.Objects.Contains(d.Id))
                    continue;
                World.Objects.Register(d.Id, o.Setup, o.Position, d.Scale, d.State, d.Flags);
                registered.Add(d.Id);
            }
        }
        catch
        {
            Undo(block.Landblock, registered);
            throw;
        }
        _loaded[block.Landblock] = block;
    }

    // Takes out what a refused Add put in. Its own method: a loop inside a catch block has the whole method
    // compiled fully optimized at its first call, which costs a process's first load more than Add's quick first
    // compilation.
    private void Undo(uint landblock, List<uint> registered)
    {
        foreach (uint id in registered)
            World.Objects.Unregister(id);
        World.UnloadLandblock(landblock);
    }

    /// <summary>Reads and adds a landblock (<see cref="Read"/> then <see cref="Add"/>).</summary>
    /// <exception cref="DatReadException">See <see cref="Read"/>.</exception>
    /// <exception cref="DatObjectException">See <see cref="Read"/>.</exception>
    /// <exception cref="ArgumentException">See <see cref="Add"/>.</exception>
    public DatLandblock LoadLandblock(uint landblock)
    {
        var block = Read(landblock);
        Add(block);
        return block;
    }

    /// <summary>
    /// Removes a landblock loaded through this instance, as <see cref="PhysicsWorld.UnloadLandblock"/> does: its
    /// cells and buildings and its objects' rows there (an object still listed in a loaded neighbour stays).
    /// </summary>
    /// <exception cref="ArgumentException">The landblock was not loaded through this instance.</exception>
    public void UnloadLandblock(uint landblock)
    {
        if (!_loaded.ContainsKey(landblock))
            throw new ArgumentException($"landblock 0x{landblock:X4}: was not loaded from the DAT files.", nameof(landblock));
        World.UnloadLandblock(landblock);
        _loaded.Remove(landblock);
    }

    /// <summary>
    /// Keeps the (2 <paramref name="radius"/> + 1)² landblocks around <paramref name="centre"/> loaded: unloads
    /// those loaded through this instance outside the window, then loads those inside not yet loaded (ones the
    /// cell DAT does not hold, past the map's edge or ocean without a LandBlock, are skipped). Each load is whole
    /// or not at all; a failure stops the call with the landblocks before it streamed.
    /// </summary>
    /// <param name="centre">The mover's landblock (0xXXYY).</param>
    /// <param name="radius">Landblocks on each side (1: the 3 × 3 window).</param>
    /// <returns>How many landblocks were loaded and unloaded.</returns>
    public (int Loaded, int Unloaded) StreamAround(uint centre, int radius = 1)
    {
        if (radius is < 0 or > 8)
            throw new ArgumentOutOfRangeException(nameof(radius), $"radius: 0 to 8 landblocks, got {radius}.");
        int cx = (int)(centre >> 8 & 0xFF), cy = (int)(centre & 0xFF);
        int unloaded = 0, loaded = 0;
        foreach (uint lb in new List<uint>(_loaded.Keys))
            if (Math.Abs((int)(lb >> 8) - cx) > radius || Math.Abs((int)(lb & 0xFF) - cy) > radius)
            {
                UnloadLandblock(lb);
                unloaded++;
            }
        for (int x = cx - radius; x <= cx + radius; x++)
            for (int y = cy - radius; y <= cy + radius; y++)
            {
                if (x is < 0 or > 0xFF || y is < 0 or > 0xFF)
                    continue;
                uint lb = (uint)(x << 8 | y);
                if (_loaded.ContainsKey(lb) || World.Cells.HasLandblock(lb) || !Files.CellContains(lb << 16 | 0xFFFF))
                    continue;
                LoadLandblock(lb);
                loaded++;
            }
        return (loaded, unloaded);
    }

    /// <summary>The physics model of a GfxObj (null when it has no physics), converted once.</summary>
    /// <exception cref="DatReadException">It is absent, of another type or unreadable.</exception>
    /// <exception cref="DatObjectException">Its physics is refused.</exception>
    public PhysicsModel? Model(uint gfxObjId) =>
        // The conversion takes the files as its state: a cached model is found without making a closure.
        Files.Converted.GetOrAdd(gfxObjId, Files, static (id, files) => new ModelEntry(DatModels.ToPhysicsModel(files.ReadPortal<GfxObj>(id)))).Model;

    /// <summary>The setup of a model id as a static object uses it: a Setup (0x02…) converted, or a GfxObj (0x01…) as one part; converted once.</summary>
    /// <exception cref="DatReadException">It or one of its parts is absent, of another type or unreadable.</exception>
    /// <exception cref="DatObjectException">It is refused.</exception>
    public PhysicsSetup Setup(uint modelId) =>
        Files.Converted.GetOrAdd(modelId, this, static (id, world) => (id >> 24) == 0x01
            ? DatSetups.FromModel(world.Model(id))
            : DatSetups.ToPhysicsSetup(world.Files.ReadPortal<Setup>(id), world.Model));

    private DatCellStructure CellStructure(uint environmentId, ushort index, ref Dictionary<uint, DatEnvironment>? environments)
    {
        // One cache key per structure: the environment's low 16 bits and the structure's index.
        uint key = (environmentId & 0xFFFF) << 16 | index;
        if (Files.Converted.TryGet(key, out DatCellStructure? converted))
            return converted;
        var environment = EnvironmentOfLoad(environmentId, ref environments);
        // The structure's index is the key's low 16 bits; the state is only the Environment (a reference: the cache's
        // code for it is the one Model and Setup use, nothing more for a first load to compile).
        return Files.Converted.GetOrAdd(key, environment, static (k, e) => DatCells.ToCellStructure(e, k & 0xFFFF));
    }

    // The Environment as this load read it, reading it on the load's first request.
    private DatEnvironment EnvironmentOfLoad(uint environmentId, ref Dictionary<uint, DatEnvironment>? environments)
    {
        environments ??= new Dictionary<uint, DatEnvironment>();
        if (!environments.TryGetValue(environmentId, out var environment))
        {
            environment = Files.ReadPortal<DatEnvironment>(environmentId);
            environments.Add(environmentId, environment);
        }
        return environment;
    }


    private static bool IsPortalId(uint id) => (id >> 24) is 0x01 or 0x02 or 0x03 or 0x09 or 0x0D or 0x13;

    // A model may be null (a GfxObj without physics); the cache holds objects.
    private sealed record ModelEntry(PhysicsModel? Model);
}
