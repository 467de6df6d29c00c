using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>An observer that only counts the work shortcuts passed over (<see cref="ITransitionObserver.OnShortcutSkip"/>).</summary>
internal sealed class ShortcutCounter : ITransitionObserver
{
    /// <summary>Camera sub-steps passed over since the last <see cref="Clear"/>.</summary>
    public int ViewerSubSteps { get; private set; }
    /// <summary>Walked camera sub-steps' cell searches passed over since the last <see cref="Clear"/>.</summary>
    public int ViewerCellSearches { get; private set; }

    public void Clear() => (ViewerSubSteps, ViewerCellSearches) = (0, 0);

    public void OnShortcutSkip(ShortcutSkip what, int count)
    {
        if (what == ShortcutSkip.ViewerSubSteps)
            ViewerSubSteps += count;
        else
            ViewerCellSearches += count;
    }

    public void OnSubStep(int step, Vector3 checkOrigin, Vector3 offset) { }
    public void OnShapeTested(uint entityId, ShadowShapeKind kind, int shapeIndex, TransitionState result) { }
    public void OnShapeSkipped(uint entityId, ShadowShapeKind kind, int shapeIndex, SkipReason reason) { }
    public void OnObjectNormal(uint entityId, ShadowShapeKind kind, Vector3 normal) { }
    public void OnCellChanged(uint fromCell, uint toCell) { }
    public void OnStepUp(Vector3 normal, bool succeeded) { }
}
