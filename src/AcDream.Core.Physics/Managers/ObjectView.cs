namespace AcDream.Core.Physics.Managers;

/// <summary>
/// What the position managers read from their object for one call (retail reads them off CPhysicsObj and its
/// CMotionInterp): where it is, whether it touches the ground (transient Contact), its radius, its speeds.
/// </summary>
internal readonly struct ObjectView
{
    public ObjectView(in Position position, bool contact, float radius, float maxSpeed, float adjustedMaxSpeed, bool isPlayer)
    {
        Position = position;
        Contact = contact;
        Radius = radius;
        MaxSpeed = maxSpeed;
        AdjustedMaxSpeed = adjustedMaxSpeed;
        IsPlayer = isPlayer;
    }

    /// <summary>The object's position (m_position).</summary>
    public Position Position { get; }
    /// <summary>transient_state &amp; Contact.</summary>
    public bool Contact { get; }
    /// <summary>CPhysicsObj::GetRadius.</summary>
    public float Radius { get; }
    /// <summary>CMotionInterp::get_max_speed (0 without an interpreter).</summary>
    public float MaxSpeed { get; }
    /// <summary>CMotionInterp::get_adjusted_max_speed (0 without an interpreter).</summary>
    public float AdjustedMaxSpeed { get; }
    /// <summary>The object is the client's own player (CPhysicsObj::player_object).</summary>
    public bool IsPlayer { get; }

    /// <summary>
    /// CPhysicsObj::GetAutonomyBlipDistance (CPhysicsObj.c:303): how far an update may be from the last queued
    /// position before the object is teleported instead of smoothed: 100 m outdoors; indoors (cell index
    /// 0x100 or more) 25 m for the player, 20 m for any other object.
    /// </summary>
    public float AutonomyBlipDistance => (Position.CellId & 0xFFFF) >= 0x100 ? (IsPlayer ? 25f : 20f) : 100f;
}
