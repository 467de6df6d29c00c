using System.Numerics;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The last move an engine refused before its first sub-step (see
/// <see cref="Transition.RefusesBeforeFirstStep"/>), to answer the same request again without redoing
/// the work (not retail; changes no result). A client whose player pushes into a wall sends the very
/// same request every frame: the state the refusal handed back, and the same step towards the wall.
/// The refusal depends only on the request: the mover (immutable), its state, the target and the
/// engine's sub-step scale. The input checks passed for it and still pass while the world removes no
/// cell (the memo is keyed by the graph's <see cref="World.CellGraph.RemovalCount"/>: after a landblock
/// is unloaded the request is checked again), and no object or cell geometry is consulted before the
/// first sub-step.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.RefusalMemo"/> (not retail; taken in <c>PhysicsEngine.Move</c>). Skips: checking
/// and refusing again a request bit for bit the same as the last one refused. Same result: the refusal is a
/// function of the request alone (above). Proof: RefusedMoveTests (each way the request can differ), and the
/// suite with shortcuts off.
/// </remarks>
internal struct RefusalMemo
{
    private bool _valid;
    private MoverDescription? _mover;
    private MoverState _state;
    private Position _target;
    private int _removals;

    /// <summary>Forgets the refusal (the engine's settings changed).</summary>
    public void Clear()
    {
        _valid = false;
        _mover = null;
    }

    /// <summary>Remembers a refused request.</summary>
    public void Remember(MoverDescription mover, in MoverState state, in Position target, int removals)
    {
        _removals = removals;
        _mover = mover;
        _state = state;
        _target = target;
        _valid = true;
    }

    /// <summary>True when this request is, bit for bit, the one last refused.</summary>
    public readonly bool Matches(MoverDescription mover, in MoverState state, in Position target, int removals) =>
        _valid && removals == _removals && ReferenceEquals(mover, _mover) && Position.SameBits(target, _target) && SameBits(state, _state);

    private static bool SameBits(in MoverState a, in MoverState b) =>
        Position.SameBits(a.Position, b.Position)
        && a.Contact == b.Contact && a.OnWalkable == b.OnWalkable
        && a.ContactPlaneCellId == b.ContactPlaneCellId && a.ContactPlaneIsWater == b.ContactPlaneIsWater
        && Bits(a.ContactPlane.Normal, a.ContactPlane.D).Equals(Bits(b.ContactPlane.Normal, b.ContactPlane.D))
        && a.SlidingNormalValid == b.SlidingNormalValid
        && VectorMath.SameBits(a.SlidingNormal, b.SlidingNormal);

    private static Vector128<int> Bits(Vector3 v, float w) => new Vector4(v, w).AsVector128().AsInt32();
}
