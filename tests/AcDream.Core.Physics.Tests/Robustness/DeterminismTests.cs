using System.Threading.Tasks;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Bit-identical trajectories run to run and across threads (one engine per thread over a shared world).
/// Comparison with committed data, per scene and per area, is in <see cref="RecordedDeterminismTests"/>.
/// </summary>
public class DeterminismTests
{
    public const int HashSeed = 777;

    private sealed class Fnv
    {
        public ulong Value = 14695981039346656037UL;
        public void Add(uint x)
        {
            for (int i = 0; i < 4; i++)
            {
                Value ^= (byte)(x >> (8 * i));
                Value *= 1099511628211UL;
            }
        }
        public void Add(float f) => Add(BitConverter.SingleToUInt32Bits(f));
        public void Add(Vector3 v) { Add(v.X); Add(v.Y); Add(v.Z); }
        public void Add(Quaternion q) { Add(q.X); Add(q.Y); Add(q.Z); Add(q.W); }
        public void Add(in MoveResult r)
        {
            var n = r.Next;
            Add(n.Position.CellId);
            Add(n.Position.Frame.Origin);
            Add(n.Position.Frame.Orientation);
            Add((uint)((r.Succeeded ? 1 : 0) | (n.Contact ? 2 : 0) | (n.OnWalkable ? 4 : 0) | (n.SlidingNormalValid ? 8 : 0)
                | (r.CollisionNormalValid ? 16 : 0) | (r.CollidedWithEnvironment ? 32 : 0)));
            Add(n.ContactPlane.Normal);
            Add(n.ContactPlane.D);
            Add(n.SlidingNormal);
            Add(r.CollisionNormal);
            foreach (uint id in r.CollidedObjects.Span)
                Add(id);
        }
    }

    /// <summary>The trajectory of one fuzz case, hashed.</summary>
    internal static ulong CaseHash(SceneFuzzer.Case c, PhysicsEngine engine)
    {
        var h = new Fnv();
        var state = c.Start;
        foreach (var offset in c.Targets)
        {
            var r = engine.Resolve(c.Mover, state, SceneFuzzer.TargetFor(state, offset));
            h.Add(r);
            state = r.Next;
        }
        return h.Value;
    }

    internal static ulong SuiteHash(int seed, int cases)
    {
        var h = new Fnv();
        for (int i = 0; i < cases; i++)
        {
            var c = SceneFuzzer.Make(FuzzTests.CaseSeed(seed, i));
            ulong x = CaseHash(c, new PhysicsEngine(c.World));
            h.Add((uint)x);
            h.Add((uint)(x >> 32));
        }
        return h.Value;
    }

    [Fact]
    public void SameSceneAndMotion_GiveBitIdenticalTrajectories_RunToRun()
    {
        ulong first = SuiteHash(HashSeed, 100), second = SuiteHash(HashSeed, 100);
        Assert.Equal(first, second);
        // One engine reused across cases gives what fresh engines give (nothing leaks between calls).
        for (int i = 0; i < 50; i++)
        {
            var c = SceneFuzzer.Make(FuzzTests.CaseSeed(HashSeed, i));
            var reused = new PhysicsEngine(c.World);
            CaseHash(SceneFuzzer.Make(FuzzTests.CaseSeed(HashSeed, i + 1000)), new PhysicsEngine(c.World)); // warm another engine: irrelevant
            CaseHash(c, reused);
            Assert.Equal(CaseHash(c, new PhysicsEngine(c.World)), CaseHash(c, reused));
        }
    }

    /// <summary>
    /// Every move on an engine that has just resolved other moves, of another mover, gives bit for bit what a
    /// new engine gives for that move alone: none of the work the engine keeps between calls (and none of
    /// the path's fields it does not clear) can be seen in a result.
    /// </summary>
    [Fact]
    public void EachMove_OnABusyEngine_GivesWhatANewEngineGives()
    {
        var other = MoverDescription.Player(0x5000_0FFF);
        for (int i = 0; i < 40; i++)
        {
            var c = SceneFuzzer.Make(FuzzTests.CaseSeed(HashSeed, i));
            var busy = new PhysicsEngine(c.World);
            var state = c.Start;
            int frame = 0;
            foreach (var offset in c.Targets)
            {
                var target = SceneFuzzer.TargetFor(state, offset);
                var alone = new Fnv();
                var fresh = new PhysicsEngine(c.World).Resolve(c.Mover, state, target);
                alone.Add(fresh);
                var shared = new Fnv();
                var r = busy.Resolve(c.Mover, state, target);
                shared.Add(r);
                Assert.True(alone.Value == shared.Value, $"case {i}, frame {frame}: a busy engine's result differs from a new engine's");
                // Before the next frame, the busy engine moves another mover back towards this frame's start.
                try { busy.Resolve(other, r.Next, state.Position); }
                catch (ArgumentException) { /* a start the other mover may not take: nothing was changed */ }
                state = r.Next;
                frame++;
            }
        }
    }

    [Fact]
    public void ParallelMovers_OnASharedWorld_MatchTheSequentialRun()
    {
        // One world shared by every thread; each mover is one fuzz case's mover and motion, in the
        // richest scene of the first hundred cases.
        var scene = Enumerable.Range(0, 100).Select(i => SceneFuzzer.Make(FuzzTests.CaseSeed(HashSeed, i))).MaxBy(c => c.Solids.Count)!;
        var movers = Enumerable.Range(0, 64).Select(i =>
        {
            var m = SceneFuzzer.Make(FuzzTests.CaseSeed(HashSeed + 1, i));
            var start = m.Start;
            start.Position.Frame.Origin.Z += 3f; // above any terrain of the shared scene
            start.Contact = false; start.OnWalkable = false; start.ContactPlaneCellId = 0;
            return new SceneFuzzer.Case { Seed = m.Seed, World = scene.World, Mover = m.Mover, Start = start, Targets = m.Targets };
        }).ToArray();

        var sequential = movers.Select(m => CaseHash(m, new PhysicsEngine(scene.World))).ToArray();
        for (int round = 0; round < 4; round++)
        {
            var parallel = new ulong[movers.Length];
            var engines = new System.Threading.ThreadLocal<PhysicsEngine>(() => new PhysicsEngine(scene.World));
            Parallel.For(0, movers.Length, new ParallelOptions { MaxDegreeOfParallelism = 8 }, i => parallel[i] = CaseHash(movers[i], engines.Value!));
            Assert.Equal(sequential, parallel);
        }
    }
}
