using DatReaderWriter;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Lib.IO;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;
using DatLandDefs = DatReaderWriter.Types.LandDefs;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>
/// A simple, test-side assembly of a world from two DAT files through the adapter's conversions: for each
/// landblock its LandBlock, its env cells (ids from 0x0100 up, as many as the LandBlockInfo counts) on their
/// Environments' structures, its buildings, then its static objects (the LandBlockInfo's in order, then each
/// env cell's) registered with the game-side descriptions. Models and setups are converted once per id.
/// </summary>
internal sealed class DatWorldAssembly(DatDatabase portal, DatDatabase cell, DatLandDefs landDefs, Func<uint, int, ObjectDescription> describe)
{
    private readonly Dictionary<uint, PhysicsModel?> _models = new();
    private readonly Dictionary<uint, PhysicsSetup> _setups = new();

    public PhysicsWorld Load(IEnumerable<uint> landblocks)
    {
        var world = new PhysicsWorld();
        foreach (uint block in landblocks)
            LoadLandblock(world, block);
        return world;
    }

    public void LoadLandblock(PhysicsWorld world, uint block)
    {
        var terrain = DatTerrain.ToTerrain(Get<LandBlock>(cell, (block << 16) | 0xFFFF), landDefs);
        cell.TryGet<LandBlockInfo>((block << 16) | 0xFFFE, out var info);
        var datCells = new List<DatEnvCell>();
        for (uint id = 0x0100; info is not null && datCells.Count < info.NumCells && id < 0xFFFE; id++)
            if (cell.TryGet<DatEnvCell>((block << 16) | id, out var envCell))
                datCells.Add(envCell);
        var envCells = new List<EnvCell>();
        foreach (var datCell in datCells)
        {
            var environment = Get<DatEnvironment>(portal, DatCells.EnvironmentIdOf(datCell));
            envCells.Add(DatCells.ToEnvCell(datCell, DatCells.ToCellStructure(environment, datCell.CellStructure)));
        }
        var buildings = new List<Building>();
        for (int i = 0; i < (info?.Buildings.Count ?? 0); i++)
        {
            var shell = Model(info!.Buildings[i].ModelId) ?? throw new DatObjectException(info.Id, $"buildings[{i}]: model 0x{info.Buildings[i].ModelId:X8} has no physics.");
            buildings.Add(DatLandblocks.ToBuilding(info, i, shell));
        }
        world.LoadLandblock(terrain, envCells, buildings);
        if (info is not null)
            Register(world, info.Id, DatLandblocks.Objects(info));
        foreach (var datCell in datCells)
            Register(world, datCell.Id, DatCells.StaticObjects(datCell));
    }

    private void Register(PhysicsWorld world, uint owner, IReadOnlyList<DatPlacement> placements)
    {
        for (int i = 0; i < placements.Count; i++)
        {
            var d = describe(owner, i);
            world.Objects.Register(d.Id, Setup(placements[i].ModelId), placements[i].Position, d.Scale, d.State, d.Flags);
        }
    }

    private PhysicsSetup Setup(uint id)
    {
        if (_setups.TryGetValue(id, out var setup))
            return setup;
        setup = (id >> 24) == 0x01 ? DatSetups.FromModel(Model(id)) : DatSetups.ToPhysicsSetup(Get<Setup>(portal, id), Model);
        _setups.Add(id, setup);
        return setup;
    }

    private PhysicsModel? Model(uint id)
    {
        if (!_models.TryGetValue(id, out var model))
            _models.Add(id, model = DatModels.ToPhysicsModel(Get<GfxObj>(portal, id)));
        return model;
    }

    private static T Get<T>(DatDatabase dat, uint id) where T : IDBObj =>
        dat.TryGet<T>(id, out var value) ? value : throw new DatObjectException(id, $"is not in {Path.GetFileName(dat.Options.FilePath)} as a {typeof(T).Name}.");
}
