using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>
/// An indoor cell (retail CEnvCell): placed by a frame in its landblock, with a physics BSP for collisions
/// (walls, floor, stairs), a cell BSP for containment, and portals to its neighbours.
/// </summary>
public sealed class EnvCell : Cell
{
    private readonly CellPortal[] _portals;

    /// <summary>Creates an env cell.</summary>
    /// <param name="id">Full cell id in the retail world (<see cref="LandDefs.IsValidCellId"/>); the cell part must be 0x100..0xFFFD.</param>
    /// <param name="frame">The cell's placement, landblock-local.</param>
    /// <param name="physicsBsp">The collision BSP (cell space), or null for none.</param>
    /// <param name="cellBsp">The containment BSP (cell space): its split planes bound the cell's interior.</param>
    /// <param name="portals">The openings.</param>
    public EnvCell(uint id, Frame frame, BspTree? physicsBsp, BspTree cellBsp, IReadOnlyList<CellPortal>? portals = null) : base(id)
    {
        if (LandDefs.IsLandCell(id) || (id & 0xFFFF) == CellPortal.Outside)
            throw new ArgumentException($"cell 0x{id:X8}: an env cell's index must be 0x100..0xFFFD.", nameof(id));
        // The names are built only when a check will use them (a DAT landblock load makes every cell here).
        if (!LandDefs.IsValidCellOfWorld(id))
            Guard.CellInWorld(id, $"cell 0x{id:X8}");
        if (!Guard.IsPoseAsGiven(frame))
            Guard.Pose(ref frame, $"cell 0x{id:X8}.frame");
        Position = new Position(id, frame);
        PhysicsBsp = physicsBsp;
        CellBsp = cellBsp ?? throw new ArgumentNullException(nameof(cellBsp), $"cell 0x{id:X8}.cellBsp: is required.");
        Matrix = frame.Matrix;
        var bounds = PhysicsBsp is { } physics && physics.Bounds.Radius > 0f ? physics.Bounds : CellBsp.Bounds;
        Bounds = new Sphere(Matrix.FrameToGlobal(bounds.Center, frame.Origin), bounds.Radius);
        _portals = portals is null ? Array.Empty<CellPortal>() : [.. portals];
        for (int i = 0; i < _portals.Length; i++)
            if (_portals[i] is null)
                throw new ArgumentException($"cell 0x{id:X8}.portals[{i}]: is null.", nameof(portals));
    }

    /// <summary>The cell's placement (cell id and landblock-local frame).</summary>
    public Position Position { get; }
    /// <summary>The collision BSP, or null.</summary>
    public BspTree? PhysicsBsp { get; }
    /// <summary>The containment BSP.</summary>
    public BspTree CellBsp { get; }
    /// <summary>The openings.</summary>
    public ReadOnlySpan<CellPortal> Portals => _portals;

    /// <summary>
    /// The cell frame's rotation matrix (retail Frame::cache), computed once: the frame never changes, and the
    /// cell searches of every sub-step transform through it several times (the same arithmetic as
    /// <see cref="Frame.GlobalToLocal"/>, the same bits).
    /// </summary>
    internal readonly RotationMatrix Matrix;

    /// <summary>
    /// The bounding sphere of the cell's physics BSP (or, without one or when it is empty, of its containment
    /// BSP) in landblock space, placed once (<see cref="Frame.LocalToGlobal"/>'s arithmetic).
    /// </summary>
    internal readonly Sphere Bounds;

    /// <summary>Maps a landblock-local point into the cell's space (<see cref="Frame.GlobalToLocal"/> through the kept matrix).</summary>
    internal Vector3 ToLocal(Vector3 point) => Matrix.FrameToLocal(point, Position.Frame.Origin);

    /// <summary>Retail point_in_cell: a landblock-local point lies inside the cell BSP.</summary>
    public bool ContainsPoint(Vector3 point) => BspQuery.PointInsideCellBsp(CellBsp, ToLocal(point));

    /// <summary>Retail sphere_intersects_cell for a landblock-local sphere.</summary>
    internal BoundingType IntersectsSphere(in Sphere sphere) =>
        BspQuery.SphereIntersectsCellBsp(CellBsp, new Sphere(ToLocal(sphere.Center), sphere.Radius));

    /// <summary>
    /// The distance from the bounding sphere of the cell's physics BSP (or, without one or when it is
    /// empty, of its containment BSP; when both are empty, from the cell's origin).
    /// </summary>
    internal override float DistanceOutside(Vector3 point) => MathF.Max(Vector3.Distance(point, Bounds.Center) - Bounds.Radius, 0f);
}
