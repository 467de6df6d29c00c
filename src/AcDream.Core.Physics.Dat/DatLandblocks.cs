using System;
using System.Collections.Generic;
using DatReaderWriter.DBObjs;

namespace AcDream.Core.Physics.Dat;

/// <summary>A LandBlockInfo (cell DAT 0xXXYYFFFE, retail CLandBlockInfo): the landblock's static objects and buildings.</summary>
public static class DatLandblocks
{
    /// <summary>The most static objects a landblock may place.</summary>
    public const int MaxObjects = 4096;

    /// <summary>The most buildings a landblock may have (the DAT stores the count in 16 bits).</summary>
    public const int MaxBuildings = 1024;

    /// <summary>The most portals a building may have.</summary>
    public const int MaxBuildingPortals = 256;

    /// <summary>
    /// The landblock's static objects in stored order (<c>Objects</c>, retail <c>object_ids</c> and
    /// <c>object_frames</c>): each model id at its frame, which is landblock-local; the cell is the land cell
    /// below the origin (<see cref="Position.Outdoor"/>, retail <c>LandDefs::adjust_to_outside</c>).
    /// </summary>
    /// <exception cref="DatObjectException">More than <see cref="MaxObjects"/>, an entry without its frame, a frame outside the world, or one the world would refuse (an origin beyond the coordinate limit, a rotation it cannot normalize); the message names the LandBlockInfo id.</exception>
    public static IReadOnlyList<DatPlacement> Objects(LandBlockInfo info)
    {
        ArgumentNullException.ThrowIfNull(info);
        var stabs = info.Objects;
        if (stabs is null)
            return Array.Empty<DatPlacement>();
        if (stabs.Count > MaxObjects)
            throw new DatObjectException(info.Id, $"objects: a landblock places at most {MaxObjects} objects (DatLandblocks.MaxObjects), got {stabs.Count}.");
        var result = new DatPlacement[stabs.Count];
        for (int i = 0; i < stabs.Count; i++)
        {
            var stab = stabs[i] ?? throw new DatObjectException(info.Id, $"objects[{i}]: is null.");
            result[i] = new DatPlacement(stab.Id, Outdoor(info.Id, stab.Frame, $"objects[{i}].frame"));
        }
        return result;
    }

    /// <summary>
    /// Building <paramref name="index"/> of the landblock (<c>Buildings[index]</c>, retail <c>CBuildingObj</c>):
    /// the shell model of its <c>ModelId</c>, placed at its landblock-local <c>Frame</c> in the land cell below,
    /// with the env cells its portals lead into (<c>Portals[j].OtherCellId</c> in this landblock, each once, in
    /// order) as its entrances. Portal flags, stab lists, leaf counts and the restriction table are not read.
    /// Whether the entrance cells exist is checked when the building is added to a world.
    /// </summary>
    /// <param name="info">The LandBlockInfo as read.</param>
    /// <param name="index">The building's index in <c>Buildings</c>.</param>
    /// <param name="shell">The model of the building's <c>ModelId</c> (a GfxObj's, <see cref="DatModels.ToPhysicsModel"/>).</param>
    /// <exception cref="DatObjectException">The index is out of range, a count is beyond the limits, or the runtime refuses the building; the message names the LandBlockInfo id.</exception>
    public static Building ToBuilding(LandBlockInfo info, int index, PhysicsModel shell)
    {
        ArgumentNullException.ThrowIfNull(shell);
        return ToBuilding(info, index, shell, Frame.Identity, combine: false);
    }

    /// <summary>
    /// Building <paramref name="index"/> of the landblock whose <c>ModelId</c> is a Setup (0x02…): retail makes the
    /// building's part array from the setup (<c>CBuildingObj::makeBuilding</c> → <c>CPhysicsObj::InitPartArrayObject</c>
    /// → <c>CPartArray::CreateSetup</c>; acclient.c 719152, 319645, 326946) but collides only its first part
    /// (<c>CBuildingObj::find_building_collisions</c>, acclient.c 719115: <c>parts[0]</c>; ACE's
    /// <c>BuildingObj.find_building_collisions</c> the same), so the shell is part 0's model, placed at the building's
    /// frame combined with part 0's placement frame (<see cref="Frame.Combine"/>, retail <c>Frame::combine</c> for
    /// an object's parts). The other parts and the setup's spheres and cylinder-spheres take no part in collisions.
    /// Otherwise as <see cref="ToBuilding(LandBlockInfo, int, PhysicsModel)"/>.
    /// </summary>
    /// <param name="info">The LandBlockInfo as read.</param>
    /// <param name="index">The building's index in <c>Buildings</c>.</param>
    /// <param name="setup">The setup of the building's <c>ModelId</c> (<see cref="DatSetups.ToPhysicsSetup"/>).</param>
    /// <exception cref="DatObjectException">As the other overload, or the setup has no parts, its first part no physics, or a default scale other than 1 (a <see cref="Building"/> collides its shell at scale 1); the message names the LandBlockInfo id.</exception>
    public static Building ToBuilding(LandBlockInfo info, int index, PhysicsSetup setup)
    {
        ArgumentNullException.ThrowIfNull(info);
        ArgumentNullException.ThrowIfNull(setup);
        uint modelId = index >= 0 && index < (info.Buildings?.Count ?? 0) ? info.Buildings![index]?.ModelId ?? 0 : 0;
        if (setup.Parts.Count == 0)
            throw new DatObjectException(info.Id, $"buildings[{index}].modelId: Setup 0x{modelId:X8} has no parts; a building collides by its first part.");
        var part = setup.Parts[0];
        if (part.Model is null)
            throw new DatObjectException(info.Id, $"buildings[{index}].modelId: Setup 0x{modelId:X8}'s first part has no physics, so no shell.");
        if (part.DefaultScale != 1f)
            throw new DatObjectException(info.Id, $"buildings[{index}].modelId: Setup 0x{modelId:X8}'s first part has default scale {part.DefaultScale}; a building's shell is collided at scale 1.");
        return ToBuilding(info, index, part.Model, part.Frame, combine: true);
    }

    private static Building ToBuilding(LandBlockInfo info, int index, PhysicsModel shell, Frame partFrame, bool combine)
    {
        ArgumentNullException.ThrowIfNull(info);
        int count = info.Buildings?.Count ?? 0;
        if (count > MaxBuildings)
            throw new DatObjectException(info.Id, $"buildings: a landblock has at most {MaxBuildings} buildings (DatLandblocks.MaxBuildings), got {count}.");
        if (index < 0 || index >= count)
            throw new DatObjectException(info.Id, $"buildings[{index}]: the landblock has {count} buildings.");
        var building = info.Buildings![index] ?? throw new DatObjectException(info.Id, $"buildings[{index}]: is null.");
        var position = Outdoor(info.Id, building.Frame, $"buildings[{index}].frame");
        if (combine)
            position.Frame = position.Frame.Combine(partFrame);
        var portals = building.Portals;
        if ((portals?.Count ?? 0) > MaxBuildingPortals)
            throw new DatObjectException(info.Id, $"buildings[{index}].portals: a building has at most {MaxBuildingPortals} portals, got {portals!.Count}.");
        var entrances = new List<uint>(portals?.Count ?? 0);
        uint landblock = info.Id >> 16;
        for (int j = 0; j < (portals?.Count ?? 0); j++)
        {
            var portal = portals![j] ?? throw new DatObjectException(info.Id, $"buildings[{index}].portals[{j}]: is null.");
            uint cell = (landblock << 16) | portal.OtherCellId;
            if (!entrances.Contains(cell))
                entrances.Add(cell);
        }
        try
        {
            return new Building(shell, position, entrances);
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(info.Id, $"buildings[{index}]: {ex.Message}", ex);
        }
    }

    private static Position Outdoor(uint infoId, DatReaderWriter.Types.Frame? frame, string field)
    {
        if ((infoId & 0xFFFF) != 0xFFFE)
            throw new DatObjectException(infoId, "id: a LandBlockInfo's id is 0xXXYYFFFE.");
        var local = DatSetups.ToPlacementFrame(frame, infoId, field);
        Position position;
        try
        {
            position = Position.Outdoor(infoId >> 16, local.Origin);
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(infoId, $"{field}: {ex.Message}", ex);
        }
        position.Frame.Orientation = local.Orientation;
        return position;
    }
}
