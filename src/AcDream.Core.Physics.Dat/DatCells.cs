using System;
using System.Collections.Generic;
using DatReaderWriter.Enums;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// Indoor cells: an Environment's cell structures (portal DAT 0x0D00xxxx) and the EnvCells (cell DAT
/// 0xXXYY0100 and up, retail CEnvCell) built on them.
/// </summary>
public static class DatCells
{
    /// <summary>The most portals an env cell may have (the DAT stores the count in a byte).</summary>
    public const int MaxPortals = 255;

    /// <summary>The most static objects an env cell may place.</summary>
    public const int MaxStaticObjects = 4096;

    /// <summary>
    /// Converts cell structure <paramref name="index"/> of an Environment: its physics BSP over its physics
    /// polygons (<see cref="DatGeometry.ToPhysicsBsp"/>; none when the tree has no root) and its containment
    /// BSP (<see cref="DatGeometry.ToCellBsp"/>). The drawing BSP, surfaces and vertex normals are not read;
    /// the drawing polygons only where a portal names one (<see cref="ToEnvCell"/>).
    /// </summary>
    /// <param name="environment">The Environment as read.</param>
    /// <param name="index">The structure's key in <c>Cells</c> (an EnvCell's <c>CellStructure</c>).</param>
    /// <exception cref="DatObjectException">The structure is missing or refused; the message names the Environment id and the structure.</exception>
    public static DatCellStructure ToCellStructure(DatEnvironment environment, uint index)
    {
        ArgumentNullException.ThrowIfNull(environment);
        uint id = environment.Id;
        if (environment.Cells is null || !environment.Cells.TryGetValue(index, out var structure) || structure is null)
            throw new DatObjectException(id, $"cells[{index}]: the environment has no cell structure {index}.");
        var physics = structure.PhysicsBSP?.Root is null
            ? null
            : DatGeometry.ToPhysicsBsp(id, $"cells[{index}].physicsBSP", structure.PhysicsBSP, structure.PhysicsPolygons, structure.VertexArray);
        var cellBsp = DatGeometry.ToCellBsp(id, $"cells[{index}].cellBSP", structure.CellBSP);
        return new DatCellStructure(id, index, physics, cellBsp, structure);
    }

    /// <summary>
    /// Converts an env cell on its structure: the full cell id, its landblock-local <c>Position</c>, the
    /// structure's trees, and its portals in order. A portal's polygon is the structure's <b>drawing</b> polygon
    /// <c>PolygonId</c> (as retail and ACE); its other cell is <see cref="CellPortal.Outside"/> for 0xFFFF, else
    /// that cell of the same landblock; its side is <c>(Flags &amp; PortalSide) == 0</c>, inverted as retail
    /// decodes it (<c>CCellPortal::UnPack</c>: <c>portal_side = !(flags &amp; 2)</c>). Surfaces, visible cells,
    /// the restriction object and <c>SeenOutside</c> are not read by the collision (see <see cref="SeenOutside"/>).
    /// Whether a portal's other cell exists is checked when the cells are added to a world.
    /// </summary>
    /// <param name="cell">The EnvCell as read.</param>
    /// <param name="structure">Its structure: <see cref="ToCellStructure"/> of Environment 0x0D000000 | <c>EnvironmentId</c>, key <c>CellStructure</c>.</param>
    /// <exception cref="DatObjectException">The structure is not the one the cell names, a portal's polygon is missing or refused, a count is beyond the limits, or the runtime refuses the cell (id, frame); the message names the cell id.</exception>
    public static EnvCell ToEnvCell(DatEnvCell cell, DatCellStructure structure)
    {
        ArgumentNullException.ThrowIfNull(cell);
        ArgumentNullException.ThrowIfNull(structure);
        uint id = cell.Id;
        if (structure.EnvironmentId != EnvironmentIdOf(cell) || structure.Index != cell.CellStructure)
            throw new DatObjectException(id, $"cellStructure: the cell is built on environment 0x{EnvironmentIdOf(cell):X8} structure {cell.CellStructure}, given 0x{structure.EnvironmentId:X8} structure {structure.Index}.");
        int count = cell.CellPortals?.Count ?? 0;
        if (count > MaxPortals)
            throw new DatObjectException(id, $"cellPortals: an env cell has at most {MaxPortals} portals, got {count}.");
        var source = structure.Source;
        var portals = new CellPortal[count];
        uint landblock = id >> 16;
        for (int i = 0; i < count; i++)
        {
            var portal = cell.CellPortals![i] ?? throw new DatObjectException(id, $"cellPortals[{i}]: is null.");
            if (source.Polygons is null || !source.Polygons.TryGetValue(portal.PolygonId, out var datPolygon))
                throw new DatObjectException(id, $"cellPortals[{i}].polygonId: polygon {portal.PolygonId} is not in environment 0x{structure.EnvironmentId:X8} structure {structure.Index}.");
            Polygon polygon;
            try
            {
                polygon = DatGeometry.ToPolygon(structure.EnvironmentId, $"cells[{structure.Index}].polygons[{portal.PolygonId}]", datPolygon, source.VertexArray);
            }
            catch (DatObjectException ex)
            {
                throw new DatObjectException(id, $"cellPortals[{i}]: {ex.Message}", ex);
            }
            uint other = portal.OtherCellId == CellPortal.Outside ? CellPortal.Outside : (landblock << 16) | portal.OtherCellId;
            bool portalSide = (portal.Flags & PortalFlags.PortalSide) == 0;
            portals[i] = new CellPortal(polygon, other, portalSide);
        }
        try
        {
            return new EnvCell(id, DatSetups.ToFrame(cell.Position, id, "position"), structure.PhysicsBsp, structure.CellBsp, portals);
        }
        catch (ArgumentException ex)
        {
            throw new DatObjectException(id, ex.Message, ex);
        }
    }

    /// <summary>The Environment an env cell is built on: 0x0D000000 | <c>EnvironmentId</c>.</summary>
    public static uint EnvironmentIdOf(DatEnvCell cell)
    {
        ArgumentNullException.ThrowIfNull(cell);
        return 0x0D00_0000u | cell.EnvironmentId;
    }

    /// <summary>
    /// Whether the cell is seen from outside (<c>Flags</c> has <c>SeenOutside</c>, retail <c>seen_outside</c>):
    /// read for a client's drawing; the runtime's cell search does not use it.
    /// </summary>
    public static bool SeenOutside(DatEnvCell cell)
    {
        ArgumentNullException.ThrowIfNull(cell);
        return cell.Flags.HasFlag(EnvCellFlags.SeenOutside);
    }

    /// <summary>
    /// The cell's static objects in stored order (<c>StaticObjects</c>, present when <c>Flags</c> has
    /// <c>HasStaticObjs</c>): each model id at its landblock-local frame, labelled with this cell.
    /// </summary>
    /// <exception cref="DatObjectException">More than <see cref="MaxStaticObjects"/>, an entry without its frame, or a frame the world would refuse (an origin beyond the coordinate limit, a rotation it cannot normalize); the message names the cell id.</exception>
    public static IReadOnlyList<DatPlacement> StaticObjects(DatEnvCell cell)
    {
        ArgumentNullException.ThrowIfNull(cell);
        var stabs = cell.StaticObjects;
        if (stabs is null || !cell.Flags.HasFlag(EnvCellFlags.HasStaticObjs))
            return Array.Empty<DatPlacement>();
        if (stabs.Count > MaxStaticObjects)
            throw new DatObjectException(cell.Id, $"staticObjects: an env cell places at most {MaxStaticObjects} objects, got {stabs.Count}.");
        var result = new DatPlacement[stabs.Count];
        for (int i = 0; i < stabs.Count; i++)
        {
            var stab = stabs[i] ?? throw new DatObjectException(cell.Id, $"staticObjects[{i}]: is null.");
            result[i] = new DatPlacement(stab.Id, new Position(cell.Id, DatSetups.ToPlacementFrame(stab.Frame, cell.Id, $"staticObjects[{i}].frame")));
        }
        return result;
    }
}
