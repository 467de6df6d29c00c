using System.Numerics;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// What a transition learned about contact (retail COLLISIONINFO): the contact plane under the mover
/// and the last one known from earlier frames, the sliding and collision normals, and the objects hit.
/// </summary>
internal sealed class CollisionInfo
{
    /// <summary>A record taking the default shortcuts (<see cref="ShortcutSettings.Default"/>).</summary>
    public CollisionInfo() : this(ShortcutSettings.Default) { }

    /// <summary>A record taking <paramref name="shortcuts"/> (its transition's): only <see cref="Shortcuts.UnitMemo"/> applies.</summary>
    public CollisionInfo(Shortcuts shortcuts) => _slidingUnit = _collisionUnit = UnitMemo.For(shortcuts);

    /// <summary>The last contact plane is known (carried between frames).</summary>
    public bool LastKnownContactPlaneValid;
    /// <summary>The last contact plane.</summary>
    public Plane LastKnownContactPlane;
    /// <summary>The last contact plane is water.</summary>
    public bool LastKnownContactPlaneIsWater;
    /// <summary>The cell of the last contact plane.</summary>
    public uint LastKnownContactPlaneCellId;
    /// <summary>A contact plane was found in this step.</summary>
    public bool ContactPlaneValid;
    /// <summary>The contact plane, in the landblock space of <see cref="ContactPlaneCellId"/>.</summary>
    public Plane ContactPlane;
    /// <summary>The cell whose landblock space the contact plane is in.</summary>
    public uint ContactPlaneCellId;
    /// <summary>The contact plane is water.</summary>
    public bool ContactPlaneIsWater;
    /// <summary>What set the contact plane (not retail: retail keeps only the plane and its cell).</summary>
    public GroundKind ContactGround;
    /// <summary>The object whose shape set the contact plane, or 0.</summary>
    public uint ContactGroundObject;
    /// <summary>What set the last known contact plane.</summary>
    public GroundKind LastKnownGround;
    /// <summary>The object whose shape set the last known contact plane, or 0.</summary>
    public uint LastKnownGroundObject;
    /// <summary>
    /// The object whose shape is being tested (0 outside object tests), so that a contact plane found by
    /// a shape test is known to be that object's.
    /// </summary>
    public uint ShapeOwner;
    /// <summary>A sliding normal constrains the next step.</summary>
    public bool SlidingNormalValid;
    /// <summary>The sliding normal (horizontal).</summary>
    public Vector3 SlidingNormal;
    /// <summary>A collision normal was recorded.</summary>
    public bool CollisionNormalValid;
    /// <summary>The collision normal.</summary>
    public Vector3 CollisionNormal;
    /// <summary>Retail's adjust_offset field (kept for parity; unused by the resolution).</summary>
    public Vector3 AdjustOffset;
    /// <summary>The ids of the objects collided with, in order, without repeats.</summary>
    public System.ReadOnlyMemory<uint> CollidedObjects => _collided.Items;
    // The engine hands this list out in its MoveResult (valid until its next call), so a move's list is
    // never copied.
    private readonly IdList _collided = new();
    /// <summary>The id of the last object whose test was not OK, or 0.</summary>
    public uint LastCollidedObject;
    /// <summary>The mover hit cell geometry or terrain.</summary>
    public bool CollidedWithEnvironment;
    /// <summary>Frames spent falling in place (retail's stationary-fall counter).</summary>
    public int FramesStationaryFall;
    /// <summary>
    /// The transition asked for the mover's velocity to be zeroed (retail calls OBJECTINFO::kill_velocity
    /// when a blocked mover falls back on its last known contact plane). The transition has no velocity of
    /// its own; a client applies this.
    /// </summary>
    public bool VelocityKilled;

    /// <summary>Clears everything (retail COLLISIONINFO::init); keeps the list's capacity.</summary>
    public void Reset()
    {
        LastKnownContactPlaneValid = false;
        LastKnownContactPlane = default;
        LastKnownContactPlaneIsWater = false;
        LastKnownContactPlaneCellId = 0;
        ContactPlaneValid = false;
        ContactPlane = default;
        ContactPlaneCellId = 0;
        ContactPlaneIsWater = false;
        ContactGround = GroundKind.None;
        ContactGroundObject = 0;
        LastKnownGround = GroundKind.None;
        LastKnownGroundObject = 0;
        ShapeOwner = 0;
        SlidingNormalValid = false;
        SlidingNormal = default;
        CollisionNormalValid = false;
        CollisionNormal = default;
        AdjustOffset = default;
        _collided.Clear();
        LastCollidedObject = 0;
        CollidedWithEnvironment = false;
        FramesStationaryFall = 0;
        VelocityKilled = false;
    }

    /// <summary>Sets the contact plane.</summary>
    public void SetContactPlane(in Plane plane, bool isWater)
    {
        ContactPlaneValid = true;
        ContactPlane = plane;
        ContactPlaneIsWater = isWater;
    }

    /// <summary>
    /// Records what set the contact plane just set: the object whose shape is being tested, when there is
    /// one, else <paramref name="kind"/>.
    /// </summary>
    public void SetGround(GroundKind kind)
    {
        uint owner = ShapeOwner;
        ContactGround = owner != 0 ? GroundKind.Object : kind;
        ContactGroundObject = owner;
    }

    /// <summary>Drops the contact plane of this step.</summary>
    public void ClearContactPlane()
    {
        ContactPlaneValid = false;
        ContactPlaneIsWater = false;
    }

    /// <summary>
    /// Records a collision normal, normalized; a vector too short to normalize is recorded as zero
    /// (retail set_collision_normal).
    /// </summary>
    public void SetCollisionNormal(Vector3 normal)
    {
        CollisionNormalValid = true;
        CollisionNormal = _collisionUnit.NormalizeCheckSmall(ref normal) ? Vector3.Zero : normal;
    }

    /// <summary>
    /// Records a sliding normal: the horizontal part of <paramref name="normal"/>, normalized, or zero when
    /// too short (retail COLLISIONINFO::set_sliding_normal, acclient CTransition.c:244-252; ACE keeps the
    /// horizontal part unnormalized, which retail does not).
    /// </summary>
    public void SetSlidingNormal(Vector3 normal)
    {
        SlidingNormalValid = true;
        SlidingNormal = HorizontalUnit(normal);
    }

    /// <summary>The horizontal part of a vector, normalized; zero when too short (the sliding normal's form).</summary>
    internal Vector3 HorizontalUnit(Vector3 normal)
    {
        var horizontal = new Vector3(normal.X, normal.Y, 0f);
        return _slidingUnit.NormalizeCheckSmall(ref horizontal) ? Vector3.Zero : horizontal;
    }

    // The last normals normalized (the same ones return frame after frame while a mover slides).
    private UnitMemo _slidingUnit;
    private UnitMemo _collisionUnit;

    /// <summary>Adds an object to the collided list once; a non-OK result makes it the last collided.</summary>
    public void AddObject(uint objectId, TransitionState state)
    {
        if (!_collided.Add(objectId))
            return;
        if (state != TransitionState.OK)
            LastCollidedObject = objectId;
    }
}
