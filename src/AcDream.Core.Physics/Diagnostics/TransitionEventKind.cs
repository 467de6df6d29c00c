using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>The kind of a recorded diagnostics event.</summary>
public enum TransitionEventKind : byte
{
    /// <summary>A sub-step began.</summary>
    SubStep,
    /// <summary>An object's shape was tested.</summary>
    ShapeTested,
    /// <summary>An object's shape was skipped.</summary>
    ShapeSkipped,
    /// <summary>An object's shape set the collision normal.</summary>
    ObjectNormal,
    /// <summary>The check position changed cell.</summary>
    CellChanged,
    /// <summary>A step up was tried.</summary>
    StepUp,
    /// <summary>A shortcut passed over work (<see cref="TransitionEvent.Shortcut"/>; how much in <see cref="TransitionEvent.Index"/>).</summary>
    ShortcutSkip,
}
