using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>Resolves frames by one method; one per thread.</summary>
public sealed class DoorStepper
{
    private readonly PhysicsEngine? _engine;
    private readonly ReferenceSweep? _reference;
    private readonly Sphere[] _spheres;

    /// <summary>Creates a stepper for a method over a scene.</summary>
    public DoorStepper(DoorScene scene, DoorMethod method)
    {
        Method = method;
        _spheres = DoorScene.Player.Spheres.ToArray();
        if (method == DoorMethod.Reference)
            _reference = new ReferenceSweep(scene.Reference);
        else
            _engine = new PhysicsEngine(scene.World) { SubStepScale = DoorMethods.SubStepScale(method) };
    }

    /// <summary>The method.</summary>
    public DoorMethod Method { get; }

    /// <summary>Resolves one frame from <paramref name="state"/> towards <paramref name="target"/> (landblock space); an engine exception is reported as <see cref="DoorStep.Failed"/>.</summary>
    public DoorStep Step(in MoverState state, Vector3 target)
    {
        if (_reference is not null)
        {
            var r = _reference.Move(_spheres, state.Position.Origin, target);
            return new DoorStep(DoorScene.Standing(r.Position), r.Collided, r.LastNormal, false);
        }
        try
        {
            var goal = state.Position;
            goal.Frame.Origin = target;
            var result = _engine!.Resolve(DoorScene.Player, state, goal);
            return new DoorStep(result.Next, result.CollisionNormalValid, result.CollisionNormal, false);
        }
        catch (Exception ex) when (ex is ArgumentException or InvalidOperationException or ArithmeticException or IndexOutOfRangeException)
        {
            return new DoorStep(state, false, default, true);
        }
    }

    /// <summary>The position only (for timing loops): resolves one frame and returns the next state.</summary>
    public MoverState Resolve(in MoverState state, Vector3 target) => Step(state, target).Next;
}
