using System.Numerics;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The last rotation interpolated between two orientations (not retail; changes no result). Each
/// sub-step turns the check position part of the way from the begin to the end orientation (retail
/// Frame::interpolate_rotation, normalized in double); a mover that keeps its heading, or moves in one
/// sub-step per frame, asks for the same inputs frame after frame, and the result is a pure function of
/// their bits.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.RotationInterpolationMemo"/> (not retail). Skips: interpolating and
/// normalizing again for the same begin and end orientation bits and fraction. Same result: a pure function of
/// those bits. Proof: RememberedWorkTests.AMoverTurningAsItMoves_EndsFacingTheTarget, and the suite with shortcuts off.
/// </remarks>
internal sealed class RotationInterpolationMemo(Shortcuts shortcuts)
{
    // False when the shortcut is off: every request interpolates again.
    private readonly bool _on = (shortcuts & Shortcuts.RotationInterpolationMemo) != 0;
    private Vector128<int> _from, _to;
    private float _t;
    private Quaternion _result;
    private bool _valid, _resultIsValid;

    /// <summary>
    /// Bit for bit <see cref="Frame.InterpolatedRotation"/> of the same arguments, and whether
    /// <see cref="Frame.SetRotation"/> would take it (Frame::IsValid; else the frame keeps its rotation).
    /// </summary>
    public bool Between(in Frame from, in Frame to, float t, out Quaternion result)
    {
        var fromKey = from.OrientationKey;
        var toKey = to.OrientationKey;
        if (!_valid || !fromKey.Equals(_from) || !toKey.Equals(_to) || System.BitConverter.SingleToInt32Bits(t) != System.BitConverter.SingleToInt32Bits(_t))
        {
            _result = Frame.InterpolatedRotation(from, to, t);
            _resultIsValid = Frame.IsValidRotation(_result);
            _from = fromKey;
            _to = toKey;
            _t = t;
            _valid = _on;
        }
        result = _result;
        return _resultIsValid;
    }
}
