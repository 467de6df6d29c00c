using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

public sealed partial class PhysicsEngine
{
    /// <summary>
    /// InterpolationManager::UseTime's blip: CPhysicsObj::SetPositionSimple(target, sliding), retail's placement
    /// (<see cref="Place"/>). When it fails (no free spot, or the target's cell is not loaded: retail's SetPosition
    /// error) the queue is kept and the blip is tried again at the next quantum, as retail does; when it succeeds the
    /// smoothing stops.
    /// </summary>
    private void Blip(MoverDescription mover, ref MoverState s, ref BodyState b, in Position target, PositionManager manager)
    {
        var cell = _transition.World.Cells.Get(target.CellId);
        if (cell is null || !(cell.DistanceOutside(target.Frame.Origin) <= InputLimits.MaxDistanceFromCell + mover.Reach))
            return;
        var placed = Place(mover, target);
        if (!placed.Succeeded)
            return;
        s = placed.Next;
        b.Acceleration = BodyMotion.Acceleration(mover.PhysicsState, s.Contact, s.OnWalkable);
        manager.StopInterpolating();
    }
}
