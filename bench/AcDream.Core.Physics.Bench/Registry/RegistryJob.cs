using System.Diagnostics;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Bench.Registry;

/// <summary>
/// <c>registry</c>: the cost of removing objects from one crowded cell (retail's swap-with-last, now
/// constant time per cell) and of moving an object, as the cell fills up. Prints one line per size.
/// </summary>
public static class RegistryJob
{
    /// <summary>Runs the job.</summary>
    public static int Run()
    {
        Console.WriteLine($"{"objects in the cell",20} {"unregister (ns each)",21} {"move (ns each)",15} {"move (B each)",13}");
        var ball = new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.3f)] };
        foreach (int n in new[] { 1_000, 10_000, 100_000, 200_000 })
        {
            var world = new PhysicsWorld();
            world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
            var here = new Position(0xA9B40001, new Vector3(12, 12, 0));
            for (uint id = 1; id <= n; id++)
                world.Objects.Register(id, ball, here);
            // Moves: the object leaves the cell and is appended again.
            const int moves = 20_000;
            for (int i = 0; i < 100; i++)
                world.Objects.Move((uint)(1 + i % n), here);
            long bytes = GC.GetAllocatedBytesForCurrentThread();
            var clock = Stopwatch.StartNew();
            for (int i = 0; i < moves; i++)
                world.Objects.Move((uint)(1 + (i * 7919) % n), here);
            double moveNs = clock.Elapsed.TotalMilliseconds * 1e6 / moves;
            double moveBytes = (double)(GC.GetAllocatedBytesForCurrentThread() - bytes) / moves;
            // Removal in a scattered order (each from the middle of the list, as a scan would suffer).
            var random = new Random(n);
            var order = new uint[n];
            for (int i = 0; i < n; i++) order[i] = (uint)(i + 1);
            random.Shuffle(order);
            clock.Restart();
            foreach (uint id in order)
                world.Objects.Unregister(id);
            double removeNs = clock.Elapsed.TotalMilliseconds * 1e6 / n;
            Console.WriteLine($"{n,20:N0} {removeNs,21:F0} {moveNs,15:F0} {moveBytes,13:F1}");
        }
        return 0;
    }
}
