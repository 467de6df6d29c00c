using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>An observer that records every event in order, for tests, tools and logs. Allocates; diagnostics only.</summary>
public sealed class TransitionEventLog : ITransitionObserver
{
    private readonly List<TransitionEvent> _events = new();

    /// <summary>The events so far.</summary>
    public IReadOnlyList<TransitionEvent> Events => _events;

    /// <summary>Forgets the events.</summary>
    public void Clear() => _events.Clear();

    /// <inheritdoc />
    public void OnSubStep(int step, Vector3 checkOrigin, Vector3 offset) =>
        _events.Add(new(TransitionEventKind.SubStep, Index: step, Vector: checkOrigin, Vector2: offset));

    /// <inheritdoc />
    public void OnShapeTested(uint entityId, ShadowShapeKind kind, int shapeIndex, TransitionState result) =>
        _events.Add(new(TransitionEventKind.ShapeTested, entityId, kind, shapeIndex, Result: result));

    /// <inheritdoc />
    public void OnShapeSkipped(uint entityId, ShadowShapeKind kind, int shapeIndex, SkipReason reason) =>
        _events.Add(new(TransitionEventKind.ShapeSkipped, entityId, kind, shapeIndex, Reason: reason));

    /// <inheritdoc />
    public void OnObjectNormal(uint entityId, ShadowShapeKind kind, Vector3 normal) =>
        _events.Add(new(TransitionEventKind.ObjectNormal, entityId, kind, Vector: normal));

    /// <inheritdoc />
    public void OnCellChanged(uint fromCell, uint toCell) =>
        _events.Add(new(TransitionEventKind.CellChanged, FromCell: fromCell, ToCell: toCell));

    /// <inheritdoc />
    public void OnStepUp(Vector3 normal, bool succeeded) =>
        _events.Add(new(TransitionEventKind.StepUp, Vector: normal, Succeeded: succeeded));

    /// <inheritdoc />
    public void OnShortcutSkip(ShortcutSkip what, int count) =>
        _events.Add(new(TransitionEventKind.ShortcutSkip, Index: count, Shortcut: what));
}
