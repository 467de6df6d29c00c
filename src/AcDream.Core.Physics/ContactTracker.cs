using System;

namespace AcDream.Core.Physics;

/// <summary>
/// Retail's collision records of one mover (CPhysicsObj's collision_table and colliding_with_environment,
/// kept by CPhysicsObj::handle_all_collisions after every accepted transition): which objects it is in
/// contact with, since when, and whether it is colliding with the environment; each call to
/// <see cref="Track(in BodyStepResult, in MoverState, double)"/> lists the contacts that started and ended
/// (<see cref="Events"/>). Keep one per mover beside its <see cref="MoverState"/>, and call it after every
/// <c>PhysicsEngine.Step</c> or <see cref="PhysicsEngine.Resolve"/> of that mover with the clock the
/// host runs the world on (retail PhysicsTimer::curr_time).
/// </summary>
/// <remarks>
/// <para>As retail (CPhysicsObj.c): every object the transition collided with (<see cref="MoveResult.CollidedObjects"/>,
/// never a static object) gets its record touched at <c>now</c>; one that had none starts a contact
/// (track_object_collision). Then every record untouched for more than
/// <see cref="PhysicsConstants.CollisionRecordTimeout"/>, or for any time when the object was ethereal, ends
/// (report_collision_end). Then the environment: while colliding it stays so as long as the transition
/// collided with the environment; otherwise a collision with the environment
/// (<see cref="MoveResult.CollidedWithEnvironment"/>) or a landing on walkable ground starts one
/// (report_environment_collision). Only accepted transitions are tracked: a refused move, or a step whose
/// quanta ran no transition (the body did not move), changes nothing, as retail calls handle_all_collisions
/// from SetPositionInternal only.</para>
/// <para>Not retail: a step of several quanta (a frame longer than <see cref="PhysicsConstants.MaxQuantum"/>)
/// is tracked once, at its end, with the objects of all its quanta; retail tracks each quantum at its own
/// time. Ends are listed in the order the records were made (retail walks its hash table).</para>
/// <para>Allocates nothing once its arrays have grown to the most records and events seen.</para>
/// </remarks>
public sealed class ContactTracker
{
    private struct Record
    {
        public uint Id;
        public double Touched;
        public bool Ethereal;
    }

    private readonly PhysicsWorld _world;
    private Record[] _records = new Record[4];
    private int _recordCount;
    private ContactEvent[] _events = new ContactEvent[4];
    private int _eventCount;
    private double _now = double.NegativeInfinity;

    /// <summary>Creates the records of one mover in a world (the world tells which objects are ethereal).</summary>
    public ContactTracker(PhysicsWorld world) => _world = world ?? throw new ArgumentNullException(nameof(world));

    /// <summary>The contacts that started and ended in the last call, in order: starts, then ends, then the environment's.</summary>
    public ReadOnlySpan<ContactEvent> Events => new(_events, 0, _eventCount);

    /// <summary>True while retail's colliding_with_environment flag is set.</summary>
    public bool CollidingWithEnvironment { get; private set; }

    /// <summary>How many objects the mover has a collision record with.</summary>
    public int ObjectCount => _recordCount;

    /// <summary>True when the mover has a collision record with the object.</summary>
    public bool IsTouching(uint objectId) => Find(objectId) >= 0;

    /// <summary>
    /// Tracks a body step: <paramref name="previous"/> is the state passed to <c>PhysicsEngine.Step</c>,
    /// <paramref name="now"/> the host's clock after the step, in seconds (never earlier than the last call's).
    /// </summary>
    public void Track(in BodyStepResult step, in MoverState previous, double now) =>
        Track(step.Move, previous, now, step.Transitions > 0);

    /// <summary>
    /// Tracks a move: <paramref name="previous"/> is the state passed to <see cref="PhysicsEngine.Resolve"/>,
    /// <paramref name="now"/> the host's clock after the move, in seconds (never earlier than the last call's).
    /// </summary>
    public void Track(in MoveResult move, in MoverState previous, double now) => Track(move, previous, now, move.Succeeded);

    private void Track(in MoveResult move, in MoverState previous, double now, bool accepted)
    {
        CheckTime(now);
        _eventCount = 0;
        if (!accepted)
            return;
        // handle_all_collisions: track_object_collision for each object collided with.
        var ids = move.CollidedObjects.Span;
        for (int i = 0; i < ids.Length; i++)
        {
            bool ethereal = _world.Objects.TryGetState(ids[i], out var state) && (state & PhysicsState.Ethereal) != 0;
            int at = Find(ids[i]);
            if (at >= 0)
            {
                _records[at].Touched = now;
                _records[at].Ethereal = ethereal;
                continue;
            }
            if (_recordCount == _records.Length)
                Array.Resize(ref _records, _records.Length * 2);
            _records[_recordCount++] = new Record { Id = ids[i], Touched = now, Ethereal = ethereal };
            Add(ContactEventKind.ObjectStart, ids[i]);
        }
        EndRecords(now, force: false);
        // The environment (handle_all_collisions after report_collision_end).
        var next = move.Next;
        if (CollidingWithEnvironment)
        {
            CollidingWithEnvironment = move.CollidedWithEnvironment;
            if (!CollidingWithEnvironment)
                Add(ContactEventKind.EnvironmentEnd, 0);
        }
        else if (move.CollidedWithEnvironment || (!previous.OnWalkable && next.OnWalkable))
        {
            CollidingWithEnvironment = true;
            Add(ContactEventKind.EnvironmentStart, 0);
        }
    }

    /// <summary>
    /// Ends every object record now (retail report_collision_end(force_end = 1), called when the object
    /// leaves the world, is hidden or teleports); <see cref="Events"/> lists the ends.
    /// </summary>
    public void EndAll(double now)
    {
        CheckTime(now);
        _eventCount = 0;
        EndRecords(now, force: true);
    }

    private void EndRecords(double now, bool force)
    {
        int kept = 0;
        for (int i = 0; i < _recordCount; i++)
        {
            var r = _records[i];
            double idle = now - r.Touched;
            if (force || idle > PhysicsConstants.CollisionRecordTimeout || (r.Ethereal && idle > 0.0))
                Add(ContactEventKind.ObjectEnd, r.Id);
            else
                _records[kept++] = r;
        }
        _recordCount = kept;
    }

    private int Find(uint id)
    {
        for (int i = 0; i < _recordCount; i++)
            if (_records[i].Id == id)
                return i;
        return -1;
    }

    private void Add(ContactEventKind kind, uint id)
    {
        if (_eventCount == _events.Length)
            Array.Resize(ref _events, _events.Length * 2);
        _events[_eventCount++] = new ContactEvent(kind, id);
    }

    private void CheckTime(double now)
    {
        if (!double.IsFinite(now) || now < _now)
            throw new ArgumentException($"now: must be finite and not earlier than the last call's {_now}, got {now}.", nameof(now));
        _now = now;
    }
}
