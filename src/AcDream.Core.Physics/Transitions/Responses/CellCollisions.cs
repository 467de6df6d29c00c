using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions.Responses;

/// <summary>
/// Collides a transition with a cell's own geometry (retail CObjCell::find_env_collisions and its
/// overrides) and with the building standing in an outdoor cell (find_building_collisions). The cells
/// expose their geometry (terrain triangles, water depth, BSP trees, the building's shell); what the
/// transition does with it is decided here.
/// </summary>
internal static class CellCollisions
{
    /// <summary>
    /// Collides the transition's check spheres with the cell's geometry (retail find_env_collisions, virtual
    /// there): the land or env cell routine below.
    /// </summary>
    public static TransitionState FindEnvCollisions(Cell cell, Transition transition) => cell switch
    {
        LandCell land => FindEnvCollisions(land, transition),
        EnvCell env => FindEnvCollisions(env, transition),
        _ => TransitionState.OK,
    };

    /// <summary>Retail CEnvCell::find_env_collisions: the cell's physics BSP, as an object part at scale 1.</summary>
    public static TransitionState FindEnvCollisions(EnvCell cell, Transition transition)
    {
        var path = transition.SpherePath;
        path.ObstructionEthereal = false;
        if (cell.PhysicsBsp is null)
            return TransitionState.OK;
        TransitionState state;
        // A placement test known to be Collided (SpherePath.KnownSolidHit: the wall a step-up just failed
        // against) is not run again.
        if (path.KnownSolidHit(cell, cell.Position, 1.0f))
            state = TransitionState.Collided;
        else
        {
            path.CacheLocalSpaceSphere(cell.Position, 1.0f);
            state = path.InsertType == InsertType.InitialPlacement
                ? BspResponses.PlacementInsert(cell.PhysicsBsp, transition)
                : BspResponses.FindCollisions(cell.PhysicsBsp, transition, 1.0f, cell);
        }
        if (state != TransitionState.OK && (transition.ObjectInfo.State & ObjectInfoState.Contact) == 0)
            transition.CollisionInfo.CollidedWithEnvironment = true;
        return state;
    }

    /// <summary>
    /// Retail CLandCell::find_env_collisions (acclient.c:354991): the terrain triangle under the mover's low
    /// point; over it, a landblock that is entirely water stops every mover but the camera and a missile
    /// (acclient.c:355030), and otherwise the sphere is validated against the triangle's plane sunk by the
    /// water depth, the plane counting as water when the cell has any (acclient.c:355034, :355043).
    /// </summary>
    public static TransitionState FindEnvCollisions(LandCell cell, Transition transition)
    {
        var path = transition.SpherePath;
        if ((path.CheckPos.CellId >> 16) == (cell.Id >> 16))
        {
            // The usual case, the check position in this cell's landblock: no offset, so sphere 0 is passed as
            // it is (subtracting a zero offset would change no bit) and not copied.
            var low = path.GlobalLowPoint;
            var triangle = cell.FindTerrainPolygon(low);
            if (triangle is null)
                return TransitionState.OK;
            if (StopsInWater(cell, transition))
                return TransitionState.Collided;
            return transition.ValidateWalkable(path.GlobalSphere[0], triangle.Plane, cell.WaterType != WaterType.NotWater, cell.WaterDepth(low), cell.Id);
        }
        var blockOffset = LandDefs.BlockOffset(path.CheckPos.CellId, cell.Id);
        var local = path.GlobalLowPoint - blockOffset;
        var walkable = cell.FindTerrainPolygon(local);
        if (walkable is null)
            return TransitionState.OK;
        if (StopsInWater(cell, transition))
            return TransitionState.Collided;
        var check = path.GlobalSphere[0];
        check.Center -= blockOffset;
        return transition.ValidateWalkable(check, walkable.Plane, cell.WaterType != WaterType.NotWater, cell.WaterDepth(local), cell.Id);
    }

    /// <summary>Retail find_building_collisions: the shell, tested as an object part, with the building flag set.</summary>
    public static TransitionState FindBuildingCollisions(Building building, Transition transition)
    {
        var path = transition.SpherePath;
        path.BuildingCheck = true;
        var state = PartCollision.Collide(transition, building.Shell, building.Position, 1.0f);
        path.BuildingCheck = false;
        if (state != TransitionState.OK && (transition.ObjectInfo.State & ObjectInfoState.Contact) == 0)
            transition.CollisionInfo.CollidedWithEnvironment = true;
        return state;
    }

    // find_env_collisions' all-water stop (acclient.c:355030): the landblock (not the cell) is entirely water
    // and the mover is neither the camera (OBJECTINFO IS_VIEWER) nor a missile (PhysicsState MISSILE).
    private static bool StopsInWater(LandCell cell, Transition transition) =>
        cell.BlockEntirelyWater
        && (transition.ObjectInfo.State & ObjectInfoState.IsViewer) == 0
        && (transition.ObjectInfo.PhysicsState & PhysicsState.Missile) == 0;
}
