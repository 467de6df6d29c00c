namespace AcDream.Core.Physics;

/// <summary>What a missile's flight ended on (retail's two reports: CPhysicsObj::report_object_collision and report_environment_collision).</summary>
public enum MissileHitKind : byte
{
    /// <summary>Nothing yet: the missile is still in flight.</summary>
    None = 0,
    /// <summary>
    /// An object (<see cref="MissileHit.ObjectId"/>): retail report_object_collision, which hands the missile's
    /// weenie an AtkCollisionProfile (the object's id) and clears the missile's Missile, AlignPath and
    /// PathClipped bits.
    /// </summary>
    Object = 1,
    /// <summary>
    /// Cell geometry, a building, terrain, a static object, or an object with
    /// <see cref="PhysicsState.ReportCollisionsAsEnvironment"/> (then <see cref="MissileHit.ObjectId"/> names it):
    /// retail report_environment_collision, which clears the same bits.
    /// </summary>
    Environment = 2,
}
