using System;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>
/// An opening of an indoor cell (retail CCellPortal): a polygon in the cell's space and the cell on the
/// other side. <see cref="OtherCellId"/> 0xFFFF (or the full id with cell part 0xFFFF) leads outside.
/// </summary>
public sealed class CellPortal
{
    /// <summary>The cell-part value that means "outside" (retail uses 0xFFFF).</summary>
    public const uint Outside = 0xFFFF;

    /// <summary>Creates a portal.</summary>
    /// <param name="polygon">The opening, in the owning cell's space.</param>
    /// <param name="otherCellId">The full id of the cell behind it, or <see cref="Outside"/>.</param>
    /// <param name="portalSide">
    /// Retail portal_side (<c>CCellPortal::UnPack</c>: <c>!(flags &amp; 2)</c>): true when the owning cell lies behind
    /// the polygon (on its back side; the other cell in front), false when it lies in front. Retail reads it only where
    /// the other cell is not loaded and where an object's parts cross a portal (<c>CEnvCell::find_transit_cells</c>,
    /// <c>check_building_transit</c>); this library's cell search does not read it.
    /// </param>
    public CellPortal(Polygon polygon, uint otherCellId, bool portalSide)
    {
        Polygon = polygon ?? throw new ArgumentNullException(nameof(polygon));
        OtherCellId = otherCellId;
        PortalSide = portalSide;
    }

    /// <summary>The opening, in the owning cell's space.</summary>
    public Polygon Polygon { get; }
    /// <summary>The cell behind the opening (full id), or <see cref="Outside"/>.</summary>
    public uint OtherCellId { get; }
    /// <summary>Retail portal_side: true when the owning cell lies behind the polygon, false when in front.</summary>
    public bool PortalSide { get; }
    /// <summary>True when the portal leads outdoors.</summary>
    public bool LeadsOutside => (OtherCellId & 0xFFFF) == Outside;
}
