using System;
using System.Numerics;
using System.Diagnostics;
using System.Threading;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// A server under a crowd: <c>n</c> creatures, each registered as an object (a cylinder 0.48 m × 1.835 m, so they
/// collide with one another and with the player), chase one player with retail's MoveTo and pile up around
/// it. The player runs a circle of 6 m at 2.5 m/s (its positions come from its client, so the server only
/// moves it in the registry). Retail has no avoidance: the creatures press into a few cells and every
/// creature's transition meets the others' cylinders there.
/// <para>
/// A tick (30 Hz) as a server runs it: the player's new position is written to the registry; each creature
/// (with <c>threads</c> 2, the main thread and a second one take chunks of 8 creatures from one counter, one
/// engine per thread) is given its
/// orders by its AI and takes one body step through its motion layer against the registry as it stood at the
/// start of the tick; then, on one thread, every creature that moved is moved in the registry, in creature
/// order. Each creature's step reads only the registry and writes only its own state, so the split does not
/// change a bit (<see cref="Fingerprint"/>). Only the public API is used, so the timing driver can build this
/// against an older commit.
/// </para>
/// </summary>
internal sealed class Crowd : IDisposable
{
    /// <summary>The player's object id.</summary>
    public const uint PlayerId = 0x5000_0001;

    private const uint FirstCreatureId = 0x8000_1000;
    private const float CylinderRadius = 0.48f, CylinderHeight = 1.835f;
    // The player's circle (landblock 0xA9B4, away from the door at (100, 100)).
    private static readonly Vector3 Centre = new(70f, 66f, 0f);
    private const float CircleRadius = 6f, PlayerSpeed = 2.5f;
    /// <summary>Server ticks per second (every creature steps every tick).</summary>
    public const int Rate = 30;

    private readonly PhysicsWorld _world;
    private readonly PhysicsEngine[] _engines;
    private readonly MoverDescription[] _movers;
    private readonly MoverState[] _states;
    private readonly BodyState[] _bodies;
    private readonly ObjectMotion[] _motions;
    // Where each creature is registered (a creature that did not move is not moved in the registry).
    private readonly Position[] _registered;
    private readonly TwoThreads? _worker;
    private readonly Action<int>? _stepChunks;
    private Position _player;
    private ulong _hash = 14695981039346656037UL;

    /// <summary>Sets up <paramref name="n"/> creatures standing on a jittered ring 15–60 m around the player's circle.</summary>
    public Crowd(int n, int threads)
    {
        if (n < 1 || n > 5000) throw new ArgumentOutOfRangeException(nameof(n), n, "1 to 5,000 creatures");
        if (threads < 1 || threads > 2) throw new ArgumentOutOfRangeException(nameof(threads), threads, "1 or 2 threads");
        _world = SceneLibrary.Load("door").World;
        // A few trees and rocks about the field, fixed seed.
        var rng = new Random(33);
        var tree = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 6f)], Height = 6f, Radius = 0.4f };
        var rock = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, 0.3f), 0.8f)], Height = 1.1f, Radius = 0.8f };
        for (int i = 0; i < 60; i++)
        {
            Vector3 p;
            do p = new Vector3(4 + 184 * rng.NextSingle(), 4 + 184 * rng.NextSingle(), 0);
            while ((p.X > 92 && p.X < 122 && p.Y > 92 && p.Y < 122) || Vector3.Distance(p, Centre) < 14f);
            _world.Objects.Register(0x7300_0000u + (uint)i, (i & 1) == 0 ? tree : rock, At(p), 1f, PhysicsState.Static);
        }
        var cylinder = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, CylinderRadius, CylinderHeight)], Height = CylinderHeight, Radius = CylinderRadius };
        _player = At(PlayerAt(0));
        _world.Objects.Register(PlayerId, cylinder, _player, 1f, PhysicsState.Gravity, ShadowFlags.IsPlayer);
        _engines = new PhysicsEngine[threads];
        for (int t = 0; t < threads; t++) _engines[t] = new PhysicsEngine(_world);
        if (threads == 2)
        {
            _worker = new TwoThreads();
            _stepChunks = t => StepChunks(_engines[t]);
        }
        _movers = new MoverDescription[n];
        _states = new MoverState[n];
        _bodies = new BodyState[n];
        _motions = new ObjectMotion[n];
        _registered = new Position[n];
        var table = MotionTables.Humanoid();
        var template = MoverDescription.Player(FirstCreatureId).With(physicsState: PhysicsState.Gravity, flags: ObjectInfoState.None);
        for (int i = 0; i < n; i++)
        {
            uint id = FirstCreatureId + (uint)i;
            _movers[i] = template.With(objectId: id);
            var p = StartPoint(i, n);
            _states[i] = MoverState.OnFloor(At(p), 0f);
            _bodies[i] = BodyState.Creature();
            var motion = new ObjectMotion(table, new RetailSkills(200, 200));
            motion.SetCylinder(CylinderRadius, CylinderHeight);
            motion.MoveToProgressRule = MoveToProgressRule.GiveUp;
            motion.Place(_movers[i], _states[i], ref _bodies[i]);
            _motions[i] = motion;
            _world.Objects.Register(id, cylinder, _states[i].Position, 1f, PhysicsState.Gravity, ShadowFlags.IsCreature);
            _registered[i] = _states[i].Position;
        }
    }

    /// <summary>Creatures.</summary>
    public int Count => _states.Length;

    /// <summary>Ticks run so far.</summary>
    public int Ticks { get; private set; }

    /// <summary>FNV-1a over every creature's position (cell, origin, orientation) after every tick, and the player's.</summary>
    public ulong Fingerprint => _hash;

    /// <summary>Creatures within <paramref name="metres"/> of the player, now.</summary>
    public int NearPlayer(float metres)
    {
        int near = 0;
        foreach (var s in _states)
            if (Vector3.DistanceSquared(s.Position.Origin, _player.Origin) < metres * metres)
                near++;
        return near;
    }

    /// <summary>One server tick of 1/30 s.</summary>
    public void Tick()
    {
        Ticks++;
        // The player's client reported a new position: the server moves it in the registry.
        _player = At(PlayerAt(Ticks));
        _world.Objects.Move(PlayerId, _player);
        long t0 = Stopwatch.GetTimestamp();
        if (_worker is null)
            StepRange(_engines[0], 0, _states.Length);
        else
        {
            // Both threads take chunks of creatures in turn from one counter until none is left.
            _next = 0;
            _worker.Run(_stepChunks!);
        }
        StepMs = Stopwatch.GetElapsedTime(t0).TotalMilliseconds;
        // One writer: the creatures that moved, in creature order (the order the cells' lists take).
        for (int i = 0; i < _states.Length; i++)
        {
            var p = _states[i].Position;
            if (!SameBits(p, _registered[i]))
            {
                _world.Objects.Move(_movers[i].ObjectId, p);
                _registered[i] = p;
            }
            Add(p);
        }
        Add(_player);
    }

    /// <summary>The last tick's step phase (both threads, until both are done), milliseconds.</summary>
    public double StepMs { get; private set; }

    /// <summary>With two threads, how long each thread stepped creatures in the last tick, milliseconds.</summary>
    public (double Caller, double Second) Busy => _worker?.Busy ?? (StepMs, 0);

    /// <summary>Stops the second thread.</summary>
    public void Dispose() => _worker?.Dispose();

    private const int Chunk = 8;
    private int _next;

    private void StepChunks(PhysicsEngine engine)
    {
        int n = _states.Length;
        for (int from = Interlocked.Add(ref _next, Chunk) - Chunk; from < n; from = Interlocked.Add(ref _next, Chunk) - Chunk)
            StepRange(engine, from, Math.Min(n, from + Chunk));
    }

    private void StepRange(PhysicsEngine engine, int from, int to)
    {
        for (int i = from; i < to; i++)
        {
            Order(i);
            var r = engine.Step(_movers[i], _states[i], _bodies[i], _motions[i], 1.0 / Rate);
            _states[i] = r.Next;
            _bodies[i] = r.Body;
        }
    }

    /// <summary>
    /// The creature's AI: while its MoveTo runs, the player's position every 10 ticks (retail's TargetManager sends
    /// such updates); once the move has ended (arrived or gave up), a new MoveTo toward the player when it is
    /// more than 3 m away.
    /// </summary>
    private void Order(int i)
    {
        var motion = _motions[i];
        if (motion.MoveToStatus != MoveToStatus.Idle && motion.MoveToStatus != MoveToStatus.Ended)
        {
            if (Ticks % 10 == i % 10)
                motion.UpdateMoveToTarget(PlayerId, _player, _movers[i], _states[i], _bodies[i]);
            return;
        }
        if (Vector3.DistanceSquared(_states[i].Position.Origin, _player.Origin) <= 9f)
            return;
        motion.MoveToObject(PlayerId, CylinderRadius, CylinderHeight, MoveToParameters.Default, _movers[i], _states[i], _bodies[i]);
        motion.UpdateMoveToTarget(PlayerId, _player, _movers[i], _states[i], _bodies[i]);
    }

    private static Vector3 PlayerAt(int tick)
    {
        float a = tick * (PlayerSpeed / Rate / CircleRadius);
        return Centre + new Vector3(CircleRadius * MathF.Cos(a), CircleRadius * MathF.Sin(a), 0);
    }

    /// <summary>Creature i of n: a jittered spiral 15 to 60 m from the circle's centre (fixed).</summary>
    private static Vector3 StartPoint(int i, int n)
    {
        float f = (i + 0.5f) / n;
        float r = MathF.Sqrt(15f * 15f + f * (60f * 60f - 15f * 15f)) + 0.8f * (Hash(i, 1) - 0.5f);
        float a = i * 2.3999631f + 0.2f * Hash(i, 2);
        var p = Centre + new Vector3(r * MathF.Cos(a), r * MathF.Sin(a), 0);
        return Vector3.Clamp(p, new Vector3(3f, 3f, 0), new Vector3(189f, 189f, 0));
    }

    private static bool SameBits(in Position a, in Position b) =>
        a.CellId == b.CellId && Bits(a.Frame.Origin) == Bits(b.Frame.Origin) && Bits(a.Frame.Orientation) == Bits(b.Frame.Orientation);

    private static (uint, uint, uint) Bits(Vector3 v) =>
        (BitConverter.SingleToUInt32Bits(v.X), BitConverter.SingleToUInt32Bits(v.Y), BitConverter.SingleToUInt32Bits(v.Z));

    private static (uint, uint, uint, uint) Bits(Quaternion q) =>
        (BitConverter.SingleToUInt32Bits(q.X), BitConverter.SingleToUInt32Bits(q.Y), BitConverter.SingleToUInt32Bits(q.Z), BitConverter.SingleToUInt32Bits(q.W));

    private static Position At(Vector3 p) => new(LandDefs.LandCellAt(0xA9B4, p), p);

    private void Add(in Position p)
    {
        Add(p.CellId);
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Origin.X));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Origin.Y));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Origin.Z));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Orientation.W));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Orientation.X));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Orientation.Y));
        Add(BitConverter.SingleToUInt32Bits(p.Frame.Orientation.Z));
    }

    private void Add(uint x)
    {
        ulong h = _hash;
        for (int i = 0; i < 4; i++)
        {
            h ^= (byte)(x >> (8 * i));
            h *= 1099511628211UL;
        }
        _hash = h;
    }

    /// <summary>A fixed pseudo-random number in [0, 1) from two integers.</summary>
    private static float Hash(int a, int b)
    {
        uint h = (uint)a * 0x9E3779B1u ^ (uint)b * 0x85EBCA77u;
        h ^= h >> 15; h *= 0x2C1B3C6Du; h ^= h >> 12; h *= 0x297A2D39u; h ^= h >> 15;
        return (h >> 8) / 16777216f;
    }
}
