namespace AcDream.Core.Physics.Transitions;

/// <summary>The mover's description for one transition (retail OBJECTINFO).</summary>
internal sealed class ObjectInfo
{
    /// <summary>The mover's retail object id (0 for none); the mover never collides with itself.</summary>
    public uint ObjectId;
    /// <summary>The mover's state bits (contact, walkable, edge slide, player, PK…).</summary>
    public ObjectInfoState State;
    /// <summary>The mover's PhysicsState (missile, ethereal, gravity…).</summary>
    public PhysicsState PhysicsState;
    /// <summary>The mover's scale.</summary>
    public float Scale = 1f;
    /// <summary>How high the mover may step up, metres.</summary>
    public float StepUpHeight;
    /// <summary>How far the mover may step down to stay grounded, metres.</summary>
    public float StepDownHeight;
    /// <summary>The mover is ethereal.</summary>
    public bool Ethereal;
    /// <summary>The mover steps down to follow the ground (every mover but a missile).</summary>
    public bool StepDown;
    /// <summary>A missile's target id, or 0.</summary>
    public uint TargetId;

    /// <summary>The least normal Z the mover can walk on (retail get_walkable_z: floor_z for everyone).</summary>
    public float GetWalkableZ() => PhysicsConstants.FloorZ;

    /// <summary>True when a normal is walkable ground: Z at least floor_z (retail is_valid_walkable).</summary>
    public static bool IsValidWalkable(System.Numerics.Vector3 normal) => normal.Z >= PhysicsConstants.FloorZ;

    /// <summary>True when the mover is a player.</summary>
    public bool IsPlayer => (State & ObjectInfoState.IsPlayer) != 0;
}
