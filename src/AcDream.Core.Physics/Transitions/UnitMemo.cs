using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The last vector given to <see cref="VectorMath.NormalizeCheckSmall"/>, by its bits, and what came out.
/// A mover sliding along a wall normalizes the same vectors frame after frame (the carried sliding normal,
/// the line where the wall meets the floor), and the double square root and division are among the longest
/// waits of such a frame. Not retail; the same input bits give the same output bits, so no result changes.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.UnitMemo"/> (not retail). Skips: the double square root and division of a
/// normalization asked for again with the same input bits. Same result: the normalization is a pure function of
/// the input's bits. Proof: UnitMemoTests, and the suite with shortcuts off.
/// </remarks>
internal struct UnitMemo
{
    private Vector3 _input;
    private Vector3 _unit;
    private bool _tooShort;
    private bool _valid;
    // Set when the shortcut is off: the memo keeps nothing, so every call normalizes.
    private bool _off;

    /// <summary>A memo that remembers only when <paramref name="shortcuts"/> holds <see cref="Shortcuts.UnitMemo"/>.</summary>
    public static UnitMemo For(Shortcuts shortcuts) => new() { _off = (shortcuts & Shortcuts.UnitMemo) == 0 };

    /// <summary><see cref="VectorMath.NormalizeCheckSmall"/>, answered from memory for the same input bits.</summary>
    public bool NormalizeCheckSmall(ref Vector3 v)
    {
        if (_valid && VectorMath.SameBits(v, _input))
        {
            v = _unit;
            return _tooShort;
        }
        _input = v;
        _tooShort = VectorMath.NormalizeCheckSmall(ref v);
        _unit = v;
        _valid = !_off;
        return _tooShort;
    }
}
