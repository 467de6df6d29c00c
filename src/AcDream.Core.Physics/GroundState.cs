namespace AcDream.Core.Physics;

/// <summary>
/// What set a mover's contact plane (<see cref="MoverState.Ground"/>): the surface it stands on or leans
/// against. Retail records only the plane and the cell it was found in (COLLISIONINFO::contact_plane and
/// contact_plane_cell_id); this says which geometry of that cell the plane came from, at the places retail
/// sets the plane: the terrain test (OBJECTINFO::validate_walkable from CLandCell::find_env_collisions), a
/// physics BSP polygon (BSPTREE::find_walkable / step_sphere_down / check_walkable via CPolygon, for an env
/// cell, a building shell or an object part), or an object's sphere or cylsphere (CSphere / CCylSphere
/// set_contact_plane).
/// </summary>
public enum GroundKind : byte
{
    /// <summary>No contact plane is known, or the state was written by hand (<see cref="MoverState.OnFloor"/>) and no transition has found one since.</summary>
    None = 0,
    /// <summary>The terrain of an outdoor land cell (<see cref="MoverState.ContactPlaneCellId"/>).</summary>
    Terrain = 1,
    /// <summary>A polygon of an indoor cell's physics BSP: a floor, a stair or a ramp.</summary>
    EnvCell = 2,
    /// <summary>A polygon of a building's shell (standing in the outdoor cell <see cref="MoverState.ContactPlaneCellId"/>).</summary>
    Building = 3,
    /// <summary>A shape of a registered object: its id is <see cref="MoverState.GroundObjectId"/>.</summary>
    Object = 4,
    /// <summary>
    /// No surface: a mover that fell in place for three transitions (retail's stationary-fall rule,
    /// CTransition::validate_transition) is given a level plane under its sphere in its cell.
    /// </summary>
    StationaryFall = 5,
}

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
