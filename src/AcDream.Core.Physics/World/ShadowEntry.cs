using System;
using System.Numerics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.World;

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
    /// <summary>
    /// BSP rows: a box, in the object's landblock space, holding every polygon of the part as placed and
    /// scaled, widened by a margin far above float rounding (see <c>PartCollision.MayTouchPolygons</c>).
    /// </summary>
    public readonly Vector3 PolygonsMin, PolygonsMax;
    /// <summary>
    /// BSP rows: the box of the polygons a walkable search can take (see <see cref="Bsp.BspTree.UpFacingMin"/>)
    /// when the part stands upright; otherwise the box of all its polygons.
    /// </summary>
    public readonly Vector3 WalkableMin, WalkableMax;

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
        if (shape.Kind == ShadowShapeKind.Bsp)
        {
            PartPosition = new Position(position.CellId, position.Frame.Combine(shape.PartFrame));
            var tree = shape.Model!.Bsp;
            PlacedBox(tree.PolygonsMin, tree.PolygonsMax, PartPosition, shape.ModelScale, out PolygonsMin, out PolygonsMax);
            // Upright: the world's up seen from the part is the part's own up to within 1e-4 on X and Y, so
            // a polygon whose normal's Z is at most UpFacingZ faces the world's up by at most UpFacingZ
            // + 2e-4 (see PartCollision.MayTouchPolygons).
            var up = PartPosition.GlobalToLocalVec(Vector3.UnitZ);
            if (MathF.Abs(up.X) < 1e-4f && MathF.Abs(up.Y) < 1e-4f && up.Z > 0f)
                PlacedBox(tree.UpFacingMin, tree.UpFacingMax, PartPosition, shape.ModelScale, out WalkableMin, out WalkableMax);
            else
                (WalkableMin, WalkableMax) = (PolygonsMin, PolygonsMax);
        }
        PlacedPoint = shape.Kind switch
        {
            ShadowShapeKind.Cylinder => position.LocalToGlobal(shape.Cylinder.LowPoint),
            ShadowShapeKind.Sphere => position.LocalToGlobal(shape.Sphere.Center),
            _ => default,
        };
    }

    // The placed corners of a box in the tree's space, boxed again (any rotation), then widened: the tests
    // see the spheres through a rotation in double and a float rounding of each coordinate.
    private static void PlacedBox(Vector3 lo, Vector3 hi, in Position part, float scale, out Vector3 min, out Vector3 max)
    {
        min = new Vector3(float.MaxValue);
        max = new Vector3(float.MinValue);
        if (lo.X > hi.X)
            return;
        for (int corner = 0; corner < 8; corner++)
        {
            var local = new Vector3((corner & 1) == 0 ? lo.X : hi.X, (corner & 2) == 0 ? lo.Y : hi.Y, (corner & 4) == 0 ? lo.Z : hi.Z);
            var placed = part.LocalToGlobal(local * scale);
            min = Vector3.Min(min, placed);
            max = Vector3.Max(max, placed);
        }
        var margin = Margin(scale);
        min -= margin;
        max += margin;
    }

    /// <summary>
    /// How far the culling boxes (a row's polygon boxes, an object's reach box) are widened beyond what they
    /// hold: far above the float rounding with which the exact tests see the shapes and the spheres.
    /// </summary>
    internal static Vector3 Margin(float scale) => new(0.05f * MathF.Max(1f, scale) + 0.01f);

    /// <inheritdoc />
    public override string ToString() => $"0x{EntityId:X8} {Kind}[{Shape.Index}] state=0x{(uint)State:X}";
}
