using System.Threading.Tasks;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Bench.Benchmarks;

/// <summary>The timed workloads, shared by the BenchmarkDotNet classes and the door job's own timing loop.</summary>
public static class DoorWorkloads
{
    /// <summary>A grounded player 0.05 m short of touching the slab's front face, dead centre.</summary>
    public static MoverState TransitionStart => DoorScene.Standing(new Vector3(100f, DoorScene.FrontStop - 0.05f, 0));

    /// <summary>One frame's walk of 0.1 m into the face.</summary>
    public static Vector3 TransitionTarget => TransitionStart.Position.Origin + new Vector3(0, 0.1f, 0);

    /// <summary>Frames in the approach and slide workloads.</summary>
    public const int ApproachFrames = 30;

    /// <summary>The 30-frame head-on approach: 0.1 m per frame from 1.5 m short of the face.</summary>
    public static MoverState Approach(DoorStepper stepper)
    {
        var state = DoorScene.Standing(new Vector3(100.2f, DoorScene.FrontStop - 1.5f, 0));
        var step = new Vector3(0, 0.1f, 0);
        for (int i = 0; i < ApproachFrames; i++)
            state = stepper.Resolve(state, state.Position.Origin + step);
        return state;
    }

    /// <summary>The sliding NE approach: 0.1 m per frame at 45° from just short of the face, 30 frames (the apparatus test's walk).</summary>
    public static MoverState SlideNorthEast(DoorStepper stepper)
    {
        var state = DoorScene.Standing(new Vector3(99.6f, 99.0f, 0));
        var step = new Vector3(0.0707f, 0.0707f, 0);
        for (int i = 0; i < ApproachFrames; i++)
            state = stepper.Resolve(state, state.Position.Origin + step);
        return state;
    }

    /// <summary>Movers per batch.</summary>
    public const int BatchMovers = 256;

    /// <summary>Transitions per batch (movers × frames).</summary>
    public const int BatchTransitions = BatchMovers * ApproachFrames;

    /// <summary>
    /// Independent movers on all cores: each worker (one stepper, hence one engine, per worker) walks its
    /// share of <see cref="BatchMovers"/> movers NE along the face from spread-out lateral starts.
    /// </summary>
    public static void Batch(DoorScene scene, DoorMethod method, int workers)
    {
        Parallel.For(0, workers, new ParallelOptions { MaxDegreeOfParallelism = workers }, w =>
        {
            var stepper = new DoorStepper(scene, method);
            var step = new Vector3(0.0707f, 0.0707f, 0);
            for (int m = w; m < BatchMovers; m += workers)
            {
                var state = DoorScene.Standing(new Vector3(99.2f + 0.5f * (m % 8) / 8f, 99.0f - 0.1f * (m / 8 % 4), 0));
                for (int i = 0; i < ApproachFrames; i++)
                    state = stepper.Resolve(state, state.Position.Origin + step);
            }
        });
    }
}
