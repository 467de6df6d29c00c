using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Diagnostics;

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
