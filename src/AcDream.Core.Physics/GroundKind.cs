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
