using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>Speed of one method (nanoseconds per transition unless named otherwise).</summary>
public sealed class MethodTiming
{
    /// <summary>One door transition (0.1 m into the face).</summary>
    public double TransitionNs { get; set; }
    /// <summary>The 30-frame head-on approach, per frame.</summary>
    public double ApproachNs { get; set; }
    /// <summary>The 30-frame sliding NE approach, per frame.</summary>
    public double SlideNs { get; set; }
    /// <summary>The accuracy approach set replayed (every frame's input), per frame.</summary>
    public double MixNs { get; set; }
    /// <summary>Independent movers on all cores: transitions per second.</summary>
    public double BatchPerSecond { get; set; }
    /// <summary>Bytes allocated per door transition (steady state).</summary>
    public double BytesPerTransition { get; set; }
    /// <summary>Where the door transition number came from ("Stopwatch" or "BenchmarkDotNet").</summary>
    public string Source { get; set; } = "Stopwatch";
}
