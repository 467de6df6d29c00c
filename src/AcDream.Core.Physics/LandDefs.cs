using System;
using System.Numerics;
using System.Runtime.CompilerServices;

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
    public static bool IsValidLandblock(uint landblock) => landblock <= 0xFFFF && (landblock >> 8) < BlocksPerSide && (landblock & 0xFF) < BlocksPerSide;

    /// <summary>
    /// Retail LandDefs::inbound_valid_cellid (acclient.c:209467, 0x004979A0): a valid landblock
    /// (<see cref="IsValidLandblock"/>) and a cell part 1..0x40 (outdoor), 0x100..0xFFFD (indoor) or 0xFFFF (the
    /// landblock's own id, which names no cell; retail accepts it). For a cell a position may stand in, see
    /// <see cref="IsValidCellOfWorld"/>.
    /// </summary>
    public static bool IsValidCellId(uint cellId) => IsValidCellOfWorld(cellId) || (IsValidLandblock(cellId >> 16) && (cellId & 0xFFFF) == 0xFFFF);

    /// <summary>
    /// The stricter check this library applies to the cells positions name: as <see cref="IsValidCellId"/> without the
    /// landblock's own id 0x….FFFF (no cell has it): a valid landblock and a cell part 1..0x40 or 0x100..0xFFFD.
    /// </summary>
    public static bool IsValidCellOfWorld(uint cellId)
    {
        uint index = cellId & 0xFFFF;
        return IsValidLandblock(cellId >> 16) && ((index >= 1 && index <= 0x40) || (index >= FirstEnvCell && index <= 0xFFFD));
    }

    /// <summary>Landblocks along each axis of the world, 0x00..0xFE (retail LandDefs::get_vars: 255).</summary>
    public const int BlocksPerSide = 255;

    /// <summary>Land cells along each axis of the world: 8 per landblock, 2040 in all (global land-cell coordinates 0..2039).</summary>
    public const int CellsPerSide = BlocksPerSide * 8;

    /// <summary>True for an outdoor land cell id (cell part below 0x100).</summary>
    public static bool IsLandCell(uint cellId) => (cellId & 0xFFFF) < FirstEnvCell;

    /// <summary>The landblock part (high 16 bits) of a cell id.</summary>
    public static uint Landblock(uint cellId) => cellId >> 16;

    /// <summary>
    /// The vector from the south-west corner of <paramref name="fromCell"/>'s landblock to that of
    /// <paramref name="toCell"/>'s landblock (retail get_block_offset): zero within one landblock.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
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

    /// <summary>
    /// The global position of the south-west corner of <paramref name="cellId"/>'s landblock. Global
    /// coordinates start at the south-west corner of landblock 0x0000 and grow east (X) and north (Y) by
    /// <see cref="PhysicsConstants.LandblockLength"/> per landblock.
    /// </summary>
    public static Vector3 BlockCorner(uint cellId) =>
        new((cellId >> 24) * PhysicsConstants.LandblockLength, ((cellId >> 16) & 0xFF) * PhysicsConstants.LandblockLength, 0f);

    /// <summary>
    /// Retail LandDefs::adjust_to_outside (acclient.c:467433, 005A9BC0): re-expresses a point given in the space of
    /// <paramref name="cellId"/>'s landblock in the landblock that holds it, and labels it with the outdoor land
    /// cell below it. The point may lie beyond the block's edges (it is moved by whole landblocks); coordinates
    /// within <see cref="PhysicsConstants.Epsilon"/> of zero are first snapped to zero, as retail does, so a point
    /// a hair west of or south of a block's corner stays in that block. Returns false when the cell id is not an
    /// outdoor (1..0x40) or indoor (0x100..0xFFFD, 0xFFFF) id, a coordinate is not finite, or the point is outside
    /// the world; then, as retail, the cell id is set to 0 (and the snap to zero has been applied to the point when the
    /// cell id was one of those).
    /// </summary>
    /// <param name="cellId">In: any cell of the landblock the point is relative to. Out: the outdoor land cell holding it, or 0 on failure.</param>
    /// <param name="local">In: the point, relative to that landblock's south-west corner. Out: relative to the new landblock's (Z unchanged).</param>
    public static bool TryAdjustToOutside(ref uint cellId, ref Vector3 local)
    {
        uint index = cellId & 0xFFFF;
        if (!((index >= 1 && index <= 0x40) || (index >= FirstEnvCell && index <= 0xFFFD) || index == 0xFFFF))
        {
            cellId = 0;
            return false;
        }
        // Retail writes the snapped coordinates back before it looks the cell up (so also when that fails).
        if (MathF.Abs(local.X) < PhysicsConstants.Epsilon)
            local.X = 0f;
        if (MathF.Abs(local.Y) < PhysicsConstants.Epsilon)
            local.Y = 0f;
        // Retail computes in double (x87); so do we, so that the cell and the wrapped coordinate agree.
        double x = local.X, y = local.Y;
        double gx = (cellId >> 24) * 8.0 + Math.Floor(x / PhysicsConstants.LandCellLength);
        double gy = ((cellId >> 16) & 0xFF) * 8.0 + Math.Floor(y / PhysicsConstants.LandCellLength);
        if (!(gx >= 0 && gy >= 0 && gx < CellsPerSide && gy < CellsPerSide))
        {
            cellId = 0;
            return false;
        }
        cellId = LandCellAtGlobal((int)gx, (int)gy);
        local = new Vector3(Wrap(x), Wrap(y), local.Z);
        return true;
    }

    /// <summary>A coordinate relative to the landblock that holds it: [0, 192).</summary>
    /// <remarks>
    /// Exact for a float input: the result lies on the input's float grid, except for inputs in (-192, 0), whose
    /// result rounds, but stays below 192 because |v| ≥ <see cref="PhysicsConstants.Epsilon"/> there (smaller ones were snapped).
    /// </remarks>
    private static float Wrap(double v)
    {
        const double block = PhysicsConstants.LandblockLength;
        return (float)(v - Math.Floor(v / block) * block);
    }
}
