using System;

namespace AcDream.Core.Physics;

/// <summary>
/// The engine's shortcuts: work it passes over, or answers from memory, where it has proven that retail's
/// walk would change nothing (not retail: retail does the work). Each changes no result bit; each site carries
/// the same header (what it skips, why no result changes, the test that proves it), and the whole test suite
/// runs with all of them off as well as on (<see cref="None"/> is retail's path, step for step). Read once, at
/// construction, into the transition, its path and contacts, the engine and the cell graph
/// (<see cref="ShortcutSettings.Default"/>), so a test costs one load of a field already at hand.
/// </summary>
[Flags]
internal enum Shortcuts
{
    /// <summary>No shortcut: every step of retail's path is walked.</summary>
    None = 0,
    /// <summary>The engine answers a request bit for bit the same as the one it last refused from memory (<c>RefusalMemo</c>).</summary>
    RefusalMemo = 1 << 0,
    /// <summary>A move refused before its first sub-step is answered without setting up the path (<c>Transition.RefusesBeforeFirstStep</c>).</summary>
    EarlyRefusal = 1 << 1,
    /// <summary>The step count and first constrained sub-step worked out for the refusal are reused (<c>StepPlan</c>).</summary>
    StepPlan = 1 << 2,
    /// <summary>Only the objects whose reach box meets a region around the check spheres are tested (<c>ObjectCull</c>).</summary>
    ObjectCull = 1 << 3,
    /// <summary>A crowded cell's objects are found through an index sorted by their reach boxes (<c>CellObjectIndex</c>).</summary>
    CellObjectIndex = 1 << 4,
    /// <summary>Each candidate's reach box is tested against the check spheres' own box before its shapes (<c>ObjectCollisions.FindInCell</c>).</summary>
    ReachBoxPreCheck = 1 << 5,
    /// <summary>A part whose polygons' box no check sphere reaches is not queried in a move (<c>PartCollision.MayTouchPolygons</c>).</summary>
    PolygonBoxPreCheck = 1 << 6,
    /// <summary>A cylinder test sets only the local-space placement retail's sphere caching leaves read (<c>SpherePath.CacheLocalSpaceForCylinder</c>).</summary>
    CylinderLocalSpace = 1 << 7,
    /// <summary>A placement test of the BSP sphere 0 was just found touching is answered Collided (<c>SolidHitMemo</c>).</summary>
    SolidHitMemo = 1 << 8,
    /// <summary>The last normalization of the same input bits is reused (<c>UnitMemo</c>).</summary>
    UnitMemo = 1 << 9,
    /// <summary>The last rotation matrix of the same orientation bits is reused (<c>RotationMatrixMemo</c>).</summary>
    RotationMatrixMemo = 1 << 10,
    /// <summary>The last interpolated rotation of the same input bits is reused (<c>RotationInterpolationMemo</c>).</summary>
    RotationInterpolationMemo = 1 << 11,
    /// <summary>An outdoor cell search whose spheres lie well inside a cell without a building lists that cell alone (<c>CellGraph.AloneInSquare</c>).</summary>
    LandCellAlone = 1 << 12,
    /// <summary>The camera's leading sub-steps proven to touch nothing are passed over (<c>Transition.PassClearViewerSteps</c>).</summary>
    ViewerSteps = 1 << 13,
    /// <summary>A walked camera sub-step's cell search is answered from the proof (<c>Transition.CellAloneAtCheck</c>).</summary>
    ViewerCellSearch = 1 << 14,
    /// <summary>The mover's points at the current and last check positions are kept while the position's bits stay (<c>SpherePath.PointsAt</c>).</summary>
    PointsMemo = 1 << 15,
    /// <summary>Every shortcut (the default).</summary>
    All = (1 << 16) - 1,
}
