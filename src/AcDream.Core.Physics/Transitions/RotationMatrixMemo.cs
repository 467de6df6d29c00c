using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The rotation matrix of the last orientation asked for (not retail; changes no result). Retail caches
/// the matrix on each frame; we build it from the quaternion in double (see <see cref="RotationMatrix"/>),
/// which is a pure function of the quaternion's bits, so an orientation seen last time gives the very same
/// matrix without the arithmetic. Along one transition the mover's orientation rarely changes, and the
/// cells and objects tested one after another often share theirs.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.RotationMatrixMemo"/> (not retail). Skips: building the matrix again for the
/// same orientation bits. Same result: the matrix is a pure function of the quaternion's bits. Proof:
/// SpherePathSpheresTests, and the suite with shortcuts off.
/// </remarks>
internal sealed class RotationMatrixMemo(Shortcuts shortcuts)
{
    // False when the shortcut is off: every request builds the matrix (and the up vector) again.
    private readonly bool _on = (shortcuts & Shortcuts.RotationMatrixMemo) != 0;
    private Vector128<int> _for;
    private RotationMatrix _matrix;
    private bool _valid;
    private Vector3 _up;
    private bool _upValid;
    private RotationMatrixLanes _lanes;

    /// <summary>The matrix of <paramref name="frame"/>'s orientation: bit for bit <see cref="Frame.Matrix"/>.</summary>
    public ref readonly RotationMatrix Of(in Frame frame)
    {
        if (!_valid || !frame.OrientationKey.Equals(_for))
            Build(frame);
        return ref _matrix;
    }

    // Out of line: the callers inline Of, and the widening's temporaries would otherwise sit in their frames.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void Build(in Frame frame)
    {
        _matrix = frame.Matrix;
        _for = frame.OrientationKey;
        _valid = _on;
        _upValid = false;
        _lanes = new RotationMatrixLanes(_matrix);
    }

    /// <summary>The matrix of <paramref name="frame"/>'s orientation, widened for side-by-side transforms.</summary>
    public ref readonly RotationMatrixLanes LanesOf(in Frame frame)
    {
        Of(frame);
        return ref _lanes;
    }

    /// <summary>World up in the space of the orientation last asked for (Position::globaltolocalvec of +Z).</summary>
    public Vector3 LocalUp()
    {
        if (!_upValid)
        {
            _up = _matrix.PositionToLocal(Vector3.UnitZ);
            _upValid = _on;
        }
        return _up;
    }
}
