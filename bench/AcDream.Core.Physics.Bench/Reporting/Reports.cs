using System.Globalization;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Bench.Reporting;

/// <summary>Markdown and CSV output of the door job.</summary>
public static class Reports
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>The machine the job ran on (cores, CPU, .NET, date).</summary>
    public static string Machine()
    {
        string cpu = "unknown";
        try
        {
            if (File.Exists("/proc/cpuinfo"))
                cpu = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name", StringComparison.Ordinal))?.Split(':', 2)[1].Trim() ?? cpu;
        }
        catch (IOException)
        {
        }
        return $"{Environment.ProcessorCount} logical cores (nproc), CPU: {cpu}, {RuntimeInformation.FrameworkDescription} on {RuntimeInformation.OSDescription} ({RuntimeInformation.ProcessArchitecture}), {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC";
    }

    /// <summary>
    /// What the methods are, and that the reference is an ideal sweep rather than retail: written at the head
    /// of door.md and stability.md, so the numbers below it are read right.
    /// </summary>
    public static string MethodsAndReference() => """
        ## Reading these results

        **Methods.** *Retail* is `PhysicsEngine` as the retail client runs it: sub-steps of at most one
        sphere radius. *Scale N* is the same engine with `PhysicsEngine.SubStepScale = N` (sub-steps of N
        radii; not retail). *Reference* is `ReferenceSweep`: the player's spheres swept continuously with
        exact times of impact against the slab's faces and rounded edges, moved to the earliest contact and
        slid along it (up to 8 contacts a frame), kept on the floor.

        **The reference is an ideal sweep, not retail.** Every error and every stuck frame is measured
        against it, so Retail "losing" to it is expected, not a defect: retail resolves a frame in discrete
        sub-steps, and where a sphere meets an edge of the slab its BSP test reports one face's plane normal
        (the front or the side), while the reference rounds the edge and slides round it. On this door that
        difference explains most of the error, and Retail's stuck and jitter frames (the edge pin, below). The
        library's aim is retail's answer (checked by the parity files and the replays), not the reference's;
        the reference measures how far retail is from exact geometry, and what a non-retail sub-step scale
        changes. It scores 0 on everything by construction.


        """;

    /// <summary>The failures counted per frame, with the edge pin that explains Retail's stuck and jitter frames.</summary>
    public static string FailureDefinitions() => """
        **Failures**, counted per frame (an approach fails a kind when any of its frames does):

        | Failure | Meaning |
        |---|---|
        | Penetration | A player sphere ends the frame more than EPSILON (0.2 mm) inside the slab. |
        | Tunnel | The centre crosses the slab's middle plane, within half the slab's width plus a radius of its centre line before and after the frame. |
        | Stuck | The mover does not move (< 0.01 mm) although the reference, resolving the same frame from the same start, moves (> 0.1 mm), and the requested motion along the face per sub-step exceeds √EPSILON (0.01414 m), so retail's refusal of shorter slides (`CSphere::slide_sphere`) is not the reason. |
        | Jitter | The collision normal alternates: it differs from last frame's (dot < 0.9) and equals the one before (dot > 0.99). |
        | NaN | A non-finite position, or the method threw. |

        **The edge pin**: a slow walk (1–5 m/s) that meets a vertical edge of the slab from beside it stops
        there for good, its collision normal flipping every frame between the front face and the side face
        (each face's hit slides the mover into the other): stuck and jitter together. The reference, whose
        edge is rounded, slides round it. One approach frame by frame:
        `dotnet run -c Release --project bench/AcDream.Core.Physics.Bench -- trace Retail 45 -0.7 1 30`.


        """;

    /// <summary>What the speed/accuracy table's columns measure.</summary>
    public static string ColumnDefinitions() => """
        **Columns.** Times are per door transition, or per frame of a workload: *30-frame approach* (head-on),
        *NE slide* (0.1 m a frame at 45°), *approach mix* (every frame input of the accuracy grid replayed;
        the chart's x axis), *all cores* (independent movers on every core). *Frame error*: distance from
        the reference resolving the same frame from the same start. *Approach error*: distance from the
        reference's own path after the last frame (errors add up over an approach). *Slide error / ratio*:
        distance travelled along the face against the reference's, on approaches where the reference
        touched the door at a slant.


        """;

    private static string Mm(double metres) => (metres * 1000).ToString("0.###", Inv);
    private static string Ns(double ns) => ns.ToString(ns >= 100 ? "0" : "0.0", Inv);

    /// <summary>The speed/accuracy table.</summary>
    public static string SpeedAccuracyTable(IReadOnlyList<MethodResult> results)
    {
        var sb = new StringBuilder();
        sb.AppendLine("| Method | door transition (ns) | alloc (B) | 30-frame approach (ns/frame) | NE slide (ns/frame) | approach mix (ns/frame) | all cores (transitions/s) | frame error mean / p99 / max (mm) | approach error mean / p99 / max (mm) | max penetration (mm) | penetrating frames | tunnelling frames | stuck frames | jitter frames | NaN frames | slide error (mm) | slide ratio |");
        sb.AppendLine("|---|---:|---:|---:|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var r in results)
        {
            var a = r.Accuracy;
            var t = r.Timing;
            sb.AppendLine(string.Join(" | ", new[]
            {
                "| " + DoorMethods.Label(r.Method), Ns(t.TransitionNs), t.BytesPerTransition.ToString("0", Inv), Ns(t.ApproachNs), Ns(t.SlideNs), Ns(t.MixNs),
                t.BatchPerSecond.ToString("N0", Inv),
                $"{Mm(a.FrameError.Mean)} / {Mm(a.FrameError.P99)} / {Mm(a.FrameError.Max)}",
                $"{Mm(a.ApproachError.Mean)} / {Mm(a.ApproachError.P99)} / {Mm(a.ApproachError.Max)}",
                Mm(a.MaxPenetration), a.PenetrationFrames.ToString(Inv), a.TunnelFrames.ToString(Inv), a.StuckFrames.ToString(Inv),
                a.JitterFrames.ToString(Inv), a.NaNFrames.ToString(Inv), Mm(a.SlideError), a.SlideRatio.ToString("0.000", Inv),
            }) + " |");
        }
        return sb.ToString();
    }

    /// <summary>The speed/accuracy CSV (one row per method, SI units: ns and metres).</summary>
    public static string SpeedAccuracyCsv(IReadOnlyList<MethodResult> results)
    {
        var sb = new StringBuilder();
        sb.AppendLine("method,transition_ns,alloc_bytes,approach_ns_per_frame,slide_ns_per_frame,mix_ns_per_frame,batch_transitions_per_s,approaches,frames,frame_error_mean_m,frame_error_p99_m,frame_error_max_m,approach_error_mean_m,approach_error_p99_m,approach_error_max_m,max_penetration_m,penetration_frames,tunnel_frames,stuck_frames,jitter_frames,nan_frames,slide_approaches,slide_error_m,slide_ratio,timing_source");
        foreach (var r in results)
        {
            var a = r.Accuracy;
            var t = r.Timing;
            sb.AppendLine(string.Join(",", new object[]
            {
                r.Method, t.TransitionNs, t.BytesPerTransition, t.ApproachNs, t.SlideNs, t.MixNs, t.BatchPerSecond, a.Approaches, a.Frames,
                a.FrameError.Mean, a.FrameError.P99, a.FrameError.Max, a.ApproachError.Mean, a.ApproachError.P99, a.ApproachError.Max,
                a.MaxPenetration, a.PenetrationFrames, a.TunnelFrames, a.StuckFrames, a.JitterFrames, a.NaNFrames, a.SlideApproaches,
                a.SlideError, a.SlideRatio, t.Source,
            }.Select(v => Convert.ToString(v, Inv))));
        }
        return sb.ToString();
    }

    /// <summary>
    /// The scale table (retail door transition with other objects in the landblock): the cost follows the
    /// objects in the cells the path touches (retail tests every object listed in those cells), not the total.
    /// </summary>
    public static string ScaleTable(IReadOnlyList<(int Objects, int InDoorCell, double Ns)> scale)
    {
        double alone = scale.FirstOrDefault(r => r.Objects == 0).Ns;
        var sb = new StringBuilder();
        sb.AppendLine("| Other objects in the landblock | of them in the door's cell | door transition (ns) | × the door alone |");
        sb.AppendLine("|---:|---:|---:|---:|");
        foreach (var (objects, inDoorCell, ns) in scale)
            sb.AppendLine($"| {objects:N0} | {inDoorCell:N0} | {Ns(ns)} | {(alone > 0 ? (ns / alone).ToString("0.00", CultureInfo.InvariantCulture) : "")} |");
        return sb.ToString();
    }

    /// <summary>Failed approaches per method, frame rate and speed.</summary>
    public static string StabilityTables(IReadOnlyList<MethodResult> results)
    {
        var sb = new StringBuilder();
        sb.AppendLine("Approaches (of " + results[0].Outcomes.Length + " per method) with each failure:");
        sb.AppendLine();
        sb.AppendLine("| Method | penetration | tunnel | stuck | jitter | NaN | any |");
        sb.AppendLine("|---|---:|---:|---:|---:|---:|---:|");
        foreach (var r in results)
        {
            var f = r.Accuracy.FailedApproaches;
            sb.AppendLine($"| {DoorMethods.Label(r.Method)} | {f[DoorFailure.Penetration]} | {f[DoorFailure.Tunnel]} | {f[DoorFailure.Stuck]} | {f[DoorFailure.Jitter]} | {f[DoorFailure.NaN]} | {r.Outcomes.Count(o => o.Failures != DoorFailure.None)} |");
        }
        sb.AppendLine();
        foreach (var r in results)
        {
            sb.AppendLine($"### {DoorMethods.Label(r.Method)}");
            sb.AppendLine();
            sb.AppendLine("Failed approaches per frame rate and speed, as penetration / tunnel / stuck / jitter / NaN (of " +
                DoorApproaches.Headings.Length * DoorApproaches.Laterals.Length + " approaches per row):");
            sb.AppendLine();
            sb.AppendLine("| Rate | " + string.Join(" | ", DoorApproaches.Speeds.Select(s => $"{s:0} m/s")) + " |");
            sb.AppendLine("|---|" + string.Concat(DoorApproaches.Speeds.Select(_ => "---|")));
            foreach (int hz in DoorApproaches.Rates)
            {
                sb.Append($"| {hz} Hz |");
                foreach (float speed in DoorApproaches.Speeds)
                {
                    var cell = r.Outcomes.Where(o => o.Approach.Hz == hz && o.Approach.Speed == speed).ToArray();
                    int Count(DoorFailure k) => cell.Count(o => (o.Failures & k) != 0);
                    sb.Append(cell.All(o => o.Failures == DoorFailure.None)
                        ? " – |"
                        : $" {Count(DoorFailure.Penetration)} / {Count(DoorFailure.Tunnel)} / {Count(DoorFailure.Stuck)} / {Count(DoorFailure.Jitter)} / {Count(DoorFailure.NaN)} |");
                }
                sb.AppendLine();
            }
            sb.AppendLine();
        }
        return sb.ToString();
    }

    /// <summary>One row per method and approach: the failures and the numbers behind them.</summary>
    public static string StabilityCsv(IReadOnlyList<MethodResult> results)
    {
        var sb = new StringBuilder();
        sb.AppendLine("method,hz,speed_mps,lateral_m,heading_deg,frames,failures,max_penetration_m,penetration_frames,tunnel_frames,stuck_frames,jitter_frames,nan_frames,final_error_m");
        foreach (var r in results)
            foreach (var o in r.Outcomes)
            {
                var a = o.Approach;
                sb.AppendLine(string.Join(",", new object[]
                {
                    r.Method, a.Hz, a.Speed, a.Lateral, a.Heading, o.Frames, o.Failures.ToString().Replace(", ", "|", StringComparison.Ordinal),
                    o.MaxPenetration, o.PenetrationFrames, o.TunnelFrames, o.StuckFrames, o.JitterFrames, o.NaNFrames, o.FinalError,
                }.Select(v => Convert.ToString(v, Inv))));
            }
        return sb.ToString();
    }
}
