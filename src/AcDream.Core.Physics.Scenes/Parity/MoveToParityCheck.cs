using System;
using System.Globalization;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Runs a MoveTo parity file's script through the motion layer's MoveToManager and the body step, and compares
/// every frame with ACE's: the position within <see cref="ParityCheck.Tolerance"/>, the heading within
/// <see cref="HeadingTolerance"/>, the cell, contact and walkable flags, the interpreted forward and turn commands and
/// speeds (to the bit), the manager's movement type, command, aim turn and fail count, and the frame and code of the
/// completion. Where ACE departs from the decompile a named departure says what is compared instead, and the line says
/// so (never "ok" for what was not compared). (The position managers' files of the same data: <see cref="PositionManagerParityCheck"/>.)
/// </summary>
internal static class MoveToParityCheck
{
    /// <summary>
    /// The heading tolerance, degrees: ACE computes headings and set_heading in float (AFrame.get_heading/set_heading,
    /// System.Numerics), retail in double (Frame::get_heading, set_vector_heading, acclient.c:357667); the last bits differ.
    /// </summary>
    public const double HeadingTolerance = 1e-3;

    /// <summary>The retail player's cylinder (setup radius and height) for the MoveTo distances, as the recordings' creatures.</summary>
    private const float CreatureRadius = 0.48f, CreatureHeight = 1.835f;

    private const string TurnStartsAtCall =
        "departure turn-starts-at-call: retail's TurnToHeading begins its node at once (BeginNextNode, acclient.c:345953); ACE adds it and waits for the next UseTime (MoveToManager.cs:303), one quantum behind, so our frame f is compared with ACE's frame f+1, except its fail count on its first turn quantum (the spurious count: ACE's handler runs after the turn's motion completed, retail's while it is still pending)";

    private const string ProgressClock =
        "departure progress-clock: ACE's clock adds 1/30 s in double from 1000 s, 31 frames to pass 1 s; ours adds the float quantum, 30; so our progress checks fail {0} frames earlier (ours from frame {1}, ACE's from frame {2}) and from there our fail count at frame f is compared with ACE's at frame f+{0} (the last {0} frames' counts have no ACE frame)";

    public static ParityReport Check(ParitySet set)
    {
        if (set.MoveTo is not { } file)
            throw new ArgumentException($"{set.Name} is not a MoveTo file.", nameof(set));
        int shift = file.Name.StartsWith("turnto-heading", StringComparison.Ordinal) ? 1 : 0;
        var engine = new PhysicsEngine(file.World);
        var motion = new ObjectMotion(file.Table, file.Skills);
        motion.SetCylinder(CreatureRadius, CreatureHeight);
        var state = file.Start;
        var body = BodyState.Creature();
        motion.Place(file.Mover, state, ref body);
        int frames = 0, within = 0, identical = 0, mismatches = 0;
        double maxDifference = 0;
        string? firstFailure = null;
        uint sought = 0;
        int countingFrom = -1; // the frame our progress checks first failed (progress-clock departure)
        int aceCountingFrom = shift == 0 ? Array.FindIndex(file.Frames, x => x.FailProgressCount > 0) : -1;
        int clock = 0; // how many frames earlier ours began counting than ACE's, once both did
        for (int f = 0; f < file.Frames.Length; f++)
        {
            ref readonly var frame = ref file.Frames[f];
            foreach (var call in frame.Calls)
            {
                try
                {
                    switch (call.Kind)
                    {
                        case MoveToKind.MoveToPosition:
                            motion.MoveToPosition(call.Target, call.Parameters, file.Mover, state, body);
                            break;
                        case MoveToKind.TurnToHeading:
                            motion.TurnToHeading(call.Parameters, file.Mover, state, body);
                            break;
                        default:
                            sought = call.ObjectId;
                            motion.MoveToObject(call.ObjectId, CreatureRadius, CreatureHeight, call.Parameters, file.Mover, state, body);
                            break;
                    }
                }
                catch (ArgumentException ex)
                {
                    throw MotionParityCheck.Refused(call.Path, "the call", ex);
                }
            }
            // The target's voyeur update: inside the MoveToObject call (set_target's immediate update), else from the
            // target's own quantum, which runs after the mover's (README "Scheduling"): the mover's next UseTime sees it.
            bool atCall = frame.Calls.Length > 0;
            if (atCall && frame.TargetUpdate is { } first && sought != 0)
                Update(motion, sought, first, frame.InterpolatedUpdate ?? first, file, state, body, f);
            bool endedBefore = motion.MoveToStatus == MoveToStatus.Ended;
            BodyStepResult step;
            try
            {
                step = engine.Step(file.Mover, state, body, motion, file.FrameSeconds);
            }
            catch (ArgumentException ex)
            {
                throw MotionParityCheck.Refused($"frames[{f}]", "the frame's step", ex);
            }
            state = step.Next;
            body = step.Body;
            if (!atCall && frame.TargetUpdate is { } update && sought != 0)
                Update(motion, sought, update, frame.InterpolatedUpdate ?? update, file, state, body, f);
            bool endedNow = !endedBefore && motion.MoveToStatus == MoveToStatus.Ended;
            int e = f + shift;
            if (e >= file.Frames.Length)
                break;
            ref readonly var expected = ref file.Frames[e];
            frames++;
            var position = state.Position.Frame.Origin;
            double difference = MotionParityCheck.Distance(position, expected.Origin);
            maxDifference = Math.Max(maxDifference, difference);
            if (difference <= ParityCheck.Tolerance) within++;
            if (VectorMath.SameBits(position, expected.Origin)) identical++;
            // ACE's first turn quantum counts a failed check that retail's order never shows (the turn begun at the call is
            // still pending when the first handler runs); part of turn-starts-at-call, the count is not compared there.
            if (countingFrom < 0 && motion.MoveToFailProgressCount > 0)
            {
                countingFrom = f;
                if (aceCountingFrom > f)
                    clock = aceCountingFrom - f;
            }
            // Under progress-clock our count runs `clock` frames ahead of ACE's: compared with ACE's count that many
            // frames on, not at all where the file has no such frame. Otherwise compared frame for frame.
            int? aceFails = shift != 0 && e == 1 ? null
                : clock == 0 ? expected.FailProgressCount
                : f + clock < file.Frames.Length ? file.Frames[f + clock].FailProgressCount : null;
            string? flag = Difference(expected, state, motion, endedNow, aceFails, clock);
            if (flag is not null) mismatches++;
            if (firstFailure is null)
            {
                if (flag is not null)
                    firstFailure = $"{file.Name}: frame {f}: {flag}";
                else if (!(difference <= ParityCheck.Tolerance))
                    firstFailure = string.Format(CultureInfo.InvariantCulture, "{0}: frame {1}: position: expected {2}, actual {3} (difference {4:0.###e0} m)",
                        file.Name, f, expected.Origin, position, difference);
            }
        }
        var c = CultureInfo.InvariantCulture;
        string counts = string.Format(c, "{0} compared, {1} within {2} m, {3} bit-identical, max difference {4} m, {5}",
            ParityReport.Count(frames, "frame"), within, ParityCheck.Tolerance.ToString("0e0", c), identical,
            maxDifference == 0 ? "0" : maxDifference.ToString("0.###e0", c), ParityReport.Count(mismatches, "flag mismatch", "flag mismatches"));
        string? verdict = null;
        if (clock != 0 && firstFailure is null)
            verdict = string.Format(c, "ok (within {0} m, headings within {1} deg) under {2}; our fail count {3} at the last frame, ACE's {4}; {5}",
                ParityCheck.Tolerance.ToString("0e0", c), HeadingTolerance.ToString("0e0", c),
                string.Format(c, ProgressClock, clock, countingFrom, aceCountingFrom),
                motion.MoveToFailProgressCount, file.Frames[^1].FailProgressCount, counts);
        else if (clock != 0)
            verdict = string.Format(c, "under {0}: {1}", string.Format(c, ProgressClock, clock, countingFrom, aceCountingFrom), counts);
        else if (shift != 0 && firstFailure is null)
            verdict = $"ok (within {ParityCheck.Tolerance.ToString("0e0", c)} m, headings within {HeadingTolerance.ToString("0e0", c)} deg) under {TurnStartsAtCall}; {counts}";
        string? note = shift != 0 ? TurnStartsAtCall
            : file.Frames.Length > 0 && Array.Exists(file.Frames[0].Calls, c => c.Kind == MoveToKind.MoveToObject)
                ? "ACE's call names no walk/run threshold: ACE's default 1 m is used as ACE ran it (MovementParameters.cs:49-50; retail's is 15 m)"
                : null;
        return new ParityReport(file.Name, false, 1, frames, within, identical, maxDifference, mismatches, firstFailure, note)
        {
            Verdict = verdict,
            Threshold = $"within {ParityCheck.Tolerance.ToString("0e0", c)} m, headings within {HeadingTolerance.ToString("0e0", c)} deg",
            Departure = shift != 0 ? "turn-starts-at-call" : clock != 0 ? "progress-clock" : null,
        };
    }

    private static string? Difference(in MoveToFrame e, in MoverState a, ObjectMotion m, bool endedNow, int? aceFails, int clock)
    {
        if (a.Position.CellId != e.Cell) return $"cell: expected 0x{e.Cell:X8}, actual 0x{a.Position.CellId:X8}";
        if (a.Contact != e.Contact) return $"contact: expected {e.Contact}, actual {a.Contact}";
        if (a.OnWalkable != e.Walkable) return $"walkable: expected {e.Walkable}, actual {a.OnWalkable}";
        float heading = Headings.Of(a.Position.Frame);
        double dh = Math.Abs((double)heading - e.Heading);
        dh = Math.Min(dh, 360.0 - dh);
        if (!(dh <= HeadingTolerance))
            return string.Format(CultureInfo.InvariantCulture, "heading: expected {0:R}, actual {1:R}", e.Heading, heading);
        var i = m.Interpreted;
        if (i.ForwardCommand != e.ForwardCommand || !MotionParityCheck.Same(i.ForwardSpeed, e.ForwardSpeed) || i.TurnCommand != e.TurnCommand || !MotionParityCheck.Same(i.TurnSpeed, e.TurnSpeed))
            return string.Format(CultureInfo.InvariantCulture, "interpreted: expected forward 0x{0:X8}×{1:R} turn 0x{2:X8}×{3:R}, actual 0x{4:X8}×{5:R} 0x{6:X8}×{7:R}",
                e.ForwardCommand, e.ForwardSpeed, e.TurnCommand, e.TurnSpeed, i.ForwardCommand, i.ForwardSpeed, i.TurnCommand, i.TurnSpeed);
        if (m.MoveToKind != e.Kind || m.MoveToCommand != e.Command || m.MoveToAuxCommand != e.AuxCommand
            || aceFails is { } fails && m.MoveToFailProgressCount != fails)
        {
            string expectedFails = aceFails is null ? "not compared" : clock == 0 ? $"{aceFails}" : $"{aceFails} (ACE's frame +{clock}, progress-clock)";
            return $"moveTo: expected {e.Kind} command 0x{e.Command:X8} aux 0x{e.AuxCommand:X8} fails {expectedFails}, actual {m.MoveToKind} 0x{m.MoveToCommand:X8} 0x{m.MoveToAuxCommand:X8} {m.MoveToFailProgressCount}";
        }
        string? ours = endedNow ? Name(m.MoveToResult) : null;
        if (ours != e.Completed)
            return $"completion: expected {e.Completed ?? "none"}, actual {ours ?? "none"}";
        return null;
    }

    private static string Name(MoveToError e) => e == MoveToError.None ? "None" : e.ToString();

    // A target update the library refuses names the frame's recorded target position.
    private static void Update(ObjectMotion motion, uint sought, in Position update, in Position interpolated, MoveToParityFile file, in MoverState state, in BodyState body, int f)
    {
        try
        {
            motion.UpdateMoveToTarget(sought, update, interpolated, file.Mover, state, body);
        }
        catch (ArgumentException ex)
        {
            throw MotionParityCheck.Refused($"frames[{f}].targetInfo.targetPosition", "the target update", ex);
        }
    }
}
