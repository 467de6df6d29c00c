using System;
using System.Numerics;

namespace AcDream.Core.Physics.Transitions;

internal sealed partial class Transition
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
        else if (path.PlacementAllowsSliding)
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

    /// <summary>
    /// Retail validate_placement: accepts an OK placement as the current position; an adjusted one is
    /// re-inserted once (when <paramref name="adjust"/>) and judged again.
    /// </summary>
    internal TransitionState ValidatePlacement(TransitionState state, bool adjust)
    {
        var path = SpherePath;
        if (path.CheckCell is null)
            return TransitionState.Collided;
        switch (state)
        {
            case TransitionState.OK:
                path.CurPos = path.CheckPos;
                path.CurCell = path.CheckCell;
                path.CacheGlobalCurrCenter();
                break;
            case TransitionState.Adjusted:
            case TransitionState.Slid:
                if (adjust)
                    return ValidatePlacement(PlacementInsert(), false);
                break;
        }
        return state;
    }

    /// <summary>
    /// Retail find_placement_position: puts an object into the world where it is, pushing it out of cell
    /// geometry, then (when that spot is taken by an object) searching rings around it for a free one, and
    /// finally settling it onto the ground below. True when a place was found; the path's current position
    /// is then the placement.
    /// </summary>
    public bool FindPlacementPosition()
    {
        var path = SpherePath;
        path.SetCheckPos(path.CurPos, path.CurCell);
        path.InsertType = InsertType.InitialPlacement;
        var state = TransitionState.Collided;
        if (path.CheckCell is not null)
        {
            state = InsertIntoCell(path.CheckCell, 3);
            if (state == TransitionState.OK)
                state = CheckOtherCells(path.CheckCell);
        }
        if (ValidatePlacement(state, adjust: true) != TransitionState.OK)
            return false;
        path.InsertType = InsertType.Placement;
        if (!FindPlacementPos())
            return false;
        if (!ObjectInfo.StepDown)
            return ValidatePlacement(TransitionState.OK, adjust: true) == TransitionState.OK;

        path.WalkableAllowance = PhysicsConstants.LandingZ;
        path.SaveCheckPos();
        path.Backup = path.InsertType;
        path.InsertType = InsertType.Transition;
        float radius = path.GlobalSphere[0].Radius;
        float depth = ObjectInfo.StepDownHeight;
        if (path.NumSphere < 2 && radius * 2 < depth)
            depth = radius * 0.5f;
        bool landed;
        if (depth <= radius * 2)
        {
            landed = StepDown(depth, PhysicsConstants.LandingZ);
        }
        else
        {
            depth *= 0.5f;
            landed = StepDown(depth, PhysicsConstants.LandingZ) || StepDown(depth, PhysicsConstants.LandingZ);
        }
        if (!landed)
        {
            path.RestoreCheckPos();
            CollisionInfo.ClearContactPlane();
        }
        path.InsertType = path.Backup;
        path.Walkable = null;
        return ValidatePlacement(TransitionState.OK, adjust: true) == TransitionState.OK;
    }

    /// <summary>
    /// Retail find_placement_pos: tries the spot itself, then rings of growing radius (up to 4 m, or 2 m for
    /// a sphere under 0.125 m) with more headings on each ring, and takes the first free spot.
    /// </summary>
    private bool FindPlacementPos()
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        path.SetCheckPos(path.CurPos, path.CurCell);
        ci.SlidingNormalValid = false;
        ci.ClearContactPlane();
        if (ValidatePlacementTransition(TransitionalInsert(3)) == TransitionState.OK)
            return true;
        if (!path.PlacementAllowsSliding)
            return false;

        float reach = 4.0f;
        float radius = path.LocalSphere[0].Radius;
        bool small = false;
        if (radius < 0.125f)
        {
            small = true;
            reach = 2.0f;
        }
        else if (radius < 0.48f)
        {
            radius = 0.48f;
        }
        float rings = 4.0f / radius;
        if (small)
            rings *= 0.5f;
        if (rings <= 1.0f)
            return false;
        int ringCount = (int)MathF.Ceiling(rings);
        float ringStep = reach / ringCount;
        // Retail writes π as 3.1415999 here (acclient CTransition.c:1588).
        float arcStep = 3.1415999f * ringStep / radius;
        float distance = 0f, arc = 0f;
        for (int ring = 0; ring < ringCount; ring++)
        {
            distance += ringStep;
            arc += arcStep;
            int headings = (int)MathF.Ceiling(arc) * 2;
            float degreesPerHeading = 360.0f / headings;
            for (int h = 0; h < headings; h++)
            {
                path.SetCheckPos(path.CurPos, path.CurCell);
                // Retail headings: 0° is north (+Y), 90° east (+X).
                float radians = degreesPerHeading * h * (MathF.PI / 180f);
                var offset = new Vector3(Geometry.PortableMath.Sin(radians), Geometry.PortableMath.Cos(radians), 0f) * distance;
                path.GlobalOffset = AdjustOffset(offset);
                if (path.GlobalOffset.Length() < PhysicsConstants.Epsilon)
                    continue;
                path.AddOffsetToCheckPos(path.GlobalOffset);
                ci.SlidingNormalValid = false;
                ci.ClearContactPlane();
                if (ValidatePlacementTransition(TransitionalInsert(3)) == TransitionState.OK)
                    return true;
            }
        }
        return false;
    }
}
