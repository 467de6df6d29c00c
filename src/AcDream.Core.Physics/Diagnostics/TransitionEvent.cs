using System.Numerics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>One diagnostics event; fields not used by its kind are zero.</summary>
public readonly record struct TransitionEvent(
    TransitionEventKind Kind,
    uint EntityId = 0,
    ShadowShapeKind ShapeKind = ShadowShapeKind.Bsp,
    int Index = 0,
    TransitionState Result = TransitionState.Invalid,
    SkipReason Reason = SkipReason.BspOnlyDispatch,
    Vector3 Vector = default,
    Vector3 Vector2 = default,
    uint FromCell = 0,
    uint ToCell = 0,
    bool Succeeded = false,
    ShortcutSkip Shortcut = ShortcutSkip.ViewerSubSteps);
