using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Bench.Accuracy;

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
