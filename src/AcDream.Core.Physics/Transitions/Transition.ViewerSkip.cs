using System;
using System.Numerics;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

internal sealed partial class Transition
{
    /// <summary>
    /// Shortcut <see cref="Shortcuts.ViewerSteps"/> (not retail). Skips: the camera's leading sub-steps proven to
    /// touch nothing. Same result: such a sub-step's only effect is the check position moving by it (below).
    /// Proof: CameraArmSkipTests, RealCellCameraArmTests, and the suite with shortcuts off.
    /// The camera arm's shortcut: most of a viewer's sub-steps touch nothing.
    /// Such a sub-step, from a path with no contact plane, sliding normal, collision normal or contact (the
    /// camera's start), offsets the check position by the unconstrained sub-step (adjust_offset changes
    /// nothing), inserts it into its cell, finds nothing, keeps the cell (find_cell_list lists only it and
    /// finds the centre in it) and is accepted: the check position becomes current. When the leading
    /// sub-steps of a path starting in an indoor cell, or an outdoor one without a building, are proven so (<see cref="ViewerClearance"/>), this
    /// makes the very same sums of the very same sub-step and leaves the path, the cell list and the
    /// contacts as the walk would; the sub-steps from the first one that may touch something (and always
    /// the shorter last one) are walked. Nothing is skipped when unsure or when the shortcut is off. An observer
    /// is told each passed sub-step as the walk would tell it (<see cref="ITransitionObserver.OnSubStep"/>), then
    /// how many were passed over (<see cref="ITransitionObserver.OnShortcutSkip"/>).
    /// </summary>
    /// <returns>How many sub-steps were passed over (0 to the plan's step count − 1).</returns>
    private int PassClearViewerSteps(in StepPlan plan)
    {
        var path = SpherePath;
        var ci = CollisionInfo;
        int numSteps = plan.NumSteps;
        // The proof serves both camera shortcuts: it runs when either is on.
        if ((Shortcuts & (Shortcuts.ViewerSteps | Shortcuts.ViewerCellSearch)) == 0 || numSteps < 2 || plan.FirstKnown
            || path.InsertType != InsertType.Transition || path.NumSphere != 1
            || (ObjectInfo.State & (ObjectInfoState.FreeRotate | ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != ObjectInfoState.FreeRotate
            || ci.ContactPlaneValid || ci.SlidingNormalValid || ci.CollisionNormalValid || ci.LastKnownContactPlaneValid
            || path.CurCell is not { } cell || !ReferenceEquals(path.CheckCell, cell)
            || path.CurPos.CellId != cell.Id || path.CheckPos.CellId != cell.Id)
            return 0;

        int most = numSteps - 1;
        var perStep = plan.PerStep;
        var start = path.GlobalSphere[0].Center;
        var end = start + perStep * most;
        float size = MathF.Max(VectorMath.MaxAbs(start), VectorMath.MaxAbs(end));
        if (!(size <= ViewerClearance.MaxCoordinate))
            return 0;
        // Each walked sub-step adds in float: at most half an ulp of the sum per axis, ~1.2e-7 × size, plus the
        // sub-step's own rounding. Passed-over steps stay within the drift budget of the ideal centres.
        float drift = 2.5e-7f * (size + 1f);
        most = Math.Min(most, (int)(ViewerClearance.DriftBudget / drift));

        float radius = path.GlobalSphere[0].Radius;
        var land = cell as LandCell;
        float clear, cellAlone = 0f;
        if (land is not null)
            clear = ViewerClearance.ClearFractionOutdoors(World.Objects, land, start, end, radius, ObjectInfo);
        else
            clear = ViewerClearance.ClearFraction(World.Cells, World.Objects, (EnvCell)cell, start, end, radius, ObjectInfo, out cellAlone);
        if (cellAlone > 0f)
        {
            var along = end - start;
            (_aloneCell, _aloneFrom, _aloneAlong, _aloneLength2, _aloneBefore, _aloneRadius)
                = (cell, start, along, Vector3.Dot(along, along), MathF.Min(cellAlone, 1f), radius);
        }
        if ((Shortcuts & Shortcuts.ViewerSteps) == 0)
            return 0;
        // Sub-step i ends at the fraction i / (numSteps − 1) of the segment: pass those strictly before the first doubt.
        int count = float.IsPositiveInfinity(clear) ? most : Math.Min(most, (int)Math.Ceiling((double)clear * (numSteps - 1)) - 1);
        if (count <= 0)
            return 0;

        // What the walked sub-steps would leave: the check position moved by the same sums, accepted. Outdoors
        // each walked sub-step also re-labels the position with its land cell (AdjustCheckPos: the landblock
        // offset, zero, added), and passes only while the cell holds the centre (the sphere centre is the
        // origin: the viewer's sphere sits at the mover's origin).
        var origin = path.CheckPos.Frame.Origin;
        var observer = Observer;
        if (land is not null)
        {
            if (path.LocalSphere[0].Center != Vector3.Zero)
                return 0;
            var relabel = LandDefs.BlockOffset(land.Id, land.Id);
            int held = 0;
            while (held < count)
            {
                var next = origin + perStep + relabel;
                if (!land.ContainsPoint(next))
                    break;
                observer?.OnSubStep(held, origin, perStep);
                origin = next;
                held++;
            }
            count = held;
            if (count <= 0)
                return 0;
        }
        else if (observer is null)
        {
            for (int i = 0; i < count; i++)
                origin += perStep;
        }
        else
        {
            for (int i = 0; i < count; i++)
            {
                observer.OnSubStep(i, origin, perStep);
                origin += perStep;
            }
        }
        // The check spheres are not computed for the moved check position here: accepting it (below) computes
        // the current ones and copies them, as after a walked sub-step (the spheres' caches compare bits).
        path.CheckPos.Frame.Origin = origin;
        path.GlobalOffset = perStep;
        CellArray.Clear();
        CellArray.Add(cell);
        path.HitsInteriorCell = land is null;
        SetCurrentCheckPos();
        observer?.OnShortcutSkip(ShortcutSkip.ViewerSubSteps, count);
        return count;
    }

    // The stretch of the segment the last proof showed keeps the indoor cell alone in the cell search (set by
    // PassClearViewerSteps, cleared at the start of every transition: _aloneCell null): the cell, the segment's
    // start, its vector and squared length, the fraction before which it holds, the sphere's radius.
    private Cell? _aloneCell;
    private Vector3 _aloneFrom, _aloneAlong;
    private float _aloneLength2, _aloneBefore, _aloneRadius;

    /// <summary>
    /// Shortcut <see cref="Shortcuts.ViewerCellSearch"/> (not retail). Skips: a walked camera sub-step's cell
    /// search where the proof holds. Same result: retail's search would list the proven cell alone and find the
    /// centre in it (below). Proof: CameraArmSkipTests, RealCellCameraArmTests, and the suite with shortcuts off.
    /// The walked sub-steps' cell search, passed over where the proof holds.
    /// When the check sphere (one sphere, the proven radius, in the proven cell) lies within
    /// <see cref="ViewerClearance.DriftBudget"/> of a point of the proven stretch, retail find_cell_list would
    /// list only the cell (no portal to the outside within reach, every neighbour outside), mark the path as
    /// hitting an interior cell, and find the centre in the cell: that is what this does. The proof's margin
    /// (<see cref="ViewerClearance.Margin"/>, 1 cm) covers the 4 mm and the rounding of the test itself.
    /// </summary>
    /// An observer is told of each search passed over (<see cref="ITransitionObserver.OnShortcutSkip"/>).
    /// <returns>False when unsure: the caller searches as retail does.</returns>
    private bool CellAloneAtCheck(bool findContaining, out Cell? holder)
    {
        holder = null;
        var path = SpherePath;
        var cell = _aloneCell;
        if (cell is null || (Shortcuts & Shortcuts.ViewerCellSearch) == 0 || !IsViewer
            || path.InsertType != InsertType.Transition || path.NumSphere != 1 || !(_aloneLength2 > 0f)
            || path.CheckPos.CellId != cell.Id)
            return false;
        ref readonly var sphere = ref path.GlobalSphere[0];
        if (sphere.Radius != _aloneRadius)
            return false;
        float t = Vector3.Dot(sphere.Center - _aloneFrom, _aloneAlong) / _aloneLength2;
        if (!(t >= 0f && t < _aloneBefore))
            return false;
        var off = sphere.Center - (_aloneFrom + _aloneAlong * t);
        if (!(Vector3.Dot(off, off) <= ViewerClearance.DriftBudget * ViewerClearance.DriftBudget))
            return false;
        CellArray.Clear();
        CellArray.Add(cell);
        path.HitsInteriorCell = true;
        Observer?.OnShortcutSkip(ShortcutSkip.ViewerCellSearches, 1);
        if (findContaining)
            holder = cell;
        return true;
    }

}
