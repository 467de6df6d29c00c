using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Queries;

/// <summary>One object found by an overlap query, with the first of its collision shapes that overlapped.</summary>
public readonly struct ObjectOverlap
{
    internal ObjectOverlap(uint objectId, ShadowShapeKind kind, int shapeIndex, uint cellId, PhysicsState state)
    {
        ObjectId = objectId;
        Kind = kind;
        ShapeIndex = shapeIndex;
        CellId = cellId;
        State = state;
    }

    /// <summary>The object's id.</summary>
    public uint ObjectId { get; }
    /// <summary>The kind of shape that overlapped (the rung the object collides by: its BSP parts when it has <see cref="PhysicsState.HasPhysicsBsp"/>, else its cylspheres, else its spheres).</summary>
    public ShadowShapeKind Kind { get; }
    /// <summary>The index of that part, cylsphere or sphere in the object's setup.</summary>
    public int ShapeIndex { get; }
    /// <summary>The cell of the object's position.</summary>
    public uint CellId { get; }
    /// <summary>The object's physics state (ethereal, static…).</summary>
    public PhysicsState State { get; }

    /// <inheritdoc />
    public override string ToString() => $"0x{ObjectId:X8} {Kind}[{ShapeIndex}] in 0x{CellId:X8}";
}
