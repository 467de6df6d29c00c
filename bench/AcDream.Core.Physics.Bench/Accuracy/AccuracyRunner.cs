using System.Numerics;
using System.Threading.Tasks;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>Runs approaches with a method and measures it against the reference sweep.</summary>
public static class AccuracyRunner
{
    /// <summary>√EPSILON: retail refuses a slide whose tangential step is shorter (CSphere::slide_sphere).</summary>
    public static readonly float SlideThreshold = MathF.Sqrt(PhysicsConstants.Epsilon);

    /// <summary>Runs every approach (in parallel over <paramref name="threads"/> workers, deterministic results).</summary>
    public static ApproachOutcome[] Run(DoorScene scene, DoorMethod method, IReadOnlyList<DoorApproach> approaches, bool recordWorkload = false, int threads = 0)
    {
        var outcomes = new ApproachOutcome[approaches.Count];
        var options = new ParallelOptions { MaxDegreeOfParallelism = threads > 0 ? threads : Environment.ProcessorCount };
        Parallel.For(0, approaches.Count, options,
            () => (Stepper: new DoorStepper(scene, method), Reference: new ReferenceSweep(scene.Reference)),
            (i, _, local) =>
            {
                outcomes[i] = RunOne(local.Stepper, local.Reference, approaches[i], recordWorkload);
                return local;
            },
            _ => { });
        return outcomes;
    }

    /// <summary>Walks one approach with a method and the reference side by side.</summary>
    public static ApproachOutcome RunOne(DoorStepper stepper, ReferenceSweep reference, DoorApproach approach, bool recordWorkload = false)
    {
        int frames = approach.Frames;
        var spheres = DoorScene.Player.Spheres;
        var outcome = new ApproachOutcome { Approach = approach, FrameErrors = new float[frames] };
        var workload = recordWorkload ? new (MoverState, Vector3)[frames] : null;
        var step = approach.StepOffset;
        int subSteps = DoorMethods.SubSteps(stepper.Method, step);
        var start = approach.Start;
        var state = DoorScene.Standing(start);
        var truth = start;
        bool truthCollided = false;
        Vector3 n1 = default, n2 = default;
        bool v1 = false, v2 = false;
        int done = 0;
        for (int k = 0; k < frames; k++)
        {
            var before = state.Position.Origin;
            var target = before + step;
            if (workload is not null)
                workload[k] = (state, target);
            var result = stepper.Step(state, target);
            var after = result.Next.Position.Origin;
            done++;
            if (result.Failed || !float.IsFinite(after.X) || !float.IsFinite(after.Y) || !float.IsFinite(after.Z))
            {
                outcome.NaNFrames++;
                outcome.Failures |= DoorFailure.NaN;
                outcome.FrameErrors[k] = float.NaN;
                break;
            }
            var local = reference.Move(spheres, before, target);
            outcome.FrameErrors[k] = Vector3.Distance(after, local.Position);
            var whole = reference.Move(spheres, truth, truth + step);
            truth = whole.Position;
            truthCollided |= whole.Collided;

            float penetration = DoorScene.SlabPenetration(after);
            outcome.MaxPenetration = MathF.Max(outcome.MaxPenetration, penetration);
            if (penetration > PhysicsConstants.Epsilon)
            {
                outcome.PenetrationFrames++;
                outcome.Failures |= DoorFailure.Penetration;
            }
            if (Crossed(before, after))
            {
                outcome.TunnelFrames++;
                outcome.Failures |= DoorFailure.Tunnel;
            }
            if (IsStuck(before, after, step, local, subSteps))
            {
                outcome.StuckFrames++;
                outcome.Failures |= DoorFailure.Stuck;
            }
            if (result.NormalValid && v1 && v2 && Vector3.Dot(result.Normal, n1) < 0.9f && Vector3.Dot(result.Normal, n2) > 0.99f)
            {
                outcome.JitterFrames++;
                outcome.Failures |= DoorFailure.Jitter;
            }
            n2 = n1; v2 = v1;
            n1 = result.Normal; v1 = result.NormalValid;
            state = result.Next;
        }
        outcome.Frames = done;
        outcome.Workload = workload;
        var final = state.Position.Origin;
        outcome.FinalError = Vector3.Distance(final, truth);
        outcome.Slid = truthCollided && approach.Heading != 0;
        outcome.SlideMethod = MathF.Abs(final.X - start.X);
        outcome.SlideReference = MathF.Abs(truth.X - start.X);
        return outcome;
    }

    /// <summary>The mover's centre went from one side of the slab's middle plane to the other where the slab (plus a radius) stands.</summary>
    public static bool Crossed(Vector3 before, Vector3 after)
    {
        float mid = DoorScene.SlabMidY;
        if ((before.Y < mid) == (after.Y < mid))
            return false;
        float reach = DoorScene.SlabHalfWidth + DoorScene.PlayerRadius;
        return MathF.Abs(before.X - DoorScene.DoorOrigin.X) < reach && MathF.Abs(after.X - DoorScene.DoorOrigin.X) < reach;
    }

    /// <summary>
    /// Out = in while the reference moved, and the requested motion along the door's face (its X part, the
    /// tangential part of an approach to the face) per sub-step exceeds √EPSILON, the retail slide threshold.
    /// </summary>
    public static bool IsStuck(Vector3 before, Vector3 after, Vector3 step, in ReferenceMoveResult local, int subSteps)
    {
        if (Vector3.Distance(before, after) >= 1e-5f || Vector3.Distance(before, local.Position) <= 1e-4f)
            return false;
        return MathF.Abs(step.X) / subSteps > SlideThreshold;
    }
}
