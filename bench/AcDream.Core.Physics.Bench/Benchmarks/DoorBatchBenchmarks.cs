using System.Numerics;
using AcDream.Core.Physics.Bench.Accuracy;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Physics.Bench.Benchmarks;

/// <summary>
/// Independent movers resolved on all cores (Parallel.For, one engine per worker). The mean is per
/// transition; transitions per second = 10⁹ / mean (ns).
/// </summary>
[MemoryDiagnoser]
public class DoorBatchBenchmarks
{
    private DoorScene _scene = null!;

    public static IEnumerable<DoorMethod> Methods => [DoorMethod.Retail, DoorMethod.Reference];

    [ParamsSource(nameof(Methods))]
    public DoorMethod Resolver { get; set; }

    [GlobalSetup]
    public void Setup() => _scene = DoorScene.Create();

    [Benchmark(OperationsPerInvoke = DoorWorkloads.BatchTransitions)]
    public void AllCores() => DoorWorkloads.Batch(_scene, Resolver, Environment.ProcessorCount);
}
