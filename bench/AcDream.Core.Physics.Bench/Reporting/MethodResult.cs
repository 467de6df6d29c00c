using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>Everything measured for one method.</summary>
public sealed class MethodResult
{
    /// <summary>The method.</summary>
    public required DoorMethod Method { get; init; }
    /// <summary>Accuracy.</summary>
    public required AccuracySummary Accuracy { get; init; }
    /// <summary>Per-approach outcomes.</summary>
    public required ApproachOutcome[] Outcomes { get; init; }
    /// <summary>Speed.</summary>
    public MethodTiming Timing { get; } = new();
}
