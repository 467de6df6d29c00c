using System.Numerics;
using AcDream.Core.Physics.Bench.Accuracy;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Physics.Bench.Benchmarks;

/// <summary>A 30-frame head-on approach and a 30-frame sliding NE approach, per method.</summary>
[MemoryDiagnoser]
public class DoorApproachBenchmarks
{
    private DoorStepper _stepper = null!;

    [ParamsAllValues]
    public DoorMethod Resolver { get; set; }

    [GlobalSetup]
    public void Setup() => _stepper = new DoorStepper(DoorScene.Create(), Resolver);

    [Benchmark(OperationsPerInvoke = DoorWorkloads.ApproachFrames)]
    public MoverState Approach30() => DoorWorkloads.Approach(_stepper);

    [Benchmark(OperationsPerInvoke = DoorWorkloads.ApproachFrames)]
    public MoverState SlideNorthEast() => DoorWorkloads.SlideNorthEast(_stepper);
}
