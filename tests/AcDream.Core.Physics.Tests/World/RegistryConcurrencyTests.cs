using System.Diagnostics;
using System.Threading;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// Two threads writing to one registry (unsupported: one writer at a time) are detected: the call that
/// meets the other gets a clear <see cref="InvalidOperationException"/> and changes nothing, and the
/// registry stays consistent and usable. Before this, such writers left it broken for good (a later
/// Register threw IndexOutOfRangeException).
/// </summary>
public class RegistryConcurrencyTests
{
    private const string Expected = "another thread is modifying the registry; it takes one writer at a time. This call changed nothing.";
    private static readonly PhysicsSetup Ball = new() { Spheres = [new Sphere(Vector3.Zero, 0.4f)] };

    /// <summary>What one writer thread believes: its objects and where it last put them.</summary>
    private sealed class Writer(uint firstId, int seed)
    {
        public readonly Dictionary<uint, Position> Registered = new();
        public readonly List<string> Unexpected = new();
        public int Refused;
        private readonly Random _rng = new(seed);

        public void Run(ShadowObjectRegistry registry, Func<bool> done)
        {
            while (!done())
            {
                uint id = firstId + (uint)_rng.Next(40);
                var at = TestGeometry.At(2 + 188 * _rng.NextSingle(), 2 + 188 * _rng.NextSingle(), 0);
                try
                {
                    if (!Registered.ContainsKey(id))
                    {
                        registry.Register(id, Ball, at);
                        Registered[id] = at;
                    }
                    else if (_rng.Next(3) == 0)
                    {
                        Assert.True(registry.Unregister(id));
                        Registered.Remove(id);
                    }
                    else
                    {
                        registry.Move(id, at);
                        Registered[id] = at;
                    }
                }
                catch (InvalidOperationException e) when (e.Message.EndsWith(Expected, StringComparison.Ordinal))
                {
                    Refused++;
                }
                catch (Exception e)
                {
                    Unexpected.Add($"{e.GetType().Name}: {e.Message}");
                    if (Unexpected.Count > 5)
                        return;
                }
            }
        }
    }

    [Fact]
    public void TwoWriterThreads_GetAClearError_AndTheRegistryStaysConsistentAndUsable()
    {
        var world = TestGeometry.FlatWorld();
        var registry = world.Objects;
        var writers = new[] { new Writer(1000, 1), new Writer(2000, 2) };
        var clock = Stopwatch.StartNew();
        // Until both have met the other a few times (a collision needs one thread to be inside a write when
        // the other starts one), at most 20 s.
        bool Done() => clock.Elapsed.TotalSeconds > 20 || (writers[0].Refused >= 5 && writers[1].Refused >= 5);
        var threads = writers.Select(w => new Thread(() => w.Run(registry, Done))).ToArray();
        foreach (var t in threads)
            t.Start();
        foreach (var t in threads)
            t.Join();

        foreach (var w in writers)
            Assert.True(w.Unexpected.Count == 0, string.Join("\n", w.Unexpected));
        Assert.True(writers.Sum(w => w.Refused) > 0, $"no write was refused in {clock.Elapsed.TotalSeconds:F1} s: the threads never met");
        AssertConsistent(registry, writers.SelectMany(w => w.Registered).ToDictionary());

        // Usable afterwards: register, move and remove.
        var expected = writers.SelectMany(w => w.Registered).ToDictionary();
        registry.Register(5000, Ball, TestGeometry.At(50, 50, 0));
        registry.Move(5000, TestGeometry.At(150, 60, 0));
        expected[5000] = TestGeometry.At(150, 60, 0);
        AssertConsistent(registry, expected);
        Assert.True(registry.Unregister(5000));
        expected.Remove(5000);
        AssertConsistent(registry, expected);
    }

    /// <summary>
    /// The registry holds exactly the objects the writers believe it holds, each where they last put it,
    /// listed once in each of its cells, and every cell lists only such objects, each naming that cell.
    /// </summary>
    private static void AssertConsistent(ShadowObjectRegistry registry, Dictionary<uint, Position> expected)
    {
        Assert.Equal(expected.Count, registry.Count);
        foreach (var (id, at) in expected)
        {
            Assert.True(registry.Contains(id), $"object {id} is missing");
            Assert.Equal(at, registry.PositionOf(id));
            foreach (uint cell in registry.CellsOf(id))
            {
                var objects = registry.ObjectsInCell(cell);
                int listed = 0;
                for (int i = 0; i < objects.Count; i++)
                    listed += objects.RowsOf(i)[0].EntityId == id ? 1 : 0;
                Assert.True(listed == 1, $"object {id} is listed {listed} times in cell 0x{cell:X8}");
            }
        }
        for (uint index = 1; index <= 64; index++)
        {
            uint cell = (TestGeometry.Landblock << 16) | index;
            var objects = registry.ObjectsInCell(cell);
            for (int i = 0; i < objects.Count; i++)
            {
                uint id = objects.RowsOf(i)[0].EntityId;
                Assert.True(expected.ContainsKey(id), $"cell 0x{cell:X8} lists object {id}, which is not registered");
                Assert.Contains(cell, registry.CellsOf(id));
            }
        }
    }
}
