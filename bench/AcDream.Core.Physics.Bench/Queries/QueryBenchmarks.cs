using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Physics.Bench.Queries;

/// <summary>Each world query once (see <see cref="QueryWorkloads"/>); the Resolve row gives the scale.</summary>
[MemoryDiagnoser]
public class QueryBenchmarks
{
    private QueryWorkloads _workloads = null!;

    [GlobalSetup]
    public void Setup() => _workloads = new QueryWorkloads();

    [Benchmark] public float SphereCast() => _workloads.Run(0);
    [Benchmark] public float RayCast() => _workloads.Run(1);
    [Benchmark] public float FloorIndoors() => _workloads.Run(2);
    [Benchmark] public float FloorOutdoors() => _workloads.Run(3);
    [Benchmark] public float CellAtPoint() => _workloads.Run(4);
    [Benchmark] public float OverlapSphere() => _workloads.Run(5);
    [Benchmark] public float OverlapBox() => _workloads.Run(6);
    [Benchmark] public float CameraArm() => _workloads.Run(7);
    [Benchmark(Baseline = true)] public float Resolve() => _workloads.Run(8);
}
