using System.Collections.Generic;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// A landblock read from the DAT files and converted, not yet in any world (<see cref="DatWorld.Read"/>): its
/// terrain, its env cells, its buildings and its static objects. Made on any thread; added to a world by
/// <see cref="DatWorld.Add"/> on the world's writer thread. Immutable.
/// </summary>
public sealed class DatLandblock
{
    internal DatLandblock(uint landblock, Terrain terrain, IReadOnlyList<EnvCell> envCells, IReadOnlyList<Building> buildings,
        IReadOnlyList<DatStaticObject> objects)
    {
        Landblock = landblock;
        Terrain = terrain;
        EnvCells = envCells;
        Buildings = buildings;
        Objects = objects;
    }

    /// <summary>The landblock id (0xXXYY).</summary>
    public uint Landblock { get; }
    /// <summary>Its terrain (64 land cells).</summary>
    public Terrain Terrain { get; }
    /// <summary>Its indoor cells, 0xXXYY0100 upwards.</summary>
    public IReadOnlyList<EnvCell> EnvCells { get; }
    /// <summary>Its buildings, in the LandBlockInfo's order.</summary>
    public IReadOnlyList<Building> Buildings { get; }
    /// <summary>Its static objects: the LandBlockInfo's, then each env cell's, in order.</summary>
    public IReadOnlyList<DatStaticObject> Objects { get; }
}
