using System.Linq;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>A method's accuracy over an approach set.</summary>
public sealed class AccuracySummary
{
    /// <summary>The method.</summary>
    public required DoorMethod Method { get; init; }
    /// <summary>Approaches walked.</summary>
    public int Approaches { get; init; }
    /// <summary>Frames resolved.</summary>
    public int Frames { get; init; }
    /// <summary>Per-frame position error against the reference from the same start (metres).</summary>
    public Spread FrameError { get; init; }
    /// <summary>Position error against the reference trajectory after the whole approach (metres).</summary>
    public Spread ApproachError { get; init; }
    /// <summary>The deepest penetration of the slab after any frame (metres, 0 when never inside).</summary>
    public double MaxPenetration { get; init; }
    /// <summary>Frames with a penetration deeper than EPSILON.</summary>
    public int PenetrationFrames { get; init; }
    /// <summary>Frames that crossed the slab.</summary>
    public int TunnelFrames { get; init; }
    /// <summary>Stuck frames.</summary>
    public int StuckFrames { get; init; }
    /// <summary>Jitter frames.</summary>
    public int JitterFrames { get; init; }
    /// <summary>NaN or failed frames.</summary>
    public int NaNFrames { get; init; }
    /// <summary>Approaches with each failure.</summary>
    public IReadOnlyDictionary<DoorFailure, int> FailedApproaches { get; init; } = new Dictionary<DoorFailure, int>();
    /// <summary>Sliding approaches (the reference touched the door, heading ≠ 0).</summary>
    public int SlideApproaches { get; init; }
    /// <summary>Mean |method − reference| distance travelled along the face on sliding approaches (metres).</summary>
    public double SlideError { get; init; }
    /// <summary>Total distance along the face, method over reference, on sliding approaches.</summary>
    public double SlideRatio { get; init; }

    /// <summary>The single failures, for iteration.</summary>
    public static readonly DoorFailure[] Kinds = [DoorFailure.Penetration, DoorFailure.Tunnel, DoorFailure.Stuck, DoorFailure.Jitter, DoorFailure.NaN];

    /// <summary>Summarises outcomes.</summary>
    public static AccuracySummary Of(DoorMethod method, IReadOnlyList<ApproachOutcome> outcomes)
    {
        var slides = outcomes.Where(o => o.Slid).ToArray();
        double refSum = slides.Sum(o => (double)o.SlideReference);
        return new AccuracySummary
        {
            Method = method,
            Approaches = outcomes.Count,
            Frames = outcomes.Sum(o => o.Frames),
            FrameError = Spread.Of(outcomes.SelectMany(o => o.FrameErrors.Take(o.Frames))),
            ApproachError = Spread.Of(outcomes.Select(o => o.FinalError)),
            MaxPenetration = Math.Max(0, outcomes.Max(o => (double)o.MaxPenetration)),
            PenetrationFrames = outcomes.Sum(o => o.PenetrationFrames),
            TunnelFrames = outcomes.Sum(o => o.TunnelFrames),
            StuckFrames = outcomes.Sum(o => o.StuckFrames),
            JitterFrames = outcomes.Sum(o => o.JitterFrames),
            NaNFrames = outcomes.Sum(o => o.NaNFrames),
            FailedApproaches = Kinds.ToDictionary(k => k, k => outcomes.Count(o => (o.Failures & k) != 0)),
            SlideApproaches = slides.Length,
            SlideError = slides.Length == 0 ? 0 : slides.Average(o => Math.Abs((double)o.SlideMethod - o.SlideReference)),
            SlideRatio = refSum > 0 ? slides.Sum(o => (double)o.SlideMethod) / refSum : 1,
        };
    }

    /// <summary>The most severe failure of a set, for maps: NaN, tunnel, penetration, stuck, jitter, none.</summary>
    public static DoorFailure Worst(DoorFailure failures)
    {
        foreach (var kind in new[] { DoorFailure.NaN, DoorFailure.Tunnel, DoorFailure.Penetration, DoorFailure.Stuck, DoorFailure.Jitter })
            if ((failures & kind) != 0)
                return kind;
        return DoorFailure.None;
    }
}
