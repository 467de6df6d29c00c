using System.Numerics;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// What a mover carries from one frame to the next: where it is, and its contact with the ground
/// (retail keeps these on the physics object between transitions).
/// </summary>
public struct MoverState
{
    /// <summary>The position (cell and landblock-local frame).</summary>
    public Position Position;
    /// <summary>The mover touched a contact plane at the end of the last frame.</summary>
    public bool Contact;
    /// <summary>That plane was walkable.</summary>
    public bool OnWalkable;
    /// <summary>
    /// What set the contact plane (<see cref="GroundKind"/>): terrain, an indoor cell's floor, a building, an
    /// object (<see cref="GroundObjectId"/>), or None when no plane is known. Kept with the plane from frame
    /// to frame, as the plane is; it changes no result.
    /// </summary>
    public GroundKind Ground;
    /// <summary>The last contact plane (valid when it was ever set).</summary>
    public Plane ContactPlane;
    /// <summary>The cell whose landblock space <see cref="ContactPlane"/> is in; 0 when no plane is known.</summary>
    public uint ContactPlaneCellId;
    /// <summary>The contact plane is water.</summary>
    public bool ContactPlaneIsWater;
    /// <summary>The mover was sliding along <see cref="SlidingNormal"/>.</summary>
    public bool SlidingNormalValid;
    /// <summary>The sliding normal.</summary>
    public Vector3 SlidingNormal;
    /// <summary>The object whose shape set the contact plane when <see cref="Ground"/> is <see cref="GroundKind.Object"/>, else 0.</summary>
    public uint GroundObjectId;

    /// <summary>
    /// The contact in retail's terms (<see cref="Physics.GroundState"/>): <see cref="Contact"/> and
    /// <see cref="OnWalkable"/> summed up as walkable ground, a steep surface, or airborne.
    /// </summary>
    public readonly GroundState GroundState =>
        !Contact ? GroundState.Airborne : OnWalkable ? GroundState.WalkableGround : GroundState.SteepSurface;

    /// <summary>A mover in the air (no known ground) at a position.</summary>
    public static MoverState Airborne(Position position) => new() { Position = position };

    /// <summary>A mover standing on a horizontal floor at height <paramref name="floorZ"/> (landblock space).</summary>
    public static MoverState OnFloor(Position position, float floorZ) => new()
    {
        Position = position,
        // Checked here too, so the mistake is reported where it was made.
        Contact = Guard.CoordinateOk(floorZ, "floorZ"),
        OnWalkable = true,
        ContactPlane = new Plane(Vector3.UnitZ, -floorZ),
        ContactPlaneCellId = position.CellId,
    };
}
