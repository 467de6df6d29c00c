using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Shapes;

/// <summary>Collides a transition with one placed physics model (retail CPhysicsPart + CGfxObj::find_obj_collisions).</summary>
internal static class PartCollision
{
    /// <summary>
    /// Expresses the path in the part's space, and when a mover sphere touches the model's bounding
    /// sphere, runs the BSP query (the placement insert for an initial placement).
    /// </summary>
    public static TransitionState Collide(Transition transition, PhysicsModel model, in Position partPosition, float scale)
    {
        var path = transition.SpherePath;
        path.CacheLocalSpaceSphere(partPosition, scale);
        var bounds = model.BoundingSphere;
        for (int i = 0; i < path.NumSphere; i++)
        {
            var local = path.LocalSpaceSphere[i];
            float reach = bounds.Radius + local.Radius;
            if (Vector3.DistanceSquared(bounds.Center, local.Center) - reach * reach < PhysicsConstants.Epsilon)
            {
                return path.InsertType == InsertType.InitialPlacement
                    ? BspQuery.PlacementInsert(model.Bsp, transition)
                    : BspQuery.FindCollisions(model.Bsp, transition, scale);
            }
        }
        return TransitionState.OK;
    }
}
