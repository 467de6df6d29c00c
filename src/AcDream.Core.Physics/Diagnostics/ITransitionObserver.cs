using System.Numerics;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>
/// Structured diagnostics of a transition. Set <see cref="Transition.Observer"/> to receive them; with no
/// observer (the default) nothing is built and nothing allocates. Callbacks run on the transition's thread.
/// The observer watches the path the engine runs without it: the same shortcuts are taken, and what they
/// leave untested is reported (objects out of reach as <see cref="SkipReason.OutOfReach"/>, the rest through
/// <see cref="OnShortcutSkip"/>).
/// </summary>
public interface ITransitionObserver
{
    /// <summary>A sub-step begins at <paramref name="checkOrigin"/> with the adjusted motion <paramref name="offset"/>.</summary>
    void OnSubStep(int step, Vector3 checkOrigin, Vector3 offset);
    /// <summary>A shape of an object was tested, with its result.</summary>
    void OnShapeTested(uint entityId, ShadowShapeKind kind, int shapeIndex, TransitionState result);
    /// <summary>A shape of an object was skipped.</summary>
    void OnShapeSkipped(uint entityId, ShadowShapeKind kind, int shapeIndex, SkipReason reason);
    /// <summary>A collision normal was recorded from an object's shape.</summary>
    void OnObjectNormal(uint entityId, ShadowShapeKind kind, Vector3 normal);
    /// <summary>The check position moved from one cell to another.</summary>
    void OnCellChanged(uint fromCell, uint toCell);
    /// <summary>A step up was tried against an obstacle with this normal.</summary>
    void OnStepUp(Vector3 normal, bool succeeded);
    /// <summary>A shortcut passed over <paramref name="count"/> pieces of work of the kind <paramref name="what"/> (does nothing unless implemented).</summary>
    void OnShortcutSkip(ShortcutSkip what, int count) { }
}
