namespace AcDream.Core.Physics;

/// <summary>
/// A summary of a mover's contact, from retail's two transient-state flags CONTACT (0x1,
/// <see cref="MoverState.Contact"/>: a contact plane was found within EPSILON of the foot sphere) and
/// ON_WALKABLE (0x2, <see cref="MoverState.OnWalkable"/>: that plane's normal has Z at least
/// <see cref="PhysicsConstants.FloorZ"/>, OBJECTINFO::is_valid_walkable).
/// </summary>
public enum GroundState : byte
{
    /// <summary>Neither flag: no contact plane (falling, jumping, or standing on nothing).</summary>
    Airborne = 0,
    /// <summary>CONTACT without ON_WALKABLE: against a plane too steep to stand on (retail slides down it under gravity).</summary>
    SteepSurface = 1,
    /// <summary>CONTACT and ON_WALKABLE: standing on walkable ground (friction applies, jumps are allowed).</summary>
    WalkableGround = 2,
}
