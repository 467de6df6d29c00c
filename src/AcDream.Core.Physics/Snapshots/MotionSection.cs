using System;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Snapshots;

/// <summary>
/// Section 4 of a snapshot: an <see cref="ObjectMotion"/>'s dynamic state. The interpreter (CMotionInterp: the
/// body view, raw and interpreted states, flags, jump extent, run rate, pending motions), the motion table
/// manager (MotionState: style, substate, speed, modifiers, action count; the pending queue and animation
/// counter) and the sequence (CSequence: the nodes by animation id with frame ranges and framerates, first
/// cyclic, current, frame number, velocity, omega). The table is written as its id and must match on load.
/// A load reads and checks everything first, then changes the target: nothing is changed on failure.
/// </summary>
internal static class MotionSection
{
    // Caps on what a load accepts (far above what a motion table produces).
    internal const int MaxPending = 256, MaxModifiers = 64, MaxNodes = 1024;

    /// <summary>
    /// The fastest a loaded sequence node may play, frames/s: a table's fastest framerate (<see cref="MotionTable.MaxFramerate"/>)
    /// at DoMotion's largest speed (100) and the fastest retail run rate (4.5). The step crosses at most this many frames a
    /// second of game time, so a loaded state is stepped in bounded time (a framerate of 1e11 did not return).
    /// </summary>
    internal const float MaxSequenceFramerate = MotionTable.MaxFramerate * 100f * 4.5f;

    public static void Write(SnapshotWriter w, ObjectMotion motion)
    {
        var interp = motion.Interpreter;
        var manager = motion.Manager;
        var seq = motion.AnimationSequence;
        w.U32(motion.Table.Id);

        var body = interp.Body;
        w.Byte((byte)((body.Gravity ? 1 : 0) | (body.Contact ? 2 : 0) | (body.OnWalkable ? 4 : 0)));
        w.Quat(body.Orientation);
        w.Vec(body.Velocity);

        var raw = interp.Raw;
        w.U32((uint)raw.CurrentHoldKey);
        w.U32(raw.Style);
        w.U32(raw.ForwardCommand); w.U32((uint)raw.ForwardHoldKey); w.F32(raw.ForwardSpeed);
        w.U32(raw.SideStepCommand); w.U32((uint)raw.SideStepHoldKey); w.F32(raw.SideStepSpeed);
        w.U32(raw.TurnCommand); w.U32((uint)raw.TurnHoldKey); w.F32(raw.TurnSpeed);

        var it = interp.Interpreted;
        w.U32(it.Style);
        w.U32(it.ForwardCommand); w.F32(it.ForwardSpeed);
        w.U32(it.SideStepCommand); w.F32(it.SideStepSpeed);
        w.U32(it.TurnCommand); w.F32(it.TurnSpeed);

        w.Byte((byte)((interp.Initted ? 1 : 0) | (interp.StandingLongJump ? 2 : 0) | (interp.Autonomous ? 4 : 0)));
        w.F32(interp.JumpExtent);
        w.F32(interp.MyRunRate);
        w.U32((uint)interp.PendingCount);
        for (int i = 0; i < interp.PendingCount; i++)
        {
            var (m, e) = interp.PendingAt(i);
            w.U32(m);
            w.U32((uint)e);
        }

        var ms = manager.State;
        w.U32(ms.Style);
        w.U32(ms.Substate);
        w.F32(ms.SubstateMod);
        w.U32((uint)ms.ActionCount);
        w.U32((uint)ms.ModifierCount);
        for (int i = 0; i < ms.ModifierCount; i++)
        {
            w.U32(ms.Modifier(i).Id);
            w.F32(ms.Modifier(i).Speed);
        }
        w.U32(manager.AnimationCounter);
        w.U32((uint)manager.PendingCount);
        for (int i = 0; i < manager.PendingCount; i++)
        {
            var (m, n) = manager.PendingAt(i);
            w.U32(m);
            w.U32(n);
        }

        w.U32((uint)seq.Count);
        for (int i = 0; i < seq.Count; i++)
        {
            ref readonly var node = ref seq[i];
            w.U32(node.Animation.Id);
            w.U32((uint)node.LowFrame);
            w.U32((uint)node.HighFrame);
            w.F32(node.Framerate);
        }
        w.U32((uint)seq.FirstCyclic);
        w.U32((uint)seq.Current);
        w.F64(seq.FrameNumber);
        w.Vec(seq.Velocity);
        w.Vec(seq.Omega);
    }

    public static void Read(ref SnapshotReader r, ObjectMotion motion)
    {
        var table = motion.Table;
        uint tableId = r.U32("motion.table");
        if (tableId != table.Id)
            throw r.Fail("motion.table", $"0x{tableId:X8} is not the target's table 0x{table.Id:X8}");

        byte bodyFlags = Flags(ref r, "motion.body.flags", 7);
        var body = new InterpreterBody
        {
            Gravity = (bodyFlags & 1) != 0,
            Contact = (bodyFlags & 2) != 0,
            OnWalkable = (bodyFlags & 4) != 0,
            Orientation = r.Quat("motion.body.orientation"),
            Velocity = r.Vec("motion.body.velocity"),
        };

        var raw = new RawMotionState
        {
            CurrentHoldKey = Hold(ref r, "motion.raw.currentHoldKey"),
            Style = r.U32("motion.raw.style"),
            ForwardCommand = r.U32("motion.raw.forwardCommand"),
            ForwardHoldKey = Hold(ref r, "motion.raw.forwardHoldKey"),
            ForwardSpeed = r.F32("motion.raw.forwardSpeed"),
            SideStepCommand = r.U32("motion.raw.sideStepCommand"),
            SideStepHoldKey = Hold(ref r, "motion.raw.sideStepHoldKey"),
            SideStepSpeed = r.F32("motion.raw.sideStepSpeed"),
            TurnCommand = r.U32("motion.raw.turnCommand"),
            TurnHoldKey = Hold(ref r, "motion.raw.turnHoldKey"),
            TurnSpeed = r.F32("motion.raw.turnSpeed"),
        };
        var interpreted = new InterpretedMotionState
        {
            Style = r.U32("motion.interpreted.style"),
            ForwardCommand = r.U32("motion.interpreted.forwardCommand"),
            ForwardSpeed = r.F32("motion.interpreted.forwardSpeed"),
            SideStepCommand = r.U32("motion.interpreted.sideStepCommand"),
            SideStepSpeed = r.F32("motion.interpreted.sideStepSpeed"),
            TurnCommand = r.U32("motion.interpreted.turnCommand"),
            TurnSpeed = r.F32("motion.interpreted.turnSpeed"),
        };
        byte flags = Flags(ref r, "motion.interpreter.flags", 7);
        float jumpExtent = r.F32("motion.interpreter.jumpExtent");
        float runRate = r.F32("motion.interpreter.runRate");
        var interpPending = new (uint Motion, MotionError JumpError)[Count(ref r, "motion.interpreter.pending.count", MaxPending)];
        for (int i = 0; i < interpPending.Length; i++)
        {
            uint m = r.U32($"motion.interpreter.pending[{i}].motion");
            uint e = r.U32($"motion.interpreter.pending[{i}].jumpError");
            if (!Enum.IsDefined((MotionError)e))
                throw r.Fail($"motion.interpreter.pending[{i}].jumpError", $"unknown error 0x{e:X2}");
            interpPending[i] = (m, (MotionError)e);
        }

        uint style = r.U32("motion.manager.style");
        uint substate = r.U32("motion.manager.substate");
        float substateMod = r.F32("motion.manager.substateSpeed");
        uint actions = r.U32("motion.manager.actionCount");
        if (actions > MaxPending)
            throw r.Fail("motion.manager.actionCount", $"{actions} is more than the {MaxPending} read");
        var modifiers = new MotionAndSpeed[Count(ref r, "motion.manager.modifiers.count", MaxModifiers)];
        for (int i = 0; i < modifiers.Length; i++)
            modifiers[i] = new MotionAndSpeed(r.U32($"motion.manager.modifiers[{i}].motion"), r.F32($"motion.manager.modifiers[{i}].speed"));
        uint counter = r.U32("motion.manager.animationCounter");
        var managerPending = new (uint Motion, uint AnimCount)[Count(ref r, "motion.manager.pending.count", MaxPending)];
        for (int i = 0; i < managerPending.Length; i++)
            managerPending[i] = (r.U32($"motion.manager.pending[{i}].motion"), r.U32($"motion.manager.pending[{i}].animCount"));

        var nodes = new Sequence.Node[Count(ref r, "motion.sequence.count", MaxNodes)];
        for (int i = 0; i < nodes.Length; i++)
        {
            string f = $"motion.sequence[{i}]";
            uint id = r.U32(f + ".animation");
            if (!table.Animations.TryGetValue(id, out var animation))
                throw r.Fail(f + ".animation", $"animation 0x{id:X8} is not in motion table 0x{table.Id:X8}");
            int low = Frame(ref r, f + ".lowFrame", animation), high = Frame(ref r, f + ".highFrame", animation);
            float framerate = Bounded(ref r, f + ".framerate", MaxSequenceFramerate, "frames/s");
            nodes[i] = new Sequence.Node { Animation = animation, LowFrame = low, HighFrame = high, Framerate = framerate };
        }
        int firstCyclic = Index(ref r, "motion.sequence.firstCyclic", nodes.Length);
        int current = Index(ref r, "motion.sequence.current", nodes.Length);
        double frameNumber = r.F64("motion.sequence.frameNumber");
        // The frame number lies in the current node's animation (a played range ends one frame past its last, less
        // EPSILON), so a step crosses a bounded number of frames; an empty sequence keeps any small number (unread).
        int frames = nodes.Length == 0 ? MotionTable.MaxFrames : nodes[current].Animation.FrameCount;
        if (!(frameNumber >= (nodes.Length == 0 ? -frames : -1) && frameNumber <= frames))
            throw r.Fail("motion.sequence.frameNumber", nodes.Length == 0
                ? $"{frameNumber} is not within ±{frames}"
                : $"{frameNumber} is not within the current animation 0x{nodes[current].Animation.Id:X8} (-1 to {frames})");
        // The body step's limits on a body's velocity and omega (InputLimits.MaxExtent per second): the sequence's
        // are added to the body's offset every quantum.
        var velocity = BoundedVec(ref r, "motion.sequence.velocity", InputLimits.MaxExtent, "m/s");
        var omega = BoundedVec(ref r, "motion.sequence.omega", InputLimits.MaxExtent, "rad/s");
        if (r.Remaining != 0)
            throw r.Fail("motion", $"{r.Remaining} bytes past the end of the section's data");

        // All read and checked: now the target changes.
        var interp = motion.Interpreter;
        interp.Body = body;
        interp.Raw = raw;
        interp.Interpreted = interpreted;
        interp.Initted = (flags & 1) != 0;
        interp.StandingLongJump = (flags & 2) != 0;
        interp.Autonomous = (flags & 4) != 0;
        interp.JumpExtent = jumpExtent;
        interp.MyRunRate = runRate;
        interp.RestorePending(interpPending);
        var ms = motion.Manager.State;
        ms.Style = style;
        ms.Substate = substate;
        ms.SubstateMod = substateMod;
        ms.ActionCount = (int)actions;
        ms.ClearModifiers();
        for (int i = modifiers.Length - 1; i >= 0; i--)
            ms.AddModifierNoCheck(modifiers[i].Id, modifiers[i].Speed);
        motion.Manager.RestorePending(managerPending, counter);
        motion.AnimationSequence.Restore(nodes, firstCyclic, current, frameNumber, velocity, omega);
    }

    private static float Bounded(ref SnapshotReader r, string field, float limit, string unit)
    {
        float v = r.F32(field);
        if (!(MathF.Abs(v) <= limit))
            throw r.Fail(field, $"{v} is not within ±{limit} {unit}");
        return v;
    }

    private static Vector3 BoundedVec(ref SnapshotReader r, string field, float limit, string unit) =>
        new(Bounded(ref r, field + ".x", limit, unit), Bounded(ref r, field + ".y", limit, unit), Bounded(ref r, field + ".z", limit, unit));

    private static byte Flags(ref SnapshotReader r, string field, byte known)
    {
        byte b = r.U8(field);
        if ((b & ~known) != 0)
            throw r.Fail(field, $"unknown bits 0x{b:X2}");
        return b;
    }

    private static HoldKey Hold(ref SnapshotReader r, string field)
    {
        uint v = r.U32(field);
        if (v > (uint)HoldKey.Run)
            throw r.Fail(field, $"unknown hold key {v}");
        return (HoldKey)v;
    }

    private static int Count(ref SnapshotReader r, string field, int cap)
    {
        uint n = r.U32(field);
        if (n > cap)
            throw r.Fail(field, $"{n} is more than the {cap} read");
        return (int)n;
    }

    // A node index: −1 only for an empty sequence, else within it.
    private static int Index(ref SnapshotReader r, string field, int count)
    {
        int v = (int)r.U32(field);
        if (count == 0 ? v != -1 : (v < 0 || v >= count))
            throw r.Fail(field, $"{v} is not an index of the {count} animations");
        return v;
    }

    private static int Frame(ref SnapshotReader r, string field, Animation animation)
    {
        // Sequence.Append's clamp leaves −1 only for an animation without frames.
        int v = (int)r.U32(field), last = animation.FrameCount - 1;
        if (v < Math.Min(0, last) || v > last)
            throw r.Fail(field, $"{v} is not a frame of animation 0x{animation.Id:X8} ({animation.FrameCount} frames)");
        return v;
    }
}
