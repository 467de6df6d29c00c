using System.Numerics;

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

    /// <summary>Creates a position.</summary>
    public Position(uint cellId, Frame frame)
    {
        CellId = cellId;
        Frame = frame;
    }

    /// <summary>Creates a position with no rotation.</summary>
    public Position(uint cellId, Vector3 origin) : this(cellId, new Frame(origin)) { }

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
