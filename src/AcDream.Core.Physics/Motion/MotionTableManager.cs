using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Chooses what an object's sequence plays (retail CMotionTable's DoObjectMotion / GetObjectSequence /
/// StopObjectMotion family, canim/CMTable.c, and MotionTableManager, cphysobj/CMTableManager.c): cycles,
/// the links into them, and the modifiers combined with them, following the table's bitfield rules; and the
/// queue of motions waiting for their animations to finish. One per object; reuses its storage.
/// </summary>
internal sealed class MotionTableManager
{
    private readonly MotionTable _table;
    private readonly Sequence _sequence;
    private readonly PendingQueue<(uint Motion, uint AnimCount)> _pending = new();
    private uint _animationCounter;

    public MotionTableManager(MotionTable table, Sequence sequence)
    {
        _table = table;
        _sequence = sequence;
    }

    public MotionTableState State { get; } = new();

    // The pending motions and the animation counter, for a snapshot (read, and replaced whole by a load).
    internal int PendingCount => _pending.Count;
    internal uint AnimationCounter => _animationCounter;
    internal (uint Motion, uint AnimCount) PendingAt(int i) => _pending[i];
    internal void RestorePending(ReadOnlySpan<(uint Motion, uint AnimCount)> items, uint animationCounter)
    {
        _pending.Restore(items);
        _animationCounter = animationCounter;
    }

    /// <summary>Called for every motion whose animations are done (MotionTableManager → CPhysicsObj::MotionDone → the interpreter).</summary>
    public MotionInterpreter? Interpreter { get; set; }

    // ---- MotionTableManager ----

    /// <summary>MotionTableManager::initialize_state: the default style's default cycle.</summary>
    public void InitializeState()
    {
        uint count = 0;
        SetDefaultState(ref count);
        AddToQueue(MotionCommand.Ready, count);
    }

    /// <summary>PerformMovement for an interpreted command; false when the table has nothing for it.</summary>
    public bool DoMotion(uint motion, float speed)
    {
        uint count = 0;
        if (!GetObjectSequence(motion, speed, ref count, stopModifiers: false))
            return false;
        AddToQueue(motion, count);
        return true;
    }

    /// <summary>PerformMovement for a stop of an interpreted command.</summary>
    public bool StopMotion(uint motion)
    {
        uint count = 0;
        if (!StopSequenceMotion(motion, 1f, ref count))
            return false;
        AddToQueue(MotionCommand.Ready, count);
        return true;
    }

    /// <summary>PerformMovement for StopCompletely.</summary>
    public void StopCompletely()
    {
        uint count = 0;
        StopObjectCompletely(ref count);
        AddToQueue(MotionCommand.Ready, count);
    }

    /// <summary>MotionTableManager::AnimationDone: a link animation ended; motions whose animations are all done complete.</summary>
    public void AnimationDone(bool success)
    {
        if (_pending.Count == 0)
            return;
        _animationCounter++;
        while (_pending.Count > 0)
        {
            var entry = _pending[0];
            if (entry.AnimCount > _animationCounter)
                break;
            if ((entry.Motion & MotionCommandMask.Action) != 0 && State.ActionCount > 0)
                State.ActionCount--;
            Interpreter?.MotionDone(success);
            _animationCounter -= entry.AnimCount;
            _pending.RemoveFirst();
        }
        if (_animationCounter != 0 && _pending.Count == 0)
            _animationCounter = 0;
    }

    /// <summary>MotionTableManager::CheckForCompletedMotions (UseTime): motions that needed no animation complete.</summary>
    public void CheckForCompletedMotions()
    {
        while (_pending.Count > 0 && _pending[0].AnimCount == 0)
        {
            uint motion = _pending[0].Motion;
            if ((motion & MotionCommandMask.Action) != 0 && State.ActionCount > 0)
                State.ActionCount--;
            Interpreter?.MotionDone(true);
            _pending.RemoveFirst();
        }
    }

    /// <summary>MotionTableManager::HandleEnterWorld (CPhysicsObj::RemoveLinkAnimations): links dropped, every pending motion ends unsuccessfully.</summary>
    public void RemoveLinkAnimations()
    {
        _sequence.RemoveAllLinkAnimations();
        // Each call raises the animation counter by one, so every entry completes in the end.
        while (_pending.Count > 0)
            AnimationDone(false);
    }

    private void AddToQueue(uint motion, uint count)
    {
        _pending.Add((motion, count));
        RemoveRedundantLinks();
    }

    // MotionTableManager::remove_redundant_links: a motion queued again while its earlier entry's links are still
    // waiting drops the links queued since then.
    // Retail looks only at the newest entry with animations (CMTableManager.c:325-393); ACE goes on to older ones.
    private void RemoveRedundantLinks()
    {
        for (int i = _pending.Count - 1; i >= 0; i--)
        {
            var entry = _pending[i];
            if (entry.AnimCount == 0)
                continue;
            if ((entry.Motion & MotionCommandMask.Substate) == 0 || (entry.Motion & MotionCommandMask.Modifier) != 0)
            {
                if ((entry.Motion & MotionCommandMask.Style) != 0)
                    RemoveRedundantLinksBefore(i, styleEntry: true);
            }
            else
            {
                RemoveRedundantLinksBefore(i, styleEntry: false);
            }
            return;
        }
    }

    private bool RemoveRedundantLinksBefore(int index, bool styleEntry)
    {
        uint motion = _pending[index].Motion;
        uint blocking = styleEntry ? 0x70000000u : 0xB0000000u;
        for (int p = index - 1; p >= 0; p--)
        {
            var prev = _pending[p];
            if (prev.Motion == motion && (styleEntry || prev.AnimCount != 0))
            {
                TruncateAnimationList(p);
                return true;
            }
            if (prev.AnimCount != 0 && (prev.Motion & blocking) != 0)
                return true;
        }
        return false;
    }

    // MotionTableManager::truncate_animation_list: the entries after `index` give up their animations, which leave the sequence.
    private void TruncateAnimationList(int index)
    {
        uint total = 0;
        for (int i = _pending.Count - 1; i > index; i--)
        {
            total += _pending[i].AnimCount;
            _pending[i].AnimCount = 0;
        }
        _sequence.RemoveLinkAnimations(total);
    }

    // ---- CMotionTable ----

    private bool SetDefaultState(ref uint count)
    {
        if (!_table.TryStyleDefault(_table.DefaultStyle, out uint substate))
            return false;
        var cycle = _table.Cycle(MotionTable.CycleKey(_table.DefaultStyle, substate));
        if (cycle is null)
            return false;
        State.ClearModifiers();
        State.ActionCount = 0;
        count = (uint)cycle.Anims.Length - 1;
        State.Style = _table.DefaultStyle;
        State.Substate = substate;
        State.SubstateMod = 1f;
        _sequence.ClearPhysics();
        _sequence.ClearAnimations();
        AddMotion(cycle, State.SubstateMod);
        return true;
    }

    private uint StyleDefault(uint style) => _table.TryStyleDefault(style, out uint s) ? s : 0;

    // CMotionTable::GetObjectSequence: a style change, a new cycle (with the links into it), an action, or a modifier.
    private bool GetObjectSequence(uint motion, float speed, ref uint count, bool stopModifiers)
    {
        var state = State;
        count = 0;
        if (state.Style == 0 || state.Substate == 0)
            return false;
        uint styleDefault = StyleDefault(state.Style);
        if (motion == styleDefault && !stopModifiers && (state.Substate & MotionCommandMask.Modifier) != 0)
            return true;

        if ((motion & MotionCommandMask.Style) != 0)
        {
            if (state.Style == motion)
                return true;
            MotionData? leave = null;
            if (styleDefault != state.Substate)
                leave = GetLink(state.Style, state.Substate, state.SubstateMod, styleDefault, speed);
            // The new style's default substate (CMTable.c:515-576; ACE keys the cycle by the old style's default).
            uint newDefault = StyleDefault(motion);
            if (newDefault != 0)
            {
                var cycle = _table.Cycle(MotionTable.CycleKey(motion, newDefault));
                if (cycle is not null)
                {
                    if ((cycle.Bitfield & 1) != 0)
                        state.ClearModifiers();
                    var link = GetLink(state.Style, styleDefault, state.SubstateMod, motion, speed);
                    MotionData? enter = null;
                    if (link is null && state.Style != motion)
                    {
                        link = GetLink(state.Style, styleDefault, 1f, _table.DefaultStyle, 1f);
                        enter = GetLink(_table.DefaultStyle, StyleDefault(_table.DefaultStyle), 1f, motion, 1f);
                    }
                    _sequence.ClearPhysics();
                    _sequence.RemoveCyclicAnims();
                    AddMotion(leave, speed);
                    AddMotion(link, speed);
                    AddMotion(enter, speed);
                    AddMotion(cycle, speed);
                    state.Substate = newDefault;
                    state.Style = motion;
                    state.SubstateMod = speed;
                    ReModify();
                    count = (uint)(AnimCount(leave) + AnimCount(link) + AnimCount(enter) + AnimCount(cycle) - 1);
                    return true;
                }
            }
        }

        if ((motion & MotionCommandMask.Substate) != 0)
        {
            uint id = motion & MotionCommandMask.Command;
            var cycle = _table.Cycle(MotionTable.CycleKey(state.Style, id)) ?? _table.Cycle(MotionTable.CycleKey(_table.DefaultStyle, id));
            if (cycle is not null && IsAllowed(motion, cycle))
            {
                if (motion == state.Substate && _sequence.HasAnims && SameSign(speed, state.SubstateMod))
                {
                    // The same cycle at a new speed: retime it and swap its physics.
                    ChangeCycleSpeed(state.SubstateMod, speed);
                    SubtractMotion(cycle, state.SubstateMod);
                    CombineMotion(cycle, speed);
                    state.SubstateMod = speed;
                    return true;
                }
                if ((cycle.Bitfield & 1) != 0)
                    state.ClearModifiers();
                var link = GetLink(state.Style, state.Substate, state.SubstateMod, motion, speed);
                MotionData? enter = null;
                if (link is null || !SameSign(speed, state.SubstateMod))
                {
                    // Through the style's default substate: out of the current cycle, then into the new one.
                    link = GetLink(state.Style, state.Substate, state.SubstateMod, styleDefault, 1f);
                    enter = GetLink(state.Style, styleDefault, 1f, motion, speed);
                }
                _sequence.ClearPhysics();
                _sequence.RemoveCyclicAnims();
                if (enter is not null)
                {
                    AddMotion(link, state.SubstateMod);
                    AddMotion(enter, speed);
                }
                else
                {
                    float linkSpeed = state.SubstateMod < 0f && speed > 0f ? -speed : speed;
                    AddMotion(link, linkSpeed);
                }
                AddMotion(cycle, speed);
                if (state.Substate != motion && (state.Substate & MotionCommandMask.Modifier) != 0 && styleDefault != motion)
                    state.AddModifierNoCheck(state.Substate, state.SubstateMod);
                state.SubstateMod = speed;
                state.Substate = motion;
                ReModify();
                count = (uint)(AnimCount(cycle) + AnimCount(link) + AnimCount(enter) - 1);
                return true;
            }
        }

        if ((motion & MotionCommandMask.Action) != 0)
        {
            uint cycleKey = MotionTable.CycleKey(state.Style, state.Substate);
            var cycle = _table.Cycle(cycleKey);
            if (cycle is not null)
            {
                var link = GetLink(state.Style, state.Substate, state.SubstateMod, motion, speed);
                if (link is not null)
                {
                    state.ActionCount++;
                    _sequence.ClearPhysics();
                    _sequence.RemoveCyclicAnims();
                    AddMotion(link, speed);
                    AddMotion(cycle, state.SubstateMod);
                    ReModify();
                    count = (uint)AnimCount(link);
                    return true;
                }
                var toDefault = GetLink(state.Style, state.Substate, state.SubstateMod, styleDefault, 1f);
                if (toDefault is not null)
                {
                    link = GetLink(state.Style, styleDefault, 1f, motion, speed);
                    if (link is not null)
                    {
                        var back = GetLink(state.Style, styleDefault, 1f, state.Substate, state.SubstateMod);
                        state.ActionCount++;
                        _sequence.ClearPhysics();
                        _sequence.RemoveCyclicAnims();
                        AddMotion(toDefault, 1f);
                        AddMotion(link, speed);
                        AddMotion(back, 1f);
                        AddMotion(cycle, state.SubstateMod);
                        ReModify();
                        count = (uint)(AnimCount(toDefault) + AnimCount(link) + AnimCount(back)); // ACE counts toDefault's twice
                        return true;
                    }
                }
            }
        }

        if ((motion & MotionCommandMask.Modifier) != 0)
        {
            uint styleKey = state.Style << 16;
            var cycle = _table.Cycle(styleKey | (state.Substate & MotionCommandMask.Command));
            if (cycle is not null && (cycle.Bitfield & 1) == 0)
            {
                var modifier = _table.Modifier(styleKey | (motion & MotionCommandMask.Command)) ?? _table.Modifier(motion & MotionCommandMask.Command);
                if (modifier is not null)
                {
                    if (!state.AddModifier(motion, speed))
                    {
                        StopSequenceMotion(motion, 1f, ref count);
                        if (!state.AddModifier(motion, speed))
                            return false;
                    }
                    CombineMotion(modifier, speed);
                    return true;
                }
            }
        }
        return false;
    }

    // CMotionTable::StopSequenceMotion: stopping the substate goes back to the style's default; stopping a modifier takes its physics away.
    private bool StopSequenceMotion(uint motion, float speed, ref uint count)
    {
        var state = State;
        count = 0;
        if ((motion & MotionCommandMask.Substate) != 0 && state.Substate == motion)
        {
            GetObjectSequence(StyleDefault(state.Style), 1f, ref count, stopModifiers: true);
            return true;
        }
        if ((motion & MotionCommandMask.Modifier) == 0)
            return false;
        for (int i = 0; i < state.ModifierCount; i++)
        {
            var m = state.Modifier(i);
            if (m.Id != motion)
                continue;
            var data = _table.Modifier(MotionTable.CycleKey(state.Style, motion)) ?? _table.Modifier(motion & MotionCommandMask.Command);
            if (data is null)
                return false;
            SubtractMotion(data, m.Speed);
            state.RemoveModifierAt(i);
            return true;
        }
        return false;
    }

    // CMotionTable::StopObjectCompletely: every modifier, then the substate.
    private bool StopObjectCompletely(ref uint count)
    {
        bool any = false;
        while (State.ModifierCount > 0)
        {
            var m = State.Modifier(0);
            if (StopSequenceMotion(m.Id, m.Speed, ref count))
                any = true;
            else
                State.RemoveModifierAt(0); // retail would loop forever on a modifier the table lacks; drop it instead
        }
        return StopSequenceMotion(State.Substate, State.SubstateMod, ref count) || any;
    }

    // CMotionTable::re_modify: after a new cycle, the modifiers are taken off and applied again, head first,
    // as many times as there were modifiers (retail re-applies the head each time).
    private void ReModify()
    {
        // Not retail: a bound on re_modify's nesting. A table whose turn or sidestep cycle may replace a moving
        // substate (bitfield without 2) makes GetObjectSequence push the old substate back as a modifier, whose
        // re-giving makes it the substate again, and so on: retail's CMotionTable::re_modify ↔ GetObjectSequence
        // would recurse until its stack overflows. Past MaxReModifyDepth the remaining modifiers stay listed as
        // they are (their physics already in the sequence) instead of crashing the process.
        if (_reModifyDepth >= MaxReModifyDepth)
            return;
        _reModifyDepth++;
        try
        {
            int n = State.ModifierCount;
            for (int k = 0; k < n && State.ModifierCount > 0; k++)
            {
                var head = State.Modifier(0);
                State.RemoveModifierAt(0);
                uint ignored = 0;
                GetObjectSequence(head.Id, head.Speed, ref ignored, stopModifiers: false);
            }
        }
        finally
        {
            _reModifyDepth--;
        }
    }

    /// <summary>How deep re_modify may nest (see <see cref="ReModify"/>); a real table nests once.</summary>
    internal const int MaxReModifyDepth = 16;
    private int _reModifyDepth;

    // CMotionTable::get_link: forwards, the link from the substate to the motion (else the style's link to it);
    // with a negative speed, the link the other way round (else from the substate to the style's default).
    private MotionData? GetLink(uint style, uint substate, float substateSpeed, uint motion, float speed)
    {
        if (speed < 0f || substateSpeed < 0f)
        {
            var reverse = _table.Link(MotionTable.CycleKey(style, motion), substate);
            if (reverse is not null)
                return reverse;
            if (_table.TryStyleDefault(style, out uint styleDefault) && _table.HasLinksFrom(MotionTable.CycleKey(style, substate), out var inner))
                return inner.TryGetValue(styleDefault, out var toDefault) ? toDefault : null;
            return null;
        }
        var direct = _table.Link(MotionTable.CycleKey(style, substate), motion);
        if (direct is not null)
            return direct;
        return _table.HasLinksFrom(style << 16, out var styleLinks) && styleLinks.TryGetValue(motion, out var any) ? any : null;
    }

    // CMotionTable::is_allowed: bitfield 2 lets a cycle be entered only from the style's default substate (or itself).
    private bool IsAllowed(uint motion, MotionData cycle) =>
        (cycle.Bitfield & 2) == 0 || motion == State.Substate || StyleDefault(State.Style) == State.Substate;

    private void ChangeCycleSpeed(float oldSpeed, float newSpeed)
    {
        if (MathF.Abs(oldSpeed) > PhysicsConstants.Epsilon)
            _sequence.MultiplyCyclicFramerate(newSpeed / oldSpeed);
        else if (MathF.Abs(newSpeed) < PhysicsConstants.Epsilon)
            _sequence.MultiplyCyclicFramerate(0f);
    }

    // CMotionTable::add_motion: the motion's physics replace the sequence's; its animations are appended at the speed.
    private void AddMotion(MotionData? data, float speed)
    {
        if (data is null)
            return;
        _sequence.Velocity = data.Velocity * speed;
        _sequence.Omega = data.Omega * speed;
        var anims = data.AnimArray;
        for (int i = 0; i < anims.Length; i++)
            _sequence.Append(_table.Animation(anims[i].AnimationId), anims[i], speed);
    }

    private void CombineMotion(MotionData data, float speed) => _sequence.CombinePhysics(data.Velocity * speed, data.Omega * speed);

    private void SubtractMotion(MotionData data, float speed) => _sequence.SubtractPhysics(data.Velocity * speed, data.Omega * speed);

    // CMTable.c:66-84 same_sign: zero counts as positive (ACE's Math.Sign gives zero a sign of its own).
    internal static bool SameSign(float a, float b) => a >= 0f == b >= 0f;

    private static int AnimCount(MotionData? data) => data is null ? 0 : data.Anims.Length;
}
