using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// A position as retail keeps it: a cell id and a frame whose origin is relative to the south-west
/// corner of that cell's landblock. Landblock-local coordinates keep float precision at 1e-4 m
/// anywhere in the world; crossing a landblock adds a block offset (see <see cref="LandDefs.BlockOffset"/>).
/// </summary>
public struct Position
{
    /// <summary>The retail cell id (landblock &lt;&lt; 16 | cell).</summary>
    public uint CellId;

    /// <summary>The placement, landblock-local.</summary>
    public Frame Frame;

    /// <summary>
    /// True when two positions are the same bits: cell id, origin and the orientation as stored (so any
    /// function of them gives identical results). A position is 32 bytes with no padding (the cell id and
    /// seven floats; a test pins the size).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool SameBits(in Position a, in Position b)
    {
        // One or two vector loads per side.
        ref byte x = ref Unsafe.As<Position, byte>(ref Unsafe.AsRef(in a));
        ref byte y = ref Unsafe.As<Position, byte>(ref Unsafe.AsRef(in b));
        if (Vector256.IsHardwareAccelerated)
            return Unsafe.ReadUnaligned<Vector256<byte>>(ref x) == Unsafe.ReadUnaligned<Vector256<byte>>(ref y);
        return Unsafe.ReadUnaligned<Vector128<byte>>(ref x) == Unsafe.ReadUnaligned<Vector128<byte>>(ref y)
            && Unsafe.ReadUnaligned<Vector128<byte>>(ref Unsafe.Add(ref x, 16)) == Unsafe.ReadUnaligned<Vector128<byte>>(ref Unsafe.Add(ref y, 16));
    }

    /// <summary>Creates a position.</summary>
    public Position(uint cellId, Frame frame)
    {
        CellId = cellId;
        Frame = frame;
    }

    /// <summary>Creates a position with no rotation.</summary>
    public Position(uint cellId, Vector3 origin) : this(cellId, new Frame(origin)) { }

    /// <summary>
    /// The outdoor position of a point given relative to landblock <paramref name="landblock"/>'s south-west
    /// corner: the point may lie beyond that block's edges, and the result is in the landblock that holds
    /// it, labelled with the outdoor land cell below it (<see cref="LandDefs.TryAdjustToOutside"/>; retail
    /// adjust_to_outside). No rotation. For a point inside a building, use the indoor cell's id instead.
    /// </summary>
    /// <param name="landblock">The landblock, 0xXXYY (X east, Y north; each 0x00..0xFE).</param>
    /// <param name="local">The point relative to the landblock's south-west corner, metres.</param>
    /// <exception cref="ArgumentException">The landblock is not in the world, the point is not finite, or it falls outside the world.</exception>
    public static Position Outdoor(uint landblock, Vector3 local)
    {
        if (!LandDefs.IsValidLandblock(landblock))
            throw new ArgumentException($"landblock: must be 0xXXYY with X and Y in 0x00..0xFE, got 0x{landblock:X}.", nameof(landblock));
        Guard.Finite(local, "local");
        uint cell = (landblock << 16) | 1;
        if (!LandDefs.TryAdjustToOutside(ref cell, ref local))
            throw new ArgumentException($"local: {local} relative to landblock 0x{landblock:X4} is outside the world.", nameof(local));
        return new Position(cell, local);
    }

    /// <summary>
    /// The outdoor position of a global point (<see cref="LandDefs.BlockCorner"/>: metres from the south-west
    /// corner of landblock 0x0000): its landblock, landblock-local origin and outdoor land cell. No rotation.
    /// A float global coordinate resolves about 4 mm at the far edge of the world (49 km); keep positions
    /// landblock-local (<see cref="Outdoor"/>) where precision matters.
    /// </summary>
    /// <param name="global">The global point, metres.</param>
    /// <exception cref="ArgumentException">The point is not finite or falls outside the world.</exception>
    public static Position FromGlobal(Vector3 global)
    {
        Guard.Finite(global, "global");
        uint cell = 1;
        var local = global;
        if (!LandDefs.TryAdjustToOutside(ref cell, ref local))
            throw new ArgumentException($"global: {global} is outside the world (0 to {LandDefs.BlocksPerSide * PhysicsConstants.LandblockLength} m on X and Y).", nameof(global));
        return new Position(cell, local);
    }

    /// <summary>The origin as a global point (<see cref="LandDefs.BlockCorner"/> plus the landblock-local origin); for any cell, indoor or outdoor.</summary>
    public readonly Vector3 ToGlobal() => LandDefs.BlockCorner(CellId) + Frame.Origin;

    /// <summary>The origin, landblock-local.</summary>
    public readonly Vector3 Origin => Frame.Origin;

    /// <summary>The vector from this position to <paramref name="other"/>, across landblocks.</summary>
    public readonly Vector3 GetOffset(in Position other) =>
        other.Frame.Origin - Frame.Origin + LandDefs.BlockOffset(CellId, other.CellId);

    /// <summary>
    /// Maps a point local to <paramref name="other"/> into this position's local space (retail
    /// Position::localtolocal, acclient.c:143794: through <paramref name="other"/>'s matrix, across
    /// landblocks, then through the transpose of this position's).
    /// </summary>
    public readonly Vector3 LocalToLocal(in Position other, Vector3 point) =>
        LocalToLocal(Frame.Matrix, other, other.Frame.Matrix, point);

    /// <summary><see cref="LocalToLocal(in Position, Vector3)"/> with both frames' matrices already computed.</summary>
    internal readonly Vector3 LocalToLocal(in RotationMatrix mine, in Position other, in RotationMatrix others, Vector3 point)
    {
        var inOtherBlock = others.PositionToGlobal(point, other.Frame.Origin);
        return mine.FrameToLocal(LandDefs.BlockOffset(CellId, other.CellId) + inOtherBlock, Frame.Origin);
    }

    /// <summary>Maps a local point into this position's landblock space (retail Position::localtoglobal).</summary>
    public readonly Vector3 LocalToGlobal(Vector3 point) => Frame.Matrix.PositionToGlobal(point, Frame.Origin);

    /// <summary>Rotates a local direction into this position's landblock space (retail Position::localtoglobalvec).</summary>
    public readonly Vector3 LocalToGlobalVec(Vector3 vector) => Frame.Matrix.PositionToGlobal(vector);

    /// <summary>Rotates a landblock-space direction into this position's local space (retail Position::globaltolocalvec: the transpose).</summary>
    public readonly Vector3 GlobalToLocalVec(Vector3 vector) => Frame.Matrix.PositionToLocal(vector);

    /// <inheritdoc />
    public override readonly string ToString() => $"0x{CellId:X8} {Frame.Origin}";
}
