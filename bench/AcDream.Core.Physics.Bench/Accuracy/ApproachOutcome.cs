using System.Numerics;
using System.Threading.Tasks;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>What one method did on one approach.</summary>
public sealed class ApproachOutcome
{
    /// <summary>The approach.</summary>
    public required DoorApproach Approach { get; init; }
    /// <summary>The failures seen.</summary>
    public DoorFailure Failures { get; set; }
    /// <summary>Frames walked.</summary>
    public int Frames { get; set; }
    /// <summary>The deepest penetration of the slab after any frame (metres; ≤ 0 when clear).</summary>
    public float MaxPenetration { get; set; } = float.NegativeInfinity;
    /// <summary>Frames ending deeper than EPSILON in the slab.</summary>
    public int PenetrationFrames { get; set; }
    /// <summary>Frames crossing the slab.</summary>
    public int TunnelFrames { get; set; }
    /// <summary>Stuck frames.</summary>
    public int StuckFrames { get; set; }
    /// <summary>Jitter frames.</summary>
    public int JitterFrames { get; set; }
    /// <summary>NaN or failed frames.</summary>
    public int NaNFrames { get; set; }
    /// <summary>Per frame: distance from the reference's resolution of the same frame from the same start (metres).</summary>
    public required float[] FrameErrors { get; init; }
    /// <summary>Distance between the method's and the reference's positions after the whole approach.</summary>
    public float FinalError { get; set; }
    /// <summary>The reference touched the door during the approach and the heading has a tangential part.</summary>
    public bool Slid { get; set; }
    /// <summary>Distance travelled along the face (X) by the method over the approach.</summary>
    public float SlideMethod { get; set; }
    /// <summary>Distance travelled along the face (X) by the reference over the approach.</summary>
    public float SlideReference { get; set; }
    /// <summary>The frames' inputs (state and target) for timing replays, when recorded.</summary>
    public (MoverState State, Vector3 Target)[]? Workload { get; set; }
}
