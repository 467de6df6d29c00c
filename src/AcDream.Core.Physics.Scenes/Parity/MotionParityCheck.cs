using System;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Runs a motion parity file through the motion layer and the body step and compares every frame: the position
/// within <see cref="ParityCheck.Tolerance"/>, the cell, contact and walkable flags, whether a quantum ran, the
/// calls' results and the interpreted state (equal, speeds to the bit). The schedule is the file's: each frame
/// the calls, then 1/rate seconds given to the step (which runs a quantum once 1/30 s has gathered, as the
/// recording's rule).
/// </summary>
internal static class MotionParityCheck
{
    /// <summary>
    /// A place where ACE's motion layer departs from the decompile and a recording shows it: from
    /// <see cref="FromFrame"/> on, that file's positions are compared within <see cref="Bound"/> instead of the
    /// tolerance, and the report names it. Each is listed in docs/open-questions.md with the decompile line.
    /// </summary>
    internal readonly record struct AceDeparture(string Name, string File, int FromFrame, double Bound, string Source);

    /// <summary>The named departures (one so far).</summary>
    internal static readonly AceDeparture[] Departures =
    [
        // Walking backwards plays the walk cycle in reverse, taking each frame's root offset away. Retail's
        // Frame::subtract1 rotates the removed offset by the resulting rotation (the exact inverse of combine); ACE's
        // AFrame.Subtract rotates it by the root frame's own. The walk cycle's frames 1 and 5 turn by ±0.01 rad with a
        // 3.6 mm offset: each reverse crossing of them moves retail 7.2e-5 m from ACE; the first is at frame 9 and the
        // three backward cycles add up to 3.7e-4 m (docs/open-questions.md).
        new("reverse-root-frame-subtraction", "backwards.json.gz", 9, 4e-4,
            "Frame::subtract1, CFrame.c (acclient.c:357321); ACE Animation/AFrame.cs Subtract"),
    ];

    public static ParityReport Check(MotionParityFile file)
    {
        var engine = new PhysicsEngine(file.World);
        var motion = new ObjectMotion(file.Table, file.Skills);
        var state = file.Start;
        var body = file.StartBody;
        motion.Place(file.Mover, state, ref body);
        int frames = 0, within = 0, identical = 0, mismatches = 0, departed = 0;
        AceDeparture? departure = null;
        foreach (var d in Departures)
            if (d.File == file.Name)
                departure = d;
        double maxDifference = 0;
        string? firstFailure = null;
        for (int f = 0; f < file.Frames.Length; f++)
        {
            ref readonly var expected = ref file.Frames[f];
            string? callFailure = null;
            for (int k = 0; k < expected.Calls.Length; k++)
            {
                ref readonly var call = ref expected.Calls[k];
                string result;
                try
                {
                    result = Apply(motion, call, file.Mover, ref state, ref body);
                }
                catch (ArgumentException ex)
                {
                    // One call per recorded command, in order: k is the command's index in the file.
                    throw Refused($"frames[{f}].commands[{k}]", "the call", ex);
                }
                if (result != call.Expected)
                    callFailure ??= $"call {call.Kind} 0x{call.Motion:X8}: expected {call.Expected}, actual {result}";
            }
            BodyStepResult step;
            try
            {
                step = engine.Step(file.Mover, state, body, motion, file.FrameSeconds);
            }
            catch (ArgumentException ex)
            {
                throw Refused($"frames[{f}]", "the frame's step", ex);
            }
            state = step.Next;
            body = step.Body;
            frames++;
            var position = state.Position.Frame.Origin;
            double difference = Distance(position, expected.Position);
            maxDifference = Math.Max(maxDifference, difference);
            if (difference <= ParityCheck.Tolerance) within++;
            if (VectorMath.SameBits(position, expected.Position)) identical++;
            string? flag = callFailure ?? FlagDifference(expected, state, step.Quanta > 0, motion.Interpreted)
                ?? (expected.Sequence is { } seq ? SequenceDifference(seq, motion) : null);
            if (flag is not null) mismatches++;
            double bound = ParityCheck.Tolerance;
            if (departure is { } dep && f >= dep.FromFrame)
            {
                bound = dep.Bound;
                departed++;
            }
            if (firstFailure is null)
            {
                if (flag is not null)
                    firstFailure = $"{file.Name}: frame {f}: {flag}";
                else if (!(difference <= bound))
                    firstFailure = string.Format(CultureInfo.InvariantCulture, "{0}: frame {1}: position: expected {2}, actual {3} (difference {4:0.###e0} m, bound {5:0e0} m)",
                        file.Name, f, expected.Position, position, difference, bound);
            }
        }
        string? note = departure is { } named
            ? string.Format(CultureInfo.InvariantCulture, "{0} frames within {1:0e0} m under ACE departure {2} ({3})", departed, named.Bound, named.Name, named.Source)
            : null;
        return new ParityReport(file.Name, false, 1, frames, within, identical, maxDifference, mismatches, firstFailure, note) { Departure = departure?.Name };
    }

    /// <summary>
    /// Input the library refused while a motion or manager parity file ran, as a <see cref="SceneFormatException"/>
    /// naming the JSON path of the call or frame (the tool puts the file's name first).
    /// </summary>
    internal static SceneFormatException Refused(string path, string what, ArgumentException ex) =>
        new(path, $"{what} was refused: {SceneFormatException.Wrap(string.Empty, ex).Detail}", ex);

    private static string Apply(ObjectMotion motion, in MotionCall call, MoverDescription mover, ref MoverState state, ref BodyState body)
    {
        switch (call.Kind)
        {
            case MotionCallKind.HoldRun:
                // The recording sets the raw hold key as retail's CMotionInterp::SetHoldKey(Run) does.
                motion.SetHoldKey(HoldKey.Run, mover, ref state, ref body);
                return "None";
            case MotionCallKind.DoMotion:
                return Name(motion.DoMotion(call.Motion, new MotionParameters(call.Speed, call.Hold), mover, ref state, ref body));
            case MotionCallKind.StopMotion:
                return Name(motion.StopMotion(call.Motion, new MotionParameters(call.Speed, call.Hold), mover, ref state, ref body));
            case MotionCallKind.StopCompletely:
                return Name(motion.StopCompletely(mover, ref state, ref body));
            default:
                var charge = motion.ChargeJump(mover, state, body);
                if (charge != MotionError.None)
                    return Name(charge);
                return Name(motion.Jump(call.Extent, call.Stamina > 0, mover, ref state, ref body));
        }
    }

    // ACE's WeenieError names for the results the files record.
    private static string Name(MotionError e) => e switch
    {
        MotionError.None => "None",
        MotionError.NoMotionTableData => "NoMtableData",
        MotionError.CantJumpWhileInTheAir => "YouCantJumpWhileInTheAir",
        MotionError.CantJumpFromThisPosition => "YouCantJumpFromThisPosition",
        _ => e.ToString(),
    };

    private static string? FlagDifference(in MotionParityFrame e, in MoverState a, bool quantumRan, in InterpretedMotionState i)
    {
        if (a.Position.CellId != e.Cell) return $"cell: expected 0x{e.Cell:X8}, actual 0x{a.Position.CellId:X8}";
        if (a.Contact != e.Contact) return $"contact: expected {e.Contact}, actual {a.Contact}";
        if (a.OnWalkable != e.Walkable) return $"walkable: expected {e.Walkable}, actual {a.OnWalkable}";
        if (quantumRan != e.QuantumRan) return $"quantum ran: expected {e.QuantumRan}, actual {quantumRan}";
        var x = e.Interpreted;
        if (i.Style != x.Style || i.ForwardCommand != x.ForwardCommand || !Same(i.ForwardSpeed, x.ForwardSpeed)
            || i.SideStepCommand != x.SideStepCommand || !Same(i.SideStepSpeed, x.SideStepSpeed)
            || i.TurnCommand != x.TurnCommand || !Same(i.TurnSpeed, x.TurnSpeed))
            return $"interpreted state: expected {Describe(x)}, actual {Describe(i)}";
        return null;
    }

    /// <summary>The frame number's tolerance: ACE keeps it in float, retail (and the library) in double.</summary>
    public const double FrameNumberTolerance = 1e-4;

    /// <summary>The sequence velocity's and omega's tolerance per component (a float's last bits at 10 m/s).</summary>
    public const float SequenceVectorTolerance = 1e-5f;

    // The motion table manager's state and the sequence, as the reference logs them.
    private static string? SequenceDifference(MotionSequenceState e, ObjectMotion m)
    {
        if (m.Style != e.Style || m.Substate != e.Substate || !Same(m.SubstateSpeed, e.SubstateSpeed))
            return $"motion state: expected style 0x{e.Style:X8} substate 0x{e.Substate:X8}×{e.SubstateSpeed:R}, actual 0x{m.Style:X8} 0x{m.Substate:X8}×{m.SubstateSpeed:R}";
        if (m.ModifierCount != e.Modifiers.Length)
            return $"modifiers: expected {e.Modifiers.Length}, actual {m.ModifierCount}";
        for (int i = 0; i < e.Modifiers.Length; i++)
            if (m.Modifier(i).Id != e.Modifiers[i].Id || !Same(m.Modifier(i).Speed, e.Modifiers[i].Speed))
                return $"modifier {i}: expected 0x{e.Modifiers[i].Id:X8}×{e.Modifiers[i].Speed:R}, actual 0x{m.Modifier(i).Id:X8}×{m.Modifier(i).Speed:R}";
        if (!Close(m.SequenceVelocity, e.Velocity) || !Close(m.SequenceOmega, e.Omega))
            return $"sequence velocity/omega: expected {e.Velocity}/{e.Omega}, actual {m.SequenceVelocity}/{m.SequenceOmega}";
        if (m.CurrentAnimation != e.CurrentAnimation || !Same(m.CurrentFramerate, e.CurrentFramerate) || !(Math.Abs(m.FrameNumber - e.FrameNumber) <= FrameNumberTolerance))
            return string.Format(CultureInfo.InvariantCulture, "sequence: expected animation 0x{0:X8} at {1:R} frames/s, frame {2:R}; actual 0x{3:X8} at {4:R}, frame {5:R}",
                e.CurrentAnimation, e.CurrentFramerate, e.FrameNumber, m.CurrentAnimation, m.CurrentFramerate, m.FrameNumber);
        if (m.AnimationCount != e.Anims.Length || m.FirstCyclicAnimation != e.FirstCyclic)
            return $"animation list: expected {e.Anims.Length} (first cyclic {e.FirstCyclic}), actual {m.AnimationCount} (first cyclic {m.FirstCyclicAnimation})";
        for (int i = 0; i < e.Anims.Length; i++)
        {
            var (id, rate) = m.Animation(i);
            if (id != e.Anims[i].Id || !Same(rate, e.Anims[i].Framerate))
                return $"animation {i}: expected 0x{e.Anims[i].Id:X8}@{e.Anims[i].Framerate:R}, actual 0x{id:X8}@{rate:R}";
        }
        return null;
    }

    private static bool Close(Vector3 a, Vector3 b) =>
        MathF.Abs(a.X - b.X) <= SequenceVectorTolerance && MathF.Abs(a.Y - b.Y) <= SequenceVectorTolerance && MathF.Abs(a.Z - b.Z) <= SequenceVectorTolerance;

    internal static bool Same(float a, float b) => BitConverter.SingleToInt32Bits(a) == BitConverter.SingleToInt32Bits(b);

    private static string Describe(in InterpretedMotionState s) => string.Format(CultureInfo.InvariantCulture,
        "style 0x{0:X8} forward 0x{1:X8}×{2:R} sidestep 0x{3:X8}×{4:R} turn 0x{5:X8}×{6:R}",
        s.Style, s.ForwardCommand, s.ForwardSpeed, s.SideStepCommand, s.SideStepSpeed, s.TurnCommand, s.TurnSpeed);

    internal static double Distance(Vector3 a, Vector3 b)
    {
        double dx = (double)a.X - b.X, dy = (double)a.Y - b.Y, dz = (double)a.Z - b.Z;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }
}
