namespace AcDream.Core.Physics;

public sealed partial class Transition
{
    /// <summary>
    /// Retail validate_placement_transition: a placement that fits becomes the current position; one that
    /// does not clears the collision record so the next try starts clean (when sliding is allowed and the
    /// mover has no missile target).
    /// </summary>
    internal TransitionState ValidatePlacementTransition(TransitionState state)
    {
        var path = SpherePath;
        if (path.CheckCell is null)
            return TransitionState.Collided;
        if (state == TransitionState.OK)
        {
            path.CurPos = path.CheckPos;
            path.CurCell = path.CheckCell;
            path.CacheGlobalCurrCenter();
        }
        else if (path.PlacementAllowsSliding && ObjectInfo.TargetId == 0)
        {
            CollisionInfo.Reset();
        }
        return state;
    }

    /// <summary>Retail placement_insert: the check position against its cell and the cells around it.</summary>
    internal TransitionState PlacementInsert()
    {
        var path = SpherePath;
        if (path.CheckCell is null)
            return TransitionState.Collided;
        var cell = path.CheckCell;
        var state = InsertIntoCell(cell, 3);
        return state == TransitionState.OK ? CheckOtherCells(cell) : state;
    }
}
