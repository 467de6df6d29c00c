using System;
using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail StickyManager (CStickyManager.c): keeps an attacker at a 0.3 m gap from its target and facing it.
/// Each quantum the offset is replaced by the way to the gap (on the ground plane, at most 5 × the max speed)
/// and a turn to face the target. Sticking ends 1 s after <see cref="StickTo"/> (retail sets the timeout only
/// there: a target update does not extend it; a server keeps a melee attacker stuck by sticking it again),
/// or when the target is lost. One instance per object; no allocation.
/// </summary>
internal sealed class StickyManager
{
    /// <summary>STICKY_RADIUS: the gap (m) kept between the two cylinders.</summary>
    public const float StickyRadius = 0.3f;
    /// <summary>How long (s) a stick lasts after StickTo (StickTo: sticky_timeout_time = cur_time + 1.0).</summary>
    public const double StickyTime = 1.0;
    /// <summary>The catch-up speed is the max speed × this.</summary>
    public const float SpeedFactor = 5f;
    /// <summary>The catch-up speed (m/s) of an object whose max speed is below EPSILON.</summary>
    public const float DefaultSpeed = 15f;

    public uint TargetId { get; private set; }
    public bool Initialized { get; private set; }
    public float TargetRadius { get; private set; }
    public double TimeoutTime { get; private set; }
    public Position TargetPosition { get; private set; }

    /// <summary>
    /// StickyManager::StickTo (CStickyManager.c:388664): a running stick ends first (true: the owner cancels the
    /// MoveTo, as retail's cancel_moveto there); the target's position is awaited.
    /// </summary>
    public bool StickTo(uint targetId, float targetRadius, double now)
    {
        bool ended = End();
        TargetRadius = targetRadius;
        TargetId = targetId;
        Initialized = false;
        TimeoutTime = now + StickyTime;
        return ended;
    }

    /// <summary>
    /// StickyManager::HandleUpdateTarget (CStickyManager.c:388690): an Ok update stores the position; any other status
    /// ends the stick (true: the owner cancels the MoveTo).
    /// </summary>
    public bool HandleUpdateTarget(uint targetId, TargetStatus status, in Position position)
    {
        if (targetId != TargetId)
            return false;
        if (status != TargetStatus.Ok)
            return End();
        Initialized = true;
        TargetPosition = position;
        return false;
    }

    /// <summary>
    /// StickyManager::UseTime (CStickyManager.c:388604): the stick ends once the clock passes the timeout (true: the
    /// owner cancels the MoveTo).
    /// </summary>
    public bool UseTime(double now) => TargetId != 0 && now > TimeoutTime && End();

    /// <summary>
    /// StickyManager::HandleExitWorld (CStickyManager.c:388501), and the same clearing inside StickTo, UseTime and
    /// HandleUpdateTarget: a running stick ends. Returns whether one was running; retail then calls clear_target and
    /// CPhysicsObj::cancel_moveto, which the owner does (<see cref="PositionManager"/>).
    /// </summary>
    public bool End()
    {
        if (TargetId == 0)
            return false;
        TargetId = 0;
        Initialized = false;
        return true;
    }

    /// <summary>StickyManager::adjust_offset (CStickyManager.c:388518).</summary>
    public void AdjustOffset(ref Frame offset, float quantum, in ObjectView obj)
    {
        if (TargetId == 0 || !Initialized)
            return;
        var me = obj.Position;
        var target = TargetPosition;
        var way = me.GlobalToLocalVec(me.GetOffset(target));
        way.Z = 0f;
        float gap = (float)(Distances.CylinderNoZ(obj.Radius, me, TargetRadius, target) - StickyRadius);
        float length = way.Length();
        way = length < PhysicsConstants.Epsilon ? Vector3.Zero : way / length; // normalize_check_small
        float speed = obj.MaxSpeed * SpeedFactor;
        if (speed < PhysicsConstants.Epsilon)
            speed = DefaultSpeed;
        float step = speed * quantum;
        if (step >= MathF.Abs(gap))
            step = gap; // the whole gap (negative: backs away to it)
        offset.Origin = new Vector3(way.X * step, way.Y * step, way.Z * step);
        float turn = Headings.Towards(me, target) - Headings.Of(me.Frame);
        if (MathF.Abs(turn) < PhysicsConstants.Epsilon)
            turn = 0f;
        if (-PhysicsConstants.Epsilon > turn)
            turn += 360f;
        offset.Orientation = Headings.Facing(turn);
    }
}
