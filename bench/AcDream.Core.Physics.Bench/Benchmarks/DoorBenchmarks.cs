using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Bench.Accuracy;
using BenchmarkDotNet.Attributes;
using AcDream.Core.Physics.Transitions;

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
