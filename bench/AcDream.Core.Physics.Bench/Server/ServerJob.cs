using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text;
using System.Threading.Tasks;
using AcDream.Core.Physics.Bench.Reporting;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Bench.Server;

/// <summary>
/// The server tick job (<c>-- server [--creatures N,N,...] [--out DIR]</c>): N creatures over the
/// <see cref="ServerWorld"/> 3 × 3 landblock group, each taking one body step through its motion layer (the humanoid
/// table, a MoveTo toward a point with the server's GiveUp progress rule) per creature tick, ticks at
/// 30 Hz (a step of 1/30 s every tick) and at a 5 Hz creature rate (a step of 0.2 s every sixth tick);
/// with retail's activity rule (an object farther than 96 m from every player is not updated), counted.
/// Prints and writes <c>server.md</c>: ns per creature step, bytes per step, and the time of the same
/// ticks on one thread and on two (one engine per thread, the creatures split evenly between the threads).
/// </summary>
public static class ServerJob
{
    /// <summary>Retail's activity distance: farther than this from every player, an object is not updated (retail-facts: Activity).</summary>
    private const float ActivityDistance = 96f;

    /// <summary>The players the activity rule measures from (group frame): two near the middle landblock, two near corners.</summary>
    private static readonly Vector3[] Players = Array.ConvertAll(new Vector3[] { new(250, 260, 0), new(330, 300, 0), new(60, 60, 0), new(480, 120, 0) },
        p => p with { Z = ServerWorld.GroundAt(p.X, p.Y) + 1f });

    /// <summary>Runs the job; returns the exit code.</summary>
    public static int Run(string[] args)
    {
        int[] counts = [100, 1_000, 10_000];
        string outDir = Path.Combine("out", "server");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--out" && i + 1 < args.Length)
                outDir = args[++i];
            else if (args[i] == "--creatures" && i + 1 < args.Length && TryCounts(args[++i], out var parsed))
                counts = parsed;
            else
            {
                Console.Error.WriteLine($"server: bad argument '{args[i]}'. Usage: server [--creatures N,N,...] [--out DIR]");
                return 2;
            }
        }
        var total = Stopwatch.StartNew();
        var world = new ServerWorld();
        // Warm every path (walking, landing, both step lengths) until the JIT compiles nothing new, so no row
        // is timed in first-tier code (see RowTimer.WarmUntilJitSettles).
        var warm = Herd.Split(world, 500, 1);
        var (warmSeconds, _) = Reporting.RowTimer.WarmUntilJitSettles(() => { RunTicks(warm, 3, 1.0 / 30); RunTicks(warm, 1, 0.2); });
        var report = new StringBuilder();
        report.AppendLine("# Server tick");
        report.AppendLine();
        report.AppendLine(Reports.Machine() + string.Create(CultureInfo.InvariantCulture, $", load average {LoadAverage()}"));
        report.AppendLine();
        report.AppendLine(string.Create(CultureInfo.InvariantCulture,
            $"3 × 3 landblocks, {world.Props} trees and rocks, 9 buildings (shell + room); each creature steps through its motion layer (humanoid table, Run 200): a MoveTo toward a fixed pseudo-random point of the group (retail's default MoveTo parameters, the server's GiveUp progress rule), a new one when it ends or every 6 s of game time; warm-up {warmSeconds:0.0} s (until the JIT settled); players at {string.Join(", ", Array.ConvertAll(Players, p => $"({p.X:0}, {p.Y:0})"))}; ns per creature step is the fastest of the timed runs."));
        report.AppendLine();
        report.AppendLine("| creatures | rate | stepped / skipped per creature tick | ns per step, 1 thread | B per step | ns per step, 2 threads | 1 → 2 threads | threads' imbalance | ms per second of game time, 1 thread |");
        report.AppendLine("|---:|---|---|---:|---:|---:|---:|---:|---:|");
        Console.Write(report.ToString());
        foreach (int n in counts)
            foreach (int rate in new[] { 30, 5 })
            {
                var (one, two) = Measure(world, n, rate);
                double stepsPerSecond = one.SteppedPerTick * rate;
                string row = string.Create(CultureInfo.InvariantCulture,
                    $"| {n:N0} | {rate} Hz | {one.SteppedPerTick:0} / {one.SkippedPerTick:0} | {one.NsPerStep:0} | {one.BytesPerStep:0.#} | {two.NsPerStep:0} | {one.NsPerStep / two.NsPerStep:0.00}× | {two.Imbalance:0.00} | {stepsPerSecond * one.NsPerStep / 1e6:0.0} |");
                report.AppendLine(row);
                Console.WriteLine(row);
            }
        Directory.CreateDirectory(outDir);
        string path = Path.Combine(outDir, "server.md");
        File.WriteAllText(path, report.ToString());
        Console.WriteLine($"written to {path} ({total.Elapsed.TotalSeconds:0} s)");
        return 0;
    }

    private static bool TryCounts(string text, out int[] counts)
    {
        var parts = text.Split(',');
        counts = new int[parts.Length];
        for (int i = 0; i < parts.Length; i++)
            if (!int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out counts[i]) || counts[i] < 1 || counts[i] > 100_000)
                return false;
        return true;
    }

    private static string LoadAverage()
    {
        try { return File.Exists("/proc/loadavg") ? string.Join(' ', File.ReadAllText("/proc/loadavg").Split(' ')[..3]) : "unknown"; }
        catch (IOException) { return "unknown"; }
    }

    private readonly record struct Measured(double NsPerStep, double BytesPerStep, double SteppedPerTick, double SkippedPerTick, double Imbalance);

    /// <summary>
    /// Settles <paramref name="n"/> creatures (they start in the air and land) once on one thread and once
    /// split between two, then times creature ticks: five runs of each, one thread and two in turn (so a
    /// change of load hits both alike), the same game time at either rate (about 100,000 creature ticks at
    /// 30 Hz); per step, each keeps its fastest run.
    /// </summary>
    private static (Measured One, Measured Two) Measure(ServerWorld world, int n, int rate)
    {
        var sides = new[] { Herd.Split(world, n, 1), Herd.Split(world, n, 2) };
        double elapsed = 1.0 / rate;
        int ticks = Math.Max(3, Math.Clamp(100_000 / n, 3, 1000) * rate / 30);
        var best = new[] { double.PositiveInfinity, double.PositiveInfinity };
        var result = new Measured[2];
        foreach (var herds in sides)
            RunTicks(herds, ticks: 45, elapsed); // land
        for (int run = 0; run < 5; run++)
            for (int side = 0; side < 2; side++)
            {
                var herds = sides[side];
                foreach (var h in herds) h.ResetCounts();
                long before = GC.GetTotalAllocatedBytes(precise: true);
                long t0 = Stopwatch.GetTimestamp();
                RunTicks(herds, ticks, elapsed);
                double ns = Stopwatch.GetElapsedTime(t0).TotalNanoseconds;
                long bytes = GC.GetTotalAllocatedBytes(precise: true) - before;
                long steps = 0, skipped = 0;
                foreach (var h in herds) { steps += h.Stepped; skipped += h.Skipped; }
                double perStep = ns / Math.Max(1, steps);
                if (perStep < best[side])
                {
                    best[side] = perStep;
                    // The slower thread's time against the mean of the two (1 on one thread): how unevenly the work fell.
                    double imbalance = 1;
                    if (herds.Length > 1)
                    {
                        double sum = 0, max = 0;
                        foreach (var h in herds) { sum += h.BusyMs; max = Math.Max(max, h.BusyMs); }
                        imbalance = sum > 0 ? max / (sum / herds.Length) : 1;
                    }
                    result[side] = new Measured(perStep, bytes / (double)Math.Max(1, steps), steps / (double)ticks, skipped / (double)ticks, imbalance);
                }
            }
        return (result[0], result[1]);
    }

    private static void RunTicks(Herd[] herds, int ticks, double elapsed)
    {
        if (herds.Length == 1)
        {
            for (int t = 0; t < ticks; t++)
                herds[0].Tick(elapsed);
            return;
        }
        // One engine per thread for the whole run: each thread ticks its own landblocks' creatures.
        Parallel.For(0, herds.Length, new ParallelOptions { MaxDegreeOfParallelism = herds.Length }, h =>
        {
            long start = Stopwatch.GetTimestamp();
            for (int t = 0; t < ticks; t++)
                herds[h].Tick(elapsed);
            herds[h].BusyMs = Stopwatch.GetElapsedTime(start).TotalMilliseconds;
        });
    }

    /// <summary>The creatures one thread steps, with that thread's engine.</summary>
    private sealed class Herd
    {
        private readonly PhysicsEngine _engine;
        private readonly MoverDescription _creature = MoverDescription.Player(0x8000_0001).With(physicsState: PhysicsState.Gravity);
        private readonly MoverState[] _states;
        private readonly BodyState[] _bodies;
        private readonly ObjectMotion[] _motions;
        private readonly double[] _nextOrder;
        private readonly int[] _orders;
        private readonly int[] _seeds;
        private double _time;

        public long Stepped, Skipped;

        /// <summary>How long this herd's thread took over the last two-thread run, milliseconds.</summary>
        public double BusyMs;

        private Herd(ServerWorld world, List<int> members, int n)
        {
            _engine = new PhysicsEngine(world.World);
            _states = new MoverState[members.Count];
            _bodies = new BodyState[members.Count];
            _motions = new ObjectMotion[members.Count];
            _nextOrder = new double[members.Count];
            _orders = new int[members.Count];
            _seeds = members.ToArray();
            var table = MotionTables.Humanoid();
            for (int i = 0; i < members.Count; i++)
            {
                var p = StartPoint(members[i], n);
                p.Z = ServerWorld.GroundBelow(p.X, p.Y) + 0.5f;
                _states[i] = MoverState.Airborne(ServerWorld.At(p));
                _bodies[i] = BodyState.Creature();
                var motion = new ObjectMotion(table, new RetailSkills(200, 200));
                motion.SetCylinder(0.48f, 1.835f);
                // A server creature gives up a move that stops making progress (retail's client only counts).
                motion.MoveToProgressRule = MoveToProgressRule.GiveUp;
                motion.Place(_creature, _states[i], ref _bodies[i]);
                _motions[i] = motion;
            }
        }

        /// <summary>Creature i of n, spread over the group on a jittered grid (fixed), away from the group's edge.</summary>
        private static Vector3 StartPoint(int i, int n)
        {
            int side = (int)MathF.Ceiling(MathF.Sqrt(n));
            float cell = (ServerWorld.Extent - 40f) / side;
            return new Vector3(20f + cell * (i % side + 0.2f + 0.6f * Hash(i, 1)), 20f + cell * (i / side + 0.2f + 0.6f * Hash(i, 2)), 0);
        }

        /// <summary>
        /// Splits n creatures between <paramref name="threads"/> herds, creature i to herd i mod threads, so
        /// each herd holds an even share of every landblock's creatures and so of those near the players.
        /// (A split by landblock gave one thread five landblocks and the other four, with the players nearer
        /// some than others: the threads' stepped counts differed and two threads gave 1.12–1.26×.) The
        /// creatures do not meet one another (they are not registered as objects), so any split steps each
        /// creature the same.
        /// </summary>
        public static Herd[] Split(ServerWorld world, int n, int threads)
        {
            var lists = new List<int>[threads];
            for (int t = 0; t < threads; t++) lists[t] = new List<int>();
            for (int i = 0; i < n; i++)
                lists[i % threads].Add(i);
            var herds = new Herd[threads];
            for (int t = 0; t < threads; t++) herds[t] = new Herd(world, lists[t], n);
            return herds;
        }

        public void ResetCounts() => Stepped = Skipped = 0;

        /// <summary>One server tick: every creature near a player takes one body step of <paramref name="elapsed"/> seconds.</summary>
        public void Tick(double elapsed)
        {
            _time += elapsed;
            for (int i = 0; i < _states.Length; i++)
            {
                var at = ServerWorld.InGroup(_states[i].Position);
                if (!NearAPlayer(at))
                {
                    Skipped++;
                    continue;
                }
                Stepped++;
                Order(i);
                StepCreature(i, elapsed);
            }
        }

        /// <summary>The one place a creature's step is taken: the motion layer's body step (commands given between steps).</summary>
        private void StepCreature(int i, double elapsed)
        {
            var result = _engine.Step(_creature, _states[i], _bodies[i], _motions[i], elapsed);
            _states[i] = result.Next;
            _bodies[i] = result.Body;
        }

        /// <summary>
        /// As a server's creature AI would: when its move has ended (arrived or given up) or 6 s of game time have
        /// passed, a MoveTo toward the next fixed pseudo-random point of the group (away from its edge).
        /// </summary>
        private void Order(int i)
        {
            var motion = _motions[i];
            if (motion.MoveToStatus == MoveToStatus.Moving && _time < _nextOrder[i])
                return;
            int k = ++_orders[i];
            const float margin = 25f;
            float span = ServerWorld.Extent - 2 * margin;
            var goal = new Vector3(margin + span * Hash(_seeds[i], 2 * k + 3), margin + span * Hash(_seeds[i], 2 * k + 4), 0);
            goal.Z = ServerWorld.GroundAt(goal.X, goal.Y);
            motion.MoveToPosition(ServerWorld.At(goal), MoveToParameters.Default, _creature, _states[i], _bodies[i]);
            _nextOrder[i] = _time + 6.0;
        }

        private static bool NearAPlayer(Vector3 at)
        {
            foreach (var p in Players)
                if (Vector3.DistanceSquared(at, p) <= ActivityDistance * ActivityDistance)
                    return true;
            return false;
        }

        /// <summary>A fixed pseudo-random number in [0, 1) from two integers.</summary>
        private static float Hash(int a, int b)
        {
            uint h = (uint)a * 0x9E3779B1u ^ (uint)b * 0x85EBCA77u;
            h ^= h >> 15; h *= 0x2C1B3C6Du; h ^= h >> 12; h *= 0x297A2D39u; h ^= h >> 15;
            return (h >> 8) / 16777216f;
        }
    }
}
