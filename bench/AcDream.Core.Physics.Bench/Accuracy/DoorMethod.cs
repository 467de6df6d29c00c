using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>The ways of resolving a frame that the door benchmark compares.</summary>
public enum DoorMethod
{
    /// <summary>The engine as retail runs it (sub-steps of one sphere radius).</summary>
    Retail,
    /// <summary>Sub-steps of a quarter radius.</summary>
    Scale0_25,
    /// <summary>Sub-steps of half a radius.</summary>
    Scale0_5,
    /// <summary>Sub-steps of two radii.</summary>
    Scale2,
    /// <summary>Sub-steps of four radii.</summary>
    Scale4,
    /// <summary>The exact continuous sweep (<see cref="ReferenceSweep"/>).</summary>
    Reference,
}

/// <summary>Names and settings of <see cref="DoorMethod"/>s.</summary>
public static class DoorMethods
{
    /// <summary>Every method, retail first.</summary>
    public static readonly DoorMethod[] All = [DoorMethod.Retail, DoorMethod.Scale0_25, DoorMethod.Scale0_5, DoorMethod.Scale2, DoorMethod.Scale4, DoorMethod.Reference];

    /// <summary>The engine's sub-step scale for a method (1 for the reference, which has no sub-steps).</summary>
    public static float SubStepScale(DoorMethod method) => method switch
    {
        DoorMethod.Scale0_25 => 0.25f,
        DoorMethod.Scale0_5 => 0.5f,
        DoorMethod.Scale2 => 2f,
        DoorMethod.Scale4 => 4f,
        _ => 1f,
    };

    /// <summary>A short label for tables and charts.</summary>
    public static string Label(DoorMethod method) => method switch
    {
        DoorMethod.Retail => "Retail",
        DoorMethod.Scale0_25 => "Scale 0.25",
        DoorMethod.Scale0_5 => "Scale 0.5",
        DoorMethod.Scale2 => "Scale 2",
        DoorMethod.Scale4 => "Scale 4",
        DoorMethod.Reference => "Reference",
        _ => method.ToString(),
    };

    /// <summary>The number of sub-steps a method cuts a frame's motion into (1 for the reference).</summary>
    public static int SubSteps(DoorMethod method, Vector3 offset)
    {
        if (method == DoorMethod.Reference)
            return 1;
        int n = Transition.CalcNumSteps(offset, DoorScene.PlayerRadius * SubStepScale(method), false, out _);
        return Math.Max(n, 1);
    }
}

/// <summary>One resolved frame.</summary>
public readonly struct DoorStep
{
    /// <summary>Creates a step outcome.</summary>
    public DoorStep(MoverState next, bool normalValid, Vector3 normal, bool failed)
    {
        Next = next;
        NormalValid = normalValid;
        Normal = normal;
        Failed = failed;
    }

    /// <summary>The mover's next state.</summary>
    public MoverState Next { get; }
    /// <summary>A collision normal was reported.</summary>
    public bool NormalValid { get; }
    /// <summary>The collision normal.</summary>
    public Vector3 Normal { get; }
    /// <summary>The method threw (counted with NaN).</summary>
    public bool Failed { get; }
}

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
