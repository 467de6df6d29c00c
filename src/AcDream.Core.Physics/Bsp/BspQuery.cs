using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>Where a sphere lies against a cell BSP (retail BoundingType).</summary>
public enum BoundingType
{
    /// <summary>Entirely outside.</summary>
    Outside = 0,
    /// <summary>Partly inside.</summary>
    PartiallyInside = 1,
    /// <summary>Entirely inside.</summary>
    EntirelyInside = 2,
}

/// <summary>The retail queries over a physics BSP tree (BSPTREE / BSPNODE / BSPLEAF).</summary>
public static class BspQuery
{
    /// <summary>
    /// Retail BSPTREE::find_collisions: collides the path's local-space spheres (prepared by
    /// <see cref="SpherePath.CacheLocalSpaceSphere"/>) with the tree, in every mode the path is in
    /// (placement, walkable check, step down, collide, step up…), updating the transition.
    /// <paramref name="scale"/> is the scale of the tree's space.
    /// </summary>
    public static TransitionState FindCollisions(BspTree tree, Transition transition, float scale)
        => throw new NotImplementedException();

    /// <summary>Retail BSPTREE::placement_insert for a cell's BSP.</summary>
    public static TransitionState PlacementInsert(BspTree tree, Transition transition)
        => throw new NotImplementedException();

    /// <summary>Retail point_inside_cell_bsp: true when the point is on the inside of every split on its path.</summary>
    public static bool PointInsideCellBsp(BspTree tree, Vector3 point)
        => throw new NotImplementedException();

    /// <summary>Retail sphere_intersects_cell_bsp.</summary>
    public static BoundingType SphereIntersectsCellBsp(BspTree tree, in Sphere sphere)
        => throw new NotImplementedException();
}
