using System.Threading;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// Streaming from two threads at once (a host's loader thread and another) is misuse the world detects, as the
/// registry detects a second writer: the call that meets the other is refused with an InvalidOperationException
/// before it changes anything, and the world stays usable. Before, two threads left every later load throwing
/// IndexOutOfRangeException.
/// </summary>
public class StreamingConcurrencyTests
{
    private const string Expected = "another thread is loading or unloading a landblock or modifying the registry; the world takes one writer at a time. This call changed nothing.";
    private static readonly PhysicsSetup Ball = new() { Spheres = [new Sphere(Vector3.Zero, 0.4f)] };

    private sealed class Streamer(uint landblock)
    {
        public bool Loaded;
        public int Refused, Done;
        public readonly List<string> Unexpected = new();

        public void Run(PhysicsWorld world, Barrier start, int rounds)
        {
            start.SignalAndWait();
            for (int i = 0; i < rounds; i++)
            {
                try
                {
                    if (Loaded)
                        world.UnloadLandblock(landblock);
                    else
                        world.LoadLandblock(Terrain.Flat(landblock, 0f));
                    Loaded = !Loaded;
                    Done++;
                }
                catch (InvalidOperationException e) when (e.Message.EndsWith(Expected, StringComparison.Ordinal))
                {
                    Refused++;
                }
                catch (Exception e)
                {
                    Unexpected.Add($"round {i}: {e.GetType().Name}: {e.Message}");
                    return;
                }
            }
        }
    }

    [Fact]
    public void TwoThreadsStreaming_AreRefusedCleanly_AndTheWorldStaysUsable()
    {
        var world = new PhysicsWorld();
        var a = new Streamer(0xA9B4);
        var b = new Streamer(0x1020);
        using var start = new Barrier(2);
        var ta = new Thread(() => a.Run(world, start, 4000)) { IsBackground = true };
        var tb = new Thread(() => b.Run(world, start, 4000)) { IsBackground = true };
        ta.Start();
        tb.Start();
        Assert.True(ta.Join(TimeSpan.FromSeconds(60)) && tb.Join(TimeSpan.FromSeconds(60)), "the streaming threads did not finish");
        Assert.Empty(a.Unexpected);
        Assert.Empty(b.Unexpected);
        // Each thread's refused calls changed nothing: the world holds exactly what each believes it loaded.
        Assert.Equal(a.Loaded, world.Cells.HasLandblock(0xA9B4));
        Assert.Equal(b.Loaded, world.Cells.HasLandblock(0x1020));
        Console.WriteLine($"streaming from two threads: {a.Done + b.Done} calls done, {a.Refused + b.Refused} refused");

        // Usable: a third landblock loads, takes an object, a move is resolved in it, and it unloads.
        world.LoadLandblock(Terrain.Flat(0x3040, 0f));
        var at = new Position(0x30400001, new Vector3(5, 5, 0.4f));
        world.Objects.Register(7, Ball, at);
        Assert.Equal([0x30400001u], world.Objects.CellsOf(7));
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(new Position(0x30400001, new Vector3(20, 5, 0)), 0f);
        var target = state.Position;
        target.Frame.Origin += new Vector3(0, 1, 0);
        Assert.True(engine.Resolve(mover, state, target).Succeeded);
        world.UnloadLandblock(0x3040);
        Assert.False(world.Objects.Contains(7));
        // And the two streamed landblocks go on loading and unloading from one thread.
        foreach (uint lb in new uint[] { 0xA9B4, 0x1020 })
        {
            if (world.Cells.HasLandblock(lb))
                world.UnloadLandblock(lb);
            world.LoadLandblock(Terrain.Flat(lb, 0f));
            world.UnloadLandblock(lb);
        }
    }

    [Fact]
    public void ARegistryWriterMeetingALoad_AndALoadMeetingARegistryWriter_AreRefused()
    {
        // Deterministic half of the rule: while the writer's flag is held, streaming is refused, changing nothing.
        var world = new PhysicsWorld();
        world.Objects.BeginStreaming("LoadLandblock");
        try
        {
            var ex = Assert.Throws<InvalidOperationException>(() => world.LoadLandblock(Terrain.Flat(0xA9B4, 0f)));
            Assert.Equal($"PhysicsWorld.LoadLandblock: {Expected}", ex.Message);
            ex = Assert.Throws<InvalidOperationException>(() => world.UnloadLandblock(0xA9B4));
            Assert.StartsWith("PhysicsWorld.UnloadLandblock: another thread", ex.Message);
            ex = Assert.Throws<InvalidOperationException>(() => world.Objects.Register(1, Ball, new Position(0xA9B40001, new Vector3(5, 5, 0.4f))));
            Assert.StartsWith("ShadowObjectRegistry.Register: another thread is modifying the registry", ex.Message);
        }
        finally
        {
            world.Objects.EndStreaming();
        }
        Assert.False(world.Cells.HasLandblock(0xA9B4));
        world.LoadLandblock(Terrain.Flat(0xA9B4, 0f));
        Assert.True(world.Cells.HasLandblock(0xA9B4));
    }
}
