using System;
using System.Numerics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.World;

/// <summary>What an object is, as far as the PvP, creature and missile rules of collision care.</summary>
[Flags]
public enum ShadowFlags : byte
{
    /// <summary>Nothing special.</summary>
    None = 0,
    /// <summary>The object is a player.</summary>
    IsPlayer = 0x1,
    /// <summary>The object is a creature (players and monsters).</summary>
    IsCreature = 0x2,
    /// <summary>The object cannot be passed by players.</summary>
    IsImpenetrable = 0x4,
    /// <summary>The object is a player killer.</summary>
    IsPK = 0x8,
    /// <summary>The object is a PK-lite player.</summary>
    IsPKLite = 0x10,
    /// <summary>
    /// The object is a game object with a weenie (anything a server spawns), as opposed to static scenery
    /// from the landblock's data. Retail's missile rules only ignore weenie objects.
    /// </summary>
    HasWeenie = 0x20,
}

/// <summary>
/// One row of a cell's shadow list: one collision shape of one object, with the object's placement and
/// state copied in so a query reads one flat row. Rows of one object are contiguous in a cell's list.
/// </summary>
internal readonly struct ShadowEntry
{
    /// <summary>The object's retail id.</summary>
    public readonly uint EntityId;
    /// <summary>The shape.</summary>
    public readonly ShadowShape Shape;
    /// <summary>The shape's kind (kept beside the row, so the dispatch reads it without visiting the shape).</summary>
    public readonly ShadowShapeKind Kind;
    /// <summary>The object's position (cell id and landblock-local frame).</summary>
    public readonly Position Position;
    /// <summary>The object's scale (already applied to <see cref="Shape"/>).</summary>
    public readonly float Scale;
    /// <summary>The object's PhysicsState, with <see cref="PhysicsState.HasPhysicsBsp"/> or-ed in from its parts.</summary>
    public readonly PhysicsState State;
    /// <summary>The object's PvP / creature flags.</summary>
    public readonly ShadowFlags Flags;
    /// <summary>How many cylspheres the object has (the dispatch ladder needs it per row).</summary>
    public readonly byte CylSphereCount;
    /// <summary>How many spheres the object has.</summary>
    public readonly byte SphereCount;
    /// <summary>
    /// BSP rows: the part's placement, the object's frame combined with the part's (Frame::combine), computed
    /// when the row is written rather than at every test (the same arithmetic, so the same bits).
    /// </summary>
    public readonly Position PartPosition;
    /// <summary>
    /// Cylinder rows: the low point, sphere rows: the centre, placed by the object's frame
    /// (Position::localtoglobal) in its own landblock's space, computed when the row is written rather than
    /// at every test (the same arithmetic, so the same bits).
    /// </summary>
    public readonly Vector3 PlacedPoint;

    internal ShadowEntry(uint entityId, ShadowShape shape, in Position position, float scale, PhysicsState state, ShadowFlags flags, int cylCount, int sphereCount)
    {
        EntityId = entityId;
        Shape = shape;
        Kind = shape.Kind;
        Position = position;
        Scale = scale;
        State = state;
        Flags = flags;
        CylSphereCount = (byte)Math.Min(cylCount, 255);
        SphereCount = (byte)Math.Min(sphereCount, 255);
        PartPosition = shape.Kind == ShadowShapeKind.Bsp ? new Position(position.CellId, position.Frame.Combine(shape.PartFrame)) : default;
        PlacedPoint = shape.Kind switch
        {
            ShadowShapeKind.Cylinder => position.LocalToGlobal(shape.Cylinder.LowPoint),
            ShadowShapeKind.Sphere => position.LocalToGlobal(shape.Sphere.Center),
            _ => default,
        };
    }

    /// <inheritdoc />
    public override string ToString() => $"0x{EntityId:X8} {Kind}[{Shape.Index}] state=0x{(uint)State:X}";
}
