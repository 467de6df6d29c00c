using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Reference;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Bench.Accuracy;

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
