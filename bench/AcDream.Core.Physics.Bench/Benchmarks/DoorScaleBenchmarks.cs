using System.Numerics;
using AcDream.Core.Physics.Bench.Accuracy;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Physics.Bench.Benchmarks;

/// <summary>The door transition (retail) with other objects registered in the landblock, most in other cells.</summary>
[MemoryDiagnoser]
public class DoorScaleBenchmarks
{
    private DoorStepper _stepper = null!;
    private MoverState _state;
    private Vector3 _target;

    [Params(10, 1_000, 10_000)]
    public int Objects { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _stepper = new DoorStepper(DoorScene.Create(Objects), DoorMethod.Retail);
        _state = DoorWorkloads.TransitionStart;
        _target = DoorWorkloads.TransitionTarget;
    }

    [Benchmark]
    public MoverState Transition() => _stepper.Resolve(_state, _target);
}
