using System;
using System.Collections.Generic;
using AcDream.Core.Physics.World;
namespace AcDream.Core.Physics;

/// <summary>Everything a transition collides with: the cells and the objects registered in them.</summary>
public sealed class PhysicsWorld
{
    /// <summary>Creates an empty world.</summary>
    public PhysicsWorld()
    {
        Cells = new CellGraph();
        Objects = new ShadowObjectRegistry(Cells);
    }

    /// <summary>The cells.</summary>
    public CellGraph Cells { get; }
    /// <summary>The objects.</summary>
    public ShadowObjectRegistry Objects { get; }

    /// <summary>
    /// Adds a landblock for streaming: its terrain's 64 land cells, then its env cells, then its buildings
    /// (each as <see cref="CellGraph.AddLandblock"/>, <see cref="CellGraph.AddEnvCells"/> and
    /// <see cref="CellGraph.AddBuilding"/> add them), then lists in its cells the objects already registered
    /// in it or in a landblock beside it (an object straddling the border from a loaded neighbour, or one of
    /// this landblock's objects that kept its rows in a neighbour while this landblock was away). Register the
    /// landblock's own objects afterwards, skipping those still registered
    /// (<see cref="ShadowObjectRegistry.Contains"/>). All or nothing: a landblock already loaded, an env cell
    /// or building not in this landblock, or one that cannot be added throws naming it, and the world is left
    /// as it was. Single writer, as every change of the world: a second thread loading or unloading a landblock, or
    /// changing the registry, meanwhile is refused with an <see cref="InvalidOperationException"/> before it changes
    /// anything (as the registry refuses a second writer), and the world stays usable.
    /// </summary>
    /// <exception cref="InvalidOperationException">Another thread is loading or unloading a landblock or changing the registry.</exception>
    public void LoadLandblock(Terrain terrain, IReadOnlyList<EnvCell>? envCells = null, IReadOnlyList<Building>? buildings = null)
    {
        ArgumentNullException.ThrowIfNull(terrain);
        Objects.BeginStreaming(nameof(LoadLandblock));
        try
        {
            Load(terrain, envCells, buildings);
        }
        finally
        {
            Objects.EndStreaming();
        }
    }

    private void Load(Terrain terrain, IReadOnlyList<EnvCell>? envCells, IReadOnlyList<Building>? buildings)
    {
        if (Cells.HasLandblock(terrain.Landblock))
            throw new ArgumentException($"landblock 0x{terrain.Landblock:X4}: is already loaded.", nameof(terrain));
        Cells.AddLandblock(terrain);
        try
        {
            if (envCells is not null)
                for (int i = 0; i < envCells.Count; i++)
                {
                    var env = envCells[i] ?? throw new ArgumentException($"envCells[{i}]: is null.", nameof(envCells));
                    if (env.Id >> 16 != terrain.Landblock)
                        throw new ArgumentException($"envCells[{i}]: cell 0x{env.Id:X8} is not in landblock 0x{terrain.Landblock:X4}.", nameof(envCells));
                }
            // Together: the landblock's cells lead into each other through their portals.
            if (envCells is not null)
                Cells.AddEnvCells(envCells);
            if (buildings is not null)
                for (int i = 0; i < buildings.Count; i++)
                {
                    var building = buildings[i] ?? throw new ArgumentException($"buildings[{i}]: is null.", nameof(buildings));
                    if (building.Position.CellId >> 16 != terrain.Landblock)
                        throw new ArgumentException($"buildings[{i}]: cell 0x{building.Position.CellId:X8} is not in landblock 0x{terrain.Landblock:X4}.", nameof(buildings));
                    Cells.AddBuilding(building);
                }
        }
        catch
        {
            // Nothing of this landblock was in the world before: take out all that was added.
            Cells.RemoveLandblock(terrain.Landblock);
            throw;
        }
        Objects.ListInLandblock(terrain.Landblock);
    }

    /// <summary>
    /// Removes a landblock: the rows of the objects listed in its land and env cells, then those cells and
    /// the buildings standing in them. An object listed in cells of other landblocks too keeps those rows and
    /// stays registered at its position (it still blocks movers on the loaded side of the border); an object
    /// left with no row is unregistered, as by <see cref="ShadowObjectRegistry.Unregister"/>. Engines and
    /// queries see the change at their next call; a mover whose state names a removed cell (its position or
    /// contact-plane cell) is then refused with an <see cref="ArgumentException"/> naming that cell, so a host
    /// unloads only landblocks its movers do not stand in or touch. Allocates nothing once the world has been
    /// loaded and unloaded before. Single writer: no engine or query may run meanwhile; a second thread loading or
    /// unloading a landblock, or changing the registry, is refused as by <see cref="LoadLandblock"/>.
    /// </summary>
    /// <param name="landblock">The landblock id (x byte, y byte: the high 16 bits of its cell ids).</param>
    /// <exception cref="ArgumentException">The landblock has no cell in the world; the message names it.</exception>
    /// <exception cref="InvalidOperationException">Another thread is loading or unloading a landblock or changing the registry.</exception>
    public void UnloadLandblock(uint landblock)
    {
        Objects.BeginStreaming(nameof(UnloadLandblock));
        try
        {
            if (!Cells.HasLandblock(landblock))
                throw new ArgumentException($"landblock 0x{landblock:X4}: is not loaded.", nameof(landblock));
            Objects.DropLandblock(landblock);
            Cells.RemoveLandblock(landblock);
        }
        finally
        {
            Objects.EndStreaming();
        }
    }
}
