using System;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Runs a position managers' parity file (sticky, interpolate) through ObjectMotion's PositionManager and the body
/// step, and compares the frames where ACE follows retail with ACE's: the position within <see cref="Tolerance"/>, the
/// landblock, the heading within <see cref="MoveToParityCheck.HeadingTolerance"/>. Where ACE departs, the line names
/// the departure, what retail does and what is compared instead (or that nothing is); it never says ok for frames
/// not compared (docs/open-questions.md, "The position managers").
/// </summary>
internal static class PositionManagerParityCheck
{
    /// <summary>
    /// The position tolerance, metres: the interpolation offsets and the stick's approach are computed in float by
    /// both and through different (equivalent) formulas, so the last bits of a 100 m coordinate differ.
    /// </summary>
    public const double Tolerance = 1e-3;

    /// <summary>The sticky target's cylinder (the retail player setup, as the recording's target).</summary>
    private const float TargetRadius = 0.48f, TargetHeight = 1.835f;

    /// <summary>ACE's InterpolationManager as shipped (no applied offset): compared with nothing, described.</summary>
    private const string AsShipped = "interpolate.json.gz";

    /// <summary>How close (horizontally, metres) ours must come to a reported point to count it reached, for the description only.</summary>
    private const float ReachedDistance = 0.05f;

    private const string QuantumClock =
        "departure quantum-clock: a stick ends 1 s after StickTo (StickyManager::UseTime, acclient.c:388604, against Timer::cur_time); our clock sums the float quanta ((float)(1/30) > 1/30: the stick ends in frame {0}), ACE's timer adds a double 1/30 and ends it in frame {1}, after moving once more";

    private const string BlipFailedNode =
        "departure blip-failed-node: retail's UseTime blips to a last node that failed its progress check (NodeCompleted saves blipto_position, acclient.c:388881; UseTime, 389277); ACE's UseTime throws from frame {0} (PositionQueue.Last of an empty queue) and the object stays at the door, so frames {0}-{1} are compared with the failed node {2} instead of ACE";

    public static ParityReport Check(PositionManagerParityFile file)
    {
        var run = Run(file);
        return file.Name == AsShipped ? AsShippedReport(file, run)
            : file.Frames[0].InterpolateTo is null ? StickyReport(file, run) : InterpolationReport(file, run);
    }

    private readonly record struct Ours(Vector3[] Origins, uint[] Cells, float[] Headings, int StickEnded);

    private static Ours Run(PositionManagerParityFile file)
    {
        var engine = new PhysicsEngine(file.World);
        var motion = new ObjectMotion(file.Table, file.Skills);
        var state = file.Start;
        var body = BodyState.Creature();
        motion.Place(file.Mover, state, ref body);
        var manager = motion.PositionManager;
        int n = file.Frames.Length, stickEnded = -1;
        var origins = new Vector3[n];
        var cells = new uint[n];
        var headings = new float[n];
        uint stuckTo = 0;
        var target = file.TargetStart;
        for (int f = 0; f < n; f++)
        {
            ref readonly var frame = ref file.Frames[f];
            try
            {
                if (frame.StickTo != 0)
                {
                    stuckTo = frame.StickTo;
                    manager.StickTo(stuckTo, TargetRadius, TargetHeight, file.Mover);
                }
                // The target moves after the mover's quantum: the mover's next quantum sees the position after the last one.
                if (stuckTo != 0)
                    manager.UpdateTarget(stuckTo, target);
                if (frame.InterpolateTo is { } to)
                    manager.InterpolateTo(to, false, file.Mover, ref state);
                var step = engine.Step(file.Mover, state, body, motion, file.FrameSeconds);
                state = step.Next;
                body = step.Body;
            }
            catch (ArgumentException ex)
            {
                // The frame's recorded events (stick_to_object, @InterpolateTo) or its step.
                throw MotionParityCheck.Refused($"frames[{f}]", "the frame's calls or step", ex);
            }
            if (stuckTo != 0 && stickEnded < 0 && manager.StickyTargetId == 0)
                stickEnded = f;
            if (frame.Target is { } moved)
                target = moved;
            origins[f] = state.Position.Frame.Origin;
            cells[f] = state.Position.CellId;
            headings[f] = Headings.Of(state.Position.Frame);
        }
        return new Ours(origins, cells, headings, stickEnded);
    }

    /// <summary>Frames from..to compared with ACE; counts and the first failure (null when all agree).</summary>
    private static (int Frames, int Within, double Max, int Mismatches, string? First) Compare(PositionManagerParityFile file, Ours ours, int from, int to)
    {
        int frames = 0, within = 0, mismatches = 0;
        double max = 0;
        string? first = null;
        for (int f = from; f <= to; f++)
        {
            ref readonly var e = ref file.Frames[f];
            frames++;
            double d = MotionParityCheck.Distance(ours.Origins[f], e.Origin);
            max = Math.Max(max, d);
            if (d <= Tolerance) within++;
            string? flag = ours.Cells[f] >> 16 != e.Cell >> 16 ? $"landblock: expected 0x{e.Cell:X8}, actual 0x{ours.Cells[f]:X8}"
                : HeadingDiffers(e.Heading, ours.Headings[f]) ? string.Format(CultureInfo.InvariantCulture, "heading: expected {0:R}, actual {1:R}", e.Heading, ours.Headings[f])
                : null;
            if (flag is not null) mismatches++;
            if (first is null && (flag is not null || !(d <= Tolerance)))
                first = flag is not null ? $"{file.Name}: frame {f}: {flag}"
                    : string.Format(CultureInfo.InvariantCulture, "{0}: frame {1}: position: expected {2}, actual {3} (difference {4:0.###e0} m)", file.Name, f, e.Origin, ours.Origins[f], d);
        }
        return (frames, within, max, mismatches, first);
    }

    private static bool HeadingDiffers(float expected, float actual)
    {
        double dh = Math.Abs((double)actual - expected);
        dh = Math.Min(dh, 360.0 - dh);
        return !(dh <= MoveToParityCheck.HeadingTolerance);
    }

    private static string Counts(int frames, int within, double max, int mismatches)
    {
        var c = CultureInfo.InvariantCulture;
        return string.Format(c, "{0} compared, {1} within {2} m, max difference {3} m, {4}", ParityReport.Count(frames, "frame"), within,
            Tolerance.ToString("0e0", c), max == 0 ? "0" : max.ToString("0.###e0", c), ParityReport.Count(mismatches, "flag mismatch", "flag mismatches"));
    }

    private static string Ok => string.Format(CultureInfo.InvariantCulture, "ok (within {0} m, headings within {1} deg)",
        Tolerance.ToString("0e0", CultureInfo.InvariantCulture), MoveToParityCheck.HeadingTolerance.ToString("0e0", CultureInfo.InvariantCulture));

    private static ParityReport Report(PositionManagerParityFile file, (int Frames, int Within, double Max, int Mismatches, string? First) r, string verdict,
        string? departure = null) =>
        new(file.Name, false, 1, r.Frames, r.Within, 0, r.Max, r.Mismatches, r.First)
        {
            Verdict = verdict,
            Threshold = string.Format(CultureInfo.InvariantCulture, "within {0} m, headings within {1} deg",
                Tolerance.ToString("0e0", CultureInfo.InvariantCulture), MoveToParityCheck.HeadingTolerance.ToString("0e0", CultureInfo.InvariantCulture)),
            Departure = departure,
            CountsBitIdentical = false,
        };

    // sticky: frame for frame until our stick ends; ACE's ends one quantum later (quantum-clock), after which the two rest apart.
    private static ParityReport StickyReport(PositionManagerParityFile file, Ours ours)
    {
        var c = CultureInfo.InvariantCulture;
        int stuck = Array.FindIndex(file.Frames, x => x.StickTo != 0);
        int aceEnded = stuck < 0 ? -1 : Array.FindIndex(file.Frames, stuck, x => !x.AceStuck);
        int last = file.Frames.Length - 1;
        if (stuck < 0 || ours.StickEnded < 0 || aceEnded != ours.StickEnded + 1)
        {
            var all = Compare(file, ours, 0, last);
            return Report(file, all, string.Format(c, "{0}: our stick ended in frame {1}, ACE's in frame {2}; {3}",
                all.First is null ? Ok : "compared", ours.StickEnded, aceEnded, Counts(all.Frames, all.Within, all.Max, all.Mismatches)));
        }
        var r = Compare(file, ours, 0, ours.StickEnded);
        double apart = MotionParityCheck.Distance(ours.Origins[last], file.Frames[last].Origin);
        string clock = string.Format(c, QuantumClock, ours.StickEnded, aceEnded);
        string counts = Counts(r.Frames, r.Within, r.Max, r.Mismatches);
        return Report(file, r, string.Format(c, "{0} frames 0-{1} under {2}; frames {3}-{4} not compared (both at rest, {5:0.###} m apart: ACE's extra quantum); {6}",
            r.First is null ? Ok : "compared", ours.StickEnded, clock, aceEnded, last, apart, counts), "quantum-clock");
    }

    // interpolate-applied-offset: ACE with its two slips neutralised; compared with ACE except where its UseTime throws.
    private static ParityReport InterpolationReport(PositionManagerParityFile file, Ours ours)
    {
        var c = CultureInfo.InvariantCulture;
        int from = Array.FindIndex(file.Frames, x => x.AceThrew);
        // Without a throw, or one before any update (no failed node to blip to), every frame is compared with ACE.
        if (from < 1 || !Array.Exists(file.Frames[..from], x => x.InterpolateTo is not null))
        {
            var all = Compare(file, ours, 0, file.Frames.Length - 1);
            return Report(file, all, (all.First is null ? Ok : "compared") + "; " + Counts(all.Frames, all.Within, all.Max, all.Mismatches));
        }
        int to = from;
        while (to + 1 < file.Frames.Length && file.Frames[to + 1].AceThrew) to++;
        var node = Array.FindLast(file.Frames[..from], x => x.InterpolateTo is not null).InterpolateTo!.Value;
        var before = Compare(file, ours, 0, from - 1);
        var after = to + 1 < file.Frames.Length ? Compare(file, ours, to + 1, file.Frames.Length - 1) : (0, 0, 0.0, 0, null);
        int blipped = 0;
        for (int f = from; f <= to; f++)
        {
            var o = ours.Origins[f];
            if (ours.Cells[f] >> 16 == node.CellId >> 16 && Vector2.Distance(new(o.X, o.Y), new(node.Frame.Origin.X, node.Frame.Origin.Y)) <= Tolerance)
                blipped++;
        }
        var merged = (before.Frames + after.Frames, before.Within + after.Within, Math.Max(before.Max, after.Max), before.Mismatches + after.Mismatches,
            before.First ?? after.First ?? (blipped == to - from + 1 ? null : $"{file.Name}: frames {from}-{to}: {blipped} of {to - from + 1} at the failed node"));
        string departure = string.Format(c, BlipFailedNode, from, to, Xy(node.Frame.Origin));
        return Report(file, merged, string.Format(c, "{0} frames 0-{1} and {2}-{3} under {4} ({5} of {6} there); {7}",
            merged.Item5 is null ? Ok : "compared", from - 1, to + 1, file.Frames.Length - 1, departure, blipped, to - from + 1,
            Counts(merged.Item1, merged.Item2, merged.Item3, merged.Item4)), "blip-failed-node");
    }

    // interpolate: ACE as shipped never applies the offset; nothing is compared, the line says what each does.
    private static ParityReport AsShippedReport(PositionManagerParityFile file, Ours ours)
    {
        var c = CultureInfo.InvariantCulture;
        int n = file.Frames.Length, aceThrew = Array.FindIndex(file.Frames, x => x.AceThrew);
        int aceJumps = 0, aceMoving = 0, firstJump = -1, lastJump = -1;
        for (int f = 1; f < n; f++)
        {
            double d = MotionParityCheck.Distance(file.Frames[f].Origin, file.Frames[f - 1].Origin);
            if (d > 0.1 && OnAReport(file, file.Frames[f].Origin))
            {
                aceJumps++;
                if (firstJump < 0) firstJump = f;
                lastJump = f;
            }
            else if (d > 1e-4) aceMoving++; // any other move, smooth or a jump elsewhere
        }
        // Ours: the largest step of the smoothing (a step over 2 m is a blip), the stop at the door (before the first blip).
        double smooth = 0, doorY = 0;
        int blips = 0;
        string blipFrames = "";
        for (int f = 1; f < n; f++)
        {
            double d = MotionParityCheck.Distance(ours.Origins[f], ours.Origins[f - 1]);
            if (d > 2.0)
            {
                blips++;
                blipFrames += (blipFrames.Length == 0 ? "" : " and ") + f.ToString(c);
            }
            else
            {
                smooth = Math.Max(smooth, d);
                if (blips == 0) doorY = Math.Max(doorY, ours.Origins[f].Y);
            }
        }
        // The reported points ours comes within ReachedDistance of (horizontally) before the next report.
        int reports = 0, reached = 0;
        for (int f = 0; f < n; f++)
        {
            if (file.Frames[f].InterpolateTo is not { } p) continue;
            reports++;
            int next = Array.FindIndex(file.Frames, f + 1, x => x.InterpolateTo is not null);
            for (int g = f; g < (next < 0 ? n : next); g++)
            {
                var o = ours.Origins[g];
                if (ours.Cells[g] >> 16 == p.CellId >> 16 && Vector2.Distance(new(o.X, o.Y), new(p.Frame.Origin.X, p.Frame.Origin.Y)) <= ReachedDistance)
                {
                    reached++;
                    break;
                }
            }
        }
        var end = ours.Origins[^1];
        string verdict = string.Format(c,
            "departs (nothing compared): ACE as shipped never moves by interpolation (adjust_offset's `frame = offset;` is a no-op; Position.Subtract mutates the head node): its object jumps onto a reported point {0} times in {1} frames (frames {2}, {3}, ..., {4}; {5} other frames move at all) and its UseTime throws from frame {6}, so it never reaches the 150 m update; "
            + "ours (retail's adjust_offset) moves through the transition (at most {7:0.###} m a quantum, 2 x get_adjusted_max_speed), comes within {8} m of {9} of the {10} reported points before the next one (counting the blips), stops at the door at y {11:0.##}, blips {12} times (frames {13}: the failed node behind the door, then the 150 m update) and ends at 0x{14:X8} {15}, as interpolate-applied-offset shows",
            aceJumps, n, firstJump, firstJump + (lastJump - firstJump) / Math.Max(1, aceJumps - 1), lastJump, aceMoving, aceThrew,
            smooth, ReachedDistance.ToString(c), reached, reports, doorY, blips, blipFrames, ours.Cells[^1], Xy(end));
        return new ParityReport(file.Name, false, 1, 0, 0, 0, 0, 0, null) { Verdict = verdict, NothingCompared = true };
    }

    /// <summary>ACE's position is one of the reported points (horizontally within <see cref="Tolerance"/>: placement settles it 0.005 m up).</summary>
    private static bool OnAReport(PositionManagerParityFile file, Vector3 origin) =>
        Array.Exists(file.Frames, x => x.InterpolateTo is { } p
            && Vector2.Distance(new(p.Frame.Origin.X, p.Frame.Origin.Y), new(origin.X, origin.Y)) <= Tolerance);

    private static string Xy(Vector3 v) => string.Format(CultureInfo.InvariantCulture, "({0:0.###}, {1:0.###})", v.X, v.Y);
}
