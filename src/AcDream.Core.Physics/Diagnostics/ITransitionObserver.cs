using System.Numerics;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>Why an object's shape was not tested.</summary>
public enum SkipReason : byte
{
    /// <summary>The object has HasPhysicsBsp and no exemption applies: its cylinders and spheres are not tested (retail binary dispatch).</summary>
    BspOnlyDispatch = 0,
    /// <summary>The object collides through its cylinders or spheres, so its BSP parts are not tested.</summary>
    NotBspDispatch = 1,
    /// <summary>The object has cylinders, so its spheres are not tested.</summary>
    HasCylinders = 2,
    /// <summary>The object is ethereal and ignores collisions.</summary>
    EtherealIgnoreCollisions = 3,
    /// <summary>Missile-ignore or the PvP exemption removes the object from collision.</summary>
    Exempt = 4,
    /// <summary>The mover is the camera and the object a creature.</summary>
    ViewerVsCreature = 5,
    /// <summary>The object lies beyond reach of the mover's check spheres, so none of its shapes was tested (not a retail rule: retail would test it and find nothing).</summary>
    OutOfReach = 7,
    /// <summary>The object is ethereal and the path is stepping down.</summary>
    EtherealStepDown = 6,
}

/// <summary>
/// Work the engine passed over where it proved retail's walk would change nothing (not retail; the result is
/// the walk's, bit for bit): what <see cref="ITransitionObserver.OnShortcutSkip"/> counts.
/// </summary>
public enum ShortcutSkip : byte
{
    /// <summary>The camera's leading sub-steps proven to touch nothing (each is also reported as a sub-step).</summary>
    ViewerSubSteps = 0,
    /// <summary>A walked camera sub-step's cell search, answered from the same proof.</summary>
    ViewerCellSearches = 1,
}

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
