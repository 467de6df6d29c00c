using AcDream.Core.Physics.Bsp;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// One converted <c>CellStruct</c> of an Environment (portal DAT 0x0D00xxxx, retail CCellStruct): the physics
/// and containment trees every env cell built on it shares, and the structure as read, whose drawing polygons
/// the cells' portals name. Made by <see cref="DatCells.ToCellStructure"/>; immutable.
/// </summary>
public sealed class DatCellStructure
{
    internal DatCellStructure(uint environmentId, uint index, BspTree? physicsBsp, BspTree cellBsp, CellStruct source)
    {
        EnvironmentId = environmentId;
        Index = index;
        PhysicsBsp = physicsBsp;
        CellBsp = cellBsp;
        Source = source;
    }

    /// <summary>The Environment's id (0x0D00xxxx).</summary>
    public uint EnvironmentId { get; }
    /// <summary>The structure's key in the Environment's <c>Cells</c>.</summary>
    public uint Index { get; }
    /// <summary>The collision tree (<c>PhysicsBSP</c> over <c>PhysicsPolygons</c>), or null when the structure has none.</summary>
    public BspTree? PhysicsBsp { get; }
    /// <summary>The containment tree (<c>CellBSP</c>).</summary>
    public BspTree CellBsp { get; }
    internal CellStruct Source { get; }
}
