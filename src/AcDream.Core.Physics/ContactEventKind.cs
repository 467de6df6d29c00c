namespace AcDream.Core.Physics;

/// <summary>What a <see cref="ContactEvent"/> reports.</summary>
public enum ContactEventKind : byte
{
    /// <summary>
    /// A contact with a (non-static) object began: it had no collision record (retail track_object_collision
    /// finds no record to clobber and calls report_object_collision).
    /// </summary>
    ObjectStart = 0,
    /// <summary>
    /// A contact with an object ended: its record was not refreshed for more than
    /// <see cref="PhysicsConstants.CollisionRecordTimeout"/> (an ethereal object: for any time), or the
    /// records were ended by force (retail report_collision_end → report_object_collision_end).
    /// </summary>
    ObjectEnd = 1,
    /// <summary>
    /// A contact with the environment began (retail report_environment_collision): terrain, a cell's or a
    /// building's polygons or a static object hit while airborne, or a landing on walkable ground.
    /// </summary>
    EnvironmentStart = 2,
    /// <summary>
    /// A contact with the environment ended: a transition without one after one with it. Retail only clears
    /// its colliding_with_environment flag here and reports nothing; the event is this library's.
    /// </summary>
    EnvironmentEnd = 3,
}
