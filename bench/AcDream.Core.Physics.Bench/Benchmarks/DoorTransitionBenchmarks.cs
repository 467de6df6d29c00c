using System.Numerics;
using AcDream.Core.Physics.Bench.Accuracy;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Physics.Bench.Benchmarks;

/// <summary>One door transition: a grounded walk of 0.1 m into the slab's face, per method.</summary>
[MemoryDiagnoser]
public class DoorTransitionBenchmarks
{
    private DoorStepper _stepper = null!;
    private MoverState _state;
    private Vector3 _target;

    [ParamsAllValues]
    public DoorMethod Resolver { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _stepper = new DoorStepper(DoorScene.Create(), Resolver);
        _state = DoorWorkloads.TransitionStart;
        _target = DoorWorkloads.TransitionTarget;
    }

    [Benchmark]
    public MoverState Transition() => _stepper.Resolve(_state, _target);
}
