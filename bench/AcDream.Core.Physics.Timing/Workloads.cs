using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// One timed workload: a fixed sequence of frames resolved by one engine. <see cref="Run"/> resolves the
/// whole sequence once and returns a value that depends on every frame (so nothing can be optimized away).
/// </summary>
internal sealed class Workload
{
    private readonly PhysicsEngine _engine;
    private readonly MoverDescription _player;
    private MoverState _start;
    private readonly Vector3 _step;
    // A body workload (Name starts "body-"): each frame is one PhysicsEngine.Step of _elapsed seconds with
    // _step as the desired velocity, the body state carried from step to step; null for a Resolve workload.
    private readonly BodyState? _body;
    private readonly double _elapsed;
    // A query workload (Name starts "q-"): one call of a world query per frame; null otherwise.
    private readonly Func<float>? _query;

    private Workload(string name, string description, PhysicsWorld world, Func<float> query)
        : this(name, description, world, default, Vector3.Zero, 1)
    {
        _query = query;
    }

    private Workload(string name, string description, PhysicsWorld world, MoverState start, BodyState body, Vector3 desired, double elapsed,
        int frames)
        : this(name, description, world, start, desired, frames)
    {
        _body = body;
        _elapsed = elapsed;
    }

    private Workload(string name, string description, PhysicsWorld world, MoverState start, Vector3 step, int frames, int skip)
        : this(name, description, world, start, step, frames)
    {
        for (int i = 0; i < skip; i++) { var t = _start.Position; t.Frame.Origin += _step; _start = _engine.Resolve(_player, _start, t).Next; }
    }
    private Workload(string name, string description, PhysicsWorld world, MoverState start, Vector3 step, int frames)
    {
        Name = name;
        Description = description;
        _engine = new PhysicsEngine(world);
        _player = MoverDescription.Player();
        _start = start;
        _step = step;
        Frames = frames;
    }

    /// <summary>The short name used on the command line and in reports.</summary>
    public string Name { get; }

    /// <summary>What the workload walks.</summary>
    public string Description { get; }

    /// <summary>Transitions per run.</summary>
    public int Frames { get; }

    /// <summary>Resolves every frame once; returns the final X + Y (a data dependency on every frame).</summary>
    public float Run()
    {
        if (_query is not null)
            return _query();
        if (_body is { } body)
            return RunBody(body);
        var state = _start;
        for (int i = 0; i < Frames; i++)
        {
            var target = state.Position;
            target.Frame.Origin += _step;
            state = _engine.Resolve(_player, state, target).Next;
        }
        return state.Position.Frame.Origin.X + state.Position.Frame.Origin.Y;
    }

    private float RunBody(BodyState body)
    {
        var state = _start;
        for (int i = 0; i < Frames; i++)
        {
            var r = _engine.Step(_player, state, body, _elapsed, _step);
            state = r.Next;
            body = r.Body;
        }
        return state.Position.Frame.Origin.X + state.Position.Frame.Origin.Y;
    }

    /// <summary>Blocked frames of one run (the mover did not move), for the description.</summary>
    public int BlockedFrames()
    {
        if (_body is not null || _query is not null)
            return 0;
        var state = _start;
        int blocked = 0;
        for (int i = 0; i < Frames; i++)
        {
            var target = state.Position;
            target.Frame.Origin += _step;
            var next = _engine.Resolve(_player, state, target).Next;
            if (next.Position.Frame.Origin == state.Position.Frame.Origin)
                blocked++;
            state = next;
        }
        return blocked;
    }

    // The door of the built-in "door" scene: slab front face at y = 99.991 (landblock 0xA9B4), so the
    // player's spheres (r 0.48) touch it head-on with the centre at y = 99.511.
    private const float FrontStop = 100f - 0.009f - 0.48f;

    // 4 m/s at 30 Hz, heading 20° from the face's tangent into the face (+Y), so every frame presses into it.
    private static readonly Vector3 FaceSlideStep = new(4f / 30f * 0.9396926f, 4f / 30f * 0.34202015f, 0);

    /// <summary>Every workload, in report order.</summary>
    public static IReadOnlyList<Workload> All() =>
    [
        new("head-on", "head-on walk at 2 m/s, 30 Hz: 40 frames from 0.2 m short of the face", DoorWorld(0, 0),
            Standing(100f, FrontStop - 0.2f), new Vector3(0, 2f / 30f, 0), 40),
        new("slide-ne", "45° NE slide along the face: 30 frames of 0.1 m from (99.6, 99.0)", DoorWorld(0, 0),
            Standing(99.6f, 99.0f), new Vector3(0.0707f, 0.0707f, 0), 30),
        new("refused", "x", DoorWorld(0, 0), Standing(100f, FrontStop - 0.2f), new Vector3(0, 2f / 30f, 0), 37, 3),
        new("free", "x", DoorWorld(0, 0), Standing(100f, FrontStop - 0.2f), new Vector3(0, 2f / 30f, 0), 2),
        new("door", "the door transition: one frame of 0.1 m into the face from 0.05 m short", DoorWorld(0, 0),
            Standing(100f, FrontStop - 0.05f), new Vector3(0, 0.1f, 0), 1),
        new("door+100", "the door transition with 100 props in the door's cell (4 m or more from the door)", DoorWorld(100, 0),
            Standing(100f, FrontStop - 0.05f), new Vector3(0, 0.1f, 0), 1),
        new("door+1000", "the door transition with 1,000 props in the door's cell (4 m or more from the door)", DoorWorld(1000, 0),
            Standing(100f, FrontStop - 0.05f), new Vector3(0, 0.1f, 0), 1),
        new("face-slide", "the player sliding along the face at 4 m/s, 30 Hz: 8 frames heading 20° into it from (99.5, touching)",
            DoorWorld(0, 0), Standing(99.5f, FrontStop), FaceSlideStep, 8),
        new("slide-ne+100", "the NE slide with 100 props in the door's cell", DoorWorld(100, 0),
            Standing(99.6f, 99.0f), new Vector3(0.0707f, 0.0707f, 0), 30),
        new("body-slide", "the face slide as a body step: 8 steps of 1/30 s at 4 m/s heading 20° into the face",
            DoorWorld(0, 0), Standing(99.5f, FrontStop), BodyState.Creature(), FaceSlideStep * 30f, 1.0 / 30.0, 8),
        new("body-walk", "a body walking 3 m/s in the open: 30 steps of 1/30 s (one quantum each)",
            DoorWorld(0, 0), Standing(60f, 80f), BodyState.Creature(), new Vector3(3f, 0, 0), 1.0 / 30.0, 30),
        new("body-5hz", "a creature at the 5 Hz rate: 10 steps of 0.2 s (one quantum each) at 2.5 m/s in the open",
            DoorWorld(0, 0), Standing(60f, 80f), BodyState.Creature(), new Vector3(0, 2.5f, 0), 0.2, 10),
        new("body-3q", "a body step of 0.5 s (three quanta: 0.2, 0.2, 0.1 s) at 2.5 m/s in the open: 6 steps",
            DoorWorld(0, 0), Standing(60f, 80f), BodyState.Creature(), new Vector3(2.5f, 0, 0), 0.5, 6),
        .. QueryWorkloads(),
    ];

    /// <summary>
    /// The queries bench's calls on the built-in cottage (a room behind a doorway, the building's shell, the door
    /// in the doorway), one call per run, and the same run's player transition (<c>q-resolve</c>) the issue
    /// measures them against.
    /// </summary>
    private static IEnumerable<Workload> QueryWorkloads()
    {
        const uint land = 0xA9B40025, room = 0xA9B40100;
        var world = SceneLibrary.Load("cottage").World;
        var query = new Queries.WorldQuery(world);
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var found = new Queries.ObjectOverlap[16];
        static Position At(uint cell, float x, float y, float z) => new(cell, new Vector3(x, y, z));
        var walker = MoverState.OnFloor(At(land, 100, 97, 0), 0f);
        return
        [
            new("q-sphere", "SphereCast: 0.3 m, 6 m through the doorway, hits the door", world,
                () => query.SphereCast(At(land, 100, 97, 1), new Vector3(100, 103, 1), 0.3f, out var a) ? a.Fraction : -1f),
            new("q-ray", "RayCast: a pick along an 8.5 m diagonal", world,
                () => query.RayCast(At(land, 97, 97, 1.5f), new Vector3(103, 103, 1.5f), out var b) ? b.Fraction : -1f),
            new("q-floor-in", "TryFindFloor indoors (the room's floor)", world,
                () => query.TryFindFloor(At(land, 100, 102, 2), 5, out var c) ? c.Point.Z : -1f),
            new("q-floor-out", "TryFindFloor outdoors (terrain)", world,
                () => query.TryFindFloor(At(land, 95, 95, 2), 5, out var d) ? d.Point.Z : -1f),
            new("q-overlap", "OverlapSphere: 1 m at the door", world,
                () => query.OverlapSphere(At(land, 100, 99.5f, 1), 1f, found)),
            new("q-camera", "CameraArm: 5 m in the room, stops at the wall", world,
                () => query.CameraArm(At(room, 100, 101, 1.5f), new Vector3(100, 106, 1.5f)).Camera.Origin.Y),
            new("q-resolve", "Resolve: the player's 0.1 m step outside the cottage, for scale", world,
                () => engine.Resolve(player, walker, At(land, 100, 97.1f, 0)).Position.Origin.Y),
        ];
    }

    /// <summary>
    /// The body steps' fingerprint: FNV-1a over every field of every step's result (state, body, quanta,
    /// transitions) on the <see cref="Fingerprint"/> grid's approaches walked as body steps of 1/30 s and
    /// of 0.5 s (three quanta), in the same world.
    /// </summary>
    public static ulong BodyFingerprint()
    {
        var engine = new PhysicsEngine(DoorWorld(100, 300));
        var player = MoverDescription.Player();
        var h = new Fnv();
        foreach (double elapsed in new[] { 1.0 / 30.0, 0.5 })
            foreach (float lateral in new[] { -0.7f, -0.2f, 0f, 0.45f })
                for (int heading = -85; heading <= 85; heading += 10)
                    foreach (float speed in new[] { 1f, 4f, 10f })
                    {
                        float a = heading * MathF.PI / 180f;
                        var dir = new Vector3(MathF.Sin(a), MathF.Cos(a), 0);
                        var state = Standing(100f + lateral - 2f * dir.X, FrontStop - 2f * dir.Y);
                        var body = BodyState.Creature();
                        for (int f = 0; f < 30; f++)
                        {
                            var r = engine.Step(player, state, body, elapsed, dir * speed);
                            h.AddResult(r.Move);
                            h.AddV(r.Body.Velocity);
                            h.AddV(r.Body.Acceleration);
                            h.Add((uint)r.Body.StationaryFall);
                            h.Add((uint)(r.Quanta | (TransitionsOf(r) << 8)));
                            state = r.Next;
                            body = r.Body;
                        }
                    }
        return h.Value;
    }

    // BodyStepResult.Transitions came after the speed issue's baseline (93d4ee3). It is read by reflection so that
    // this driver still builds against such a commit (bench/compare.sh); there it hashes as 0, so the body
    // fingerprints of the two sides differ against such a base while the transition fingerprint still compares.
    private static readonly System.Reflection.PropertyInfo? TransitionsProperty = typeof(BodyStepResult).GetProperty("Transitions");

    private static int TransitionsOf(BodyStepResult r) => TransitionsProperty is { } p ? (int)p.GetValue(r)! : 0;

    /// <summary>
    /// A fingerprint of the engine's results: FNV-1a over every field of every frame's result on a grid of
    /// approaches to the door (headings −85°..85° every 5°, seven lateral offsets, 1–50 m/s at 30 Hz, 60
    /// frames each, so the fast ones run on through the props) in the door world with 100 props in the
    /// door's cell and 300 elsewhere. Equal fingerprints: bit-identical results on all of them.
    /// </summary>
    public static ulong Fingerprint()
    {
        var engine = new PhysicsEngine(DoorWorld(100, 300));
        var player = MoverDescription.Player();
        var h = new Fnv();
        foreach (float lateral in new[] { -0.7f, -0.45f, -0.2f, 0f, 0.2f, 0.45f, 0.7f })
            for (int heading = -85; heading <= 85; heading += 5)
                foreach (float speed in new[] { 1f, 2f, 5f, 10f, 20f, 50f })
                {
                    float a = heading * MathF.PI / 180f;
                    var dir = new Vector3(MathF.Sin(a), MathF.Cos(a), 0);
                    var state = Standing(100f + lateral - 2f * dir.X, FrontStop - 2f * dir.Y);
                    var step = dir * (speed / 30f);
                    for (int f = 0; f < 60; f++)
                    {
                        var target = state.Position;
                        target.Frame.Origin += step;
                        var r = engine.Resolve(player, state, target);
                        h.AddResult(r);
                        var n = r.Next;
                        state = n;
                    }
                }
        return h.Value;
    }

    /// <summary>FNV-1a over the bytes of the values added, for the fingerprints.</summary>
    private sealed class Fnv
    {
        public ulong Value { get; private set; } = 14695981039346656037UL;

        public void Add(uint x)
        {
            ulong h = Value;
            for (int i = 0; i < 4; i++)
            {
                h ^= (byte)(x >> (8 * i));
                h *= 1099511628211UL;
            }
            Value = h;
        }

        public void AddF(float f) => Add(BitConverter.SingleToUInt32Bits(f));

        public void AddV(Vector3 v)
        {
            AddF(v.X);
            AddF(v.Y);
            AddF(v.Z);
        }

        /// <summary>Every field of a move's result, in a fixed order.</summary>
        public void AddResult(in MoveResult r)
        {
            var n = r.Next;
            Add(n.Position.CellId);
            AddV(n.Position.Frame.Origin);
            AddF(n.Position.Frame.Orientation.W);
            AddF(n.Position.Frame.Orientation.Z);
            Add((uint)((r.Succeeded ? 1 : 0) | (n.Contact ? 2 : 0) | (n.OnWalkable ? 4 : 0) | (n.SlidingNormalValid ? 8 : 0)
                | (r.CollisionNormalValid ? 16 : 0) | (r.CollidedWithEnvironment ? 32 : 0) | (r.VelocityKilled ? 64 : 0)));
            AddV(n.ContactPlane.Normal);
            AddF(n.ContactPlane.D);
            Add(n.ContactPlaneCellId);
            AddV(n.SlidingNormal);
            AddV(r.CollisionNormal);
            Add(r.LastCollidedObject);
            foreach (uint id in r.CollidedObjects.Span)
                Add(id);
        }
    }

    private static MoverState Standing(float x, float y)
    {
        var p = new Vector3(x, y, 0);
        return MoverState.OnFloor(new Position(LandDefs.LandCellAt(0xA9B4, p), p), 0f);
    }

    /// <summary>
    /// The built-in door scene's world (flat landblock 0xA9B4, the door at (100, 100, 0)) with props:
    /// <paramref name="near"/> in the door's 24 m cell at least 4 m from the door, <paramref name="far"/>
    /// in other cells. Props alternate between a barrel (a cylinder) and a rock (a sphere); fixed seed.
    /// </summary>
    private static PhysicsWorld DoorWorld(int near, int far)
    {
        var world = SceneLibrary.Load("door").World;
        var rng = new Random(1234);
        var barrel = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 1.0f)], Height = 1f, Radius = 0.4f };
        var rock = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, 0.3f), 0.3f)], Height = 0.6f, Radius = 0.3f };
        for (int i = 0; i < near + far; i++)
        {
            Vector3 p;
            if (i < near)
            {
                do p = new Vector3(97 + 22 * rng.NextSingle(), 97 + 22 * rng.NextSingle(), 0);
                while (Vector2.Distance(new Vector2(p.X, p.Y), new Vector2(100, 100)) < 4f);
            }
            else
            {
                do p = new Vector3(1 + 190 * rng.NextSingle(), 1 + 190 * rng.NextSingle(), 0);
                while (p.X > 94 && p.X < 122 && p.Y > 94 && p.Y < 122);
            }
            world.Objects.Register(0x7100_0000u + (uint)i, (i & 1) == 0 ? barrel : rock,
                new Position(LandDefs.LandCellAt(0xA9B4, p), p), 1f, PhysicsState.ReportCollisions);
        }
        return world;
    }
}
