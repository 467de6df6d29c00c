using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail InterpolationManager (CInterpolationManager.c): smooths an object towards the positions a server
/// reports for it. The positions wait in a queue; each quantum the object is moved towards the head at most at
/// twice its adjusted max speed (through the transition, by the body step), a head within 0.05 m is done, and
/// every 5 frames the progress is checked; a node that does not progress fails, and after more than 3 failed
/// nodes, or when the last node failed, the object is teleported (blipped). A position farther than the
/// autonomy blip distance blips at once. One instance per object; no allocation.
/// </summary>
internal sealed class InterpolationManager
{
    /// <summary>InterpolateTo's queue cap: with this many nodes queued the oldest is dropped first (0x14).</summary>
    public const int MaxNodes = 20;
    /// <summary>A position this close (m) to the object, or to the last node, is the same position.</summary>
    public const float DesiredDistance = 0.05f;
    /// <summary>A node that fails its progress check closer than this (m) counts as reached.</summary>
    public const float CloseEnough = 0.2f;
    /// <summary>The progress check runs every this many frames.</summary>
    public const int ProgressFrames = 5;
    /// <summary>The share of the max speed the object must have made good since the last check.</summary>
    public const float MinProgressRate = 0.3f;
    /// <summary>More failed nodes than this blip the object.</summary>
    public const int MaxFailedNodes = 3;
    /// <summary>MAX_INTERPOLATED_VELOCITY (m/s): the speed of an object without a motion interpreter.</summary>
    public const float MaxInterpolatedVelocity = 7.5f;
    /// <summary>BIG_DISTANCE: original_distance before the first check, so that the first check always passes.</summary>
    public const float BigDistance = 999999f;

    private readonly Position[] _queue = new Position[MaxNodes];
    private int _head, _count;
    private float _originalDistance = BigDistance;
    private int _frameCounter;
    private float _progressQuantum;
    private int _nodeFailCounter;
    private bool _keepHeading;
    private Position _blipTo;

    public int Count => _count;
    public int NodeFailCounter => _nodeFailCounter;
    public float OriginalDistance => _originalDistance;
    public bool KeepHeading => _keepHeading;

    /// <summary>The queued position <paramref name="index"/> places from the head.</summary>
    public Position Node(int index) => _queue[(_head + index) % MaxNodes];

    /// <summary>
    /// InterpolationManager::InterpolateTo (CInterpolationManager.c:389016). Returns true with the heading to
    /// give the object when the position is where the object already is and the heading is not kept (retail
    /// calls set_heading then StopInterpolating).
    /// </summary>
    public bool InterpolateTo(in Position p, bool keepHeading, in ObjectView obj, out float setHeading)
    {
        setHeading = 0f;
        var last = _count > 0 ? _queue[Tail] : obj.Position;
        if (obj.AutonomyBlipDistance >= Distances.Between(last, p))
        {
            if (Distances.Between(obj.Position, p) > DesiredDistance)
            {
                while (_count > 0 && Distances.Between(_queue[Tail], p) < DesiredDistance)
                    _count--; // RemoveTail: the new position replaces a node it repeats
                while (_count >= MaxNodes)
                    DropHead();
                _keepHeading = keepHeading;
                Enqueue(p, obj);
            }
            else
            {
                if (!keepHeading)
                {
                    setHeading = Headings.Of(p.Frame);
                    StopInterpolating();
                    return true;
                }
                StopInterpolating();
            }
            return false;
        }
        // Too far to smooth: queued and marked failed, so the next UseTime blips to it. Retail reads the keep_heading
        // of the previous call here (the argument is not stored on this path), and does not cap the queue; the cap
        // kept here changes nothing, since the blip goes to the newest node.
        if (_count >= MaxNodes)
            DropHead();
        Enqueue(p, obj);
        _nodeFailCounter = MaxFailedNodes + 1;
        return false;
    }

    /// <summary>InterpolationManager::StopInterpolating: the queue emptied and the progress state reset.</summary>
    public void StopInterpolating()
    {
        _count = 0;
        _head = 0;
        _frameCounter = 0;
        _progressQuantum = 0f;
        _nodeFailCounter = 0;
        _originalDistance = BigDistance;
    }

    /// <summary>
    /// InterpolationManager::adjust_offset (CInterpolationManager.c:389177): while the object touches the
    /// ground, the offset becomes the way to the head node (in body axes, its rotation included unless the
    /// heading is kept), shortened to the max speed × quantum.
    /// </summary>
    public void AdjustOffset(ref Frame offset, float quantum, in ObjectView obj, bool sticky)
    {
        if (_count == 0 || !obj.Contact)
            return;
        var head = _queue[_head];
        double currentD = Distances.Between(obj.Position, head);
        float current = (float)currentD;
        if (currentD < DesiredDistance)
        {
            NodeCompleted(true, obj);
            return;
        }
        // fUseAdjustedSpeed_ is set: twice get_adjusted_max_speed, else MAX_INTERPOLATED_VELOCITY.
        float maxSpeed = (float)(obj.AdjustedMaxSpeed * 2.0);
        if (maxSpeed < PhysicsConstants.Epsilon)
            maxSpeed = MaxInterpolatedVelocity;
        _frameCounter++;
        _progressQuantum += quantum;
        if (_frameCounter >= ProgressFrames)
        {
            float progress = _originalDistance - current;
            if (!sticky && !(progress >= PhysicsConstants.Epsilon && progress / _progressQuantum / maxSpeed >= MinProgressRate))
            {
                if (current < CloseEnough)
                {
                    NodeCompleted(true, obj);
                    return;
                }
                _nodeFailCounter++;
                NodeCompleted(false, obj);
                return;
            }
            _frameCounter = 0;
            _progressQuantum = 0f;
            _originalDistance = current;
        }
        var adjustment = Subtract2(head, obj.Position);
        float step = maxSpeed * quantum;
        float distance = adjustment.Origin.Length();
        if (distance <= DesiredDistance)
            NodeCompleted(true, obj); // and still moves the last bit
        if (distance > step)
            adjustment.Origin *= step / distance;
        if (_keepHeading)
            adjustment.Orientation = Headings.Facing(0f);
        offset = adjustment;
    }

    /// <summary>
    /// The first half of InterpolationManager::UseTime (CInterpolationManager.c:389277): whether the object
    /// must be blipped, and where to: the newest queued node, else the last failed one.
    /// The caller places the object there (SetPositionSimple) and calls <see cref="StopInterpolating"/> when
    /// that succeeded; when it fails the queue stays and the blip is tried again at the next UseTime.
    /// </summary>
    public bool BlipTarget(out Position target)
    {
        target = default;
        if (_nodeFailCounter <= MaxFailedNodes && (_count > 0 || _nodeFailCounter <= 0))
            return false;
        target = _count > 0 ? _queue[Tail] : _blipTo;
        return true;
    }

    // InterpolationManager::NodeCompleted (CInterpolationManager.c:388881).
    private void NodeCompleted(bool success, in ObjectView obj)
    {
        _frameCounter = 0;
        _progressQuantum = 0f;
        bool popped = _count > 0;
        var done = popped ? _queue[_head] : default;
        if (popped)
            DropHead();
        if (_count > 0)
        {
            _originalDistance = (float)Distances.Between(obj.Position, _queue[_head]);
            return;
        }
        _originalDistance = BigDistance;
        if (success)
            StopInterpolating();
        else if (popped)
            _blipTo = done;
    }

    private int Tail => (_head + _count - 1) % MaxNodes;

    private void DropHead()
    {
        _head = (_head + 1) % MaxNodes;
        _count--;
    }

    private void Enqueue(in Position p, in ObjectView obj)
    {
        var node = p;
        if (_keepHeading)
            node.Frame.Orientation = Headings.Facing(Headings.Of(obj.Position.Frame));
        _queue[(_head + _count) % MaxNodes] = node;
        _count++;
    }

    /// <summary>
    /// Position::subtract2 (CInterpolationManager.c:388972): the frame that takes <paramref name="current"/> to
    /// <paramref name="head"/>: the rotation current⁻¹·head (Frame::subtract2, normalized as set_rotate does) and
    /// the head's origin in the current position's local axes, across landblocks (Position::localtolocal).
    /// </summary>
    internal static Frame Subtract2(in Position head, in Position current)
    {
        var h = head.Frame.Orientation;
        var c = current.Frame.Orientation;
        float qw = h.W * c.W + c.Y * h.Y + h.X * c.X + h.Z * c.Z;
        float qx = h.X * c.W - h.W * c.X - c.Y * h.Z + h.Y * c.Z;
        float qy = h.Z * c.X + c.W * h.Y - c.Y * h.W - h.X * c.Z;
        float qz = h.Z * c.W - h.Y * c.X + h.X * c.Y - h.W * c.Z;
        var result = new Frame(current.LocalToLocal(head, Vector3.Zero));
        result.SetRotate(qw, qx, qy, qz);
        return result;
    }
}
