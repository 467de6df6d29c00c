using System;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The motion table manager's state of one object (retail MotionState): the style, the substate (the cycle
/// playing) with its speed, the modifiers combined with it (newest first) and the count of actions queued.
/// Fixed storage, reused: no allocation once warm.
/// </summary>
internal sealed class MotionTableState
{
    public uint Style;
    public uint Substate;
    public float SubstateMod = 1f;
    private MotionAndSpeed[] _modifiers = new MotionAndSpeed[4];
    public int ModifierCount { get; private set; }
    public int ActionCount;

    public ref readonly MotionAndSpeed Modifier(int i) => ref _modifiers[i];

    public void ClearModifiers() => ModifierCount = 0;

    /// <summary>MotionState::add_modifier: refused when it is the substate or already a modifier.</summary>
    public bool AddModifier(uint motion, float speed)
    {
        if (Substate == motion)
            return false;
        for (int i = 0; i < ModifierCount; i++)
            if (_modifiers[i].Id == motion)
                return false;
        AddModifierNoCheck(motion, speed);
        return true;
    }

    /// <summary>MotionState::add_modifier_no_check: at the head of the list.</summary>
    public void AddModifierNoCheck(uint motion, float speed)
    {
        if (ModifierCount == _modifiers.Length)
            Array.Resize(ref _modifiers, _modifiers.Length * 2);
        Array.Copy(_modifiers, 0, _modifiers, 1, ModifierCount);
        _modifiers[0] = new MotionAndSpeed(motion, speed);
        ModifierCount++;
    }

    public void RemoveModifierAt(int index)
    {
        Array.Copy(_modifiers, index + 1, _modifiers, index, ModifierCount - index - 1);
        ModifierCount--;
    }
}
