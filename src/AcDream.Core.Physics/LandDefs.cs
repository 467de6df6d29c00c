using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>Retail cell-id arithmetic: landblocks, outdoor land cells and indoor env cells.</summary>
public static class LandDefs
{
    /// <summary>The lowest cell index of an indoor env cell; 1..64 are the 8×8 outdoor land cells.</summary>
    public const uint FirstEnvCell = 0x100;

    /// <summary>
    /// True for a landblock id (the high 16 bits of a cell id) inside retail's world: its x (high byte) and
    /// y (low byte) are both at most 0xFE, the world being 255 × 255 landblocks of 8 × 8 cells, global
    /// land-cell coordinates 0..2039 (retail LandDefs::inbound_valid_cellid, blockid_to_lcoord).
    /// </summary>
    public static bool IsValidLandblock(uint landblock) => landblock <= 0xFFFF && (landblock >> 8) <= 0xFE && (landblock & 0xFF) <= 0xFE;

    /// <summary>
    /// True for a cell id retail accepts as a cell of its world (LandDefs::inbound_valid_cellid, acclient
    /// 0x004979A0): a valid landblock (<see cref="IsValidLandblock"/>) and a cell part 1..0x40 (outdoor) or
    /// 0x100..0xFFFD (indoor). Retail also accepts 0xFFFF, the landblock's own id, which is no cell.
    /// </summary>
    public static bool IsValidCellId(uint cellId)
    {
        uint index = cellId & 0xFFFF;
        return IsValidLandblock(cellId >> 16) && ((index >= 1 && index <= 0x40) || (index >= FirstEnvCell && index <= 0xFFFD));
    }

    /// <summary>True for an outdoor land cell id (cell part below 0x100).</summary>
    public static bool IsLandCell(uint cellId) => (cellId & 0xFFFF) < FirstEnvCell;

    /// <summary>The landblock part (high 16 bits) of a cell id.</summary>
    public static uint Landblock(uint cellId) => cellId >> 16;

    /// <summary>
    /// The vector from the south-west corner of <paramref name="fromCell"/>'s landblock to that of
    /// <paramref name="toCell"/>'s landblock (retail get_block_offset): zero within one landblock.
    /// </summary>
    public static Vector3 BlockOffset(uint fromCell, uint toCell)
    {
        uint a = fromCell >> 16, b = toCell >> 16;
        if (a == b)
            return Vector3.Zero;
        int dx = (int)(b >> 8) - (int)(a >> 8);
        int dy = (int)(b & 0xFF) - (int)(a & 0xFF);
        return new Vector3(dx * PhysicsConstants.LandblockLength, dy * PhysicsConstants.LandblockLength, 0f);
    }

    /// <summary>
    /// The outdoor land cell id that holds a landblock-local point of landblock <paramref name="landblock"/>
    /// (cells are numbered 1..64 column-major: index = x * 8 + y + 1), or 0 when the point is outside the block.
    /// </summary>
    public static uint LandCellAt(uint landblock, Vector3 point)
    {
        if (!(point.X >= 0 && point.Y >= 0 && point.X < PhysicsConstants.LandblockLength && point.Y < PhysicsConstants.LandblockLength))
            return 0;
        uint cx = (uint)(point.X / PhysicsConstants.LandCellLength);
        uint cy = (uint)(point.Y / PhysicsConstants.LandCellLength);
        return (landblock << 16) | (cx * 8 + cy + 1);
    }

    /// <summary>The landblock-local south-west corner of an outdoor land cell.</summary>
    public static Vector3 LandCellCorner(uint cellId)
    {
        uint index = (cellId & 0xFFFF) - 1;
        return new Vector3((index / 8) * PhysicsConstants.LandCellLength, (index % 8) * PhysicsConstants.LandCellLength, 0f);
    }

    /// <summary>
    /// The outdoor cell id at global land-cell coordinates (0..2039 on each axis: landblock × 8 + cell),
    /// or 0 outside the world.
    /// </summary>
    public static uint LandCellAtGlobal(int gx, int gy)
    {
        if (gx < 0 || gy < 0 || gx >= 2040 || gy >= 2040)
            return 0;
        return ((uint)(gx >> 3) << 24) | ((uint)(gy >> 3) << 16) | (uint)((gx & 7) * 8 + (gy & 7) + 1);
    }
}
