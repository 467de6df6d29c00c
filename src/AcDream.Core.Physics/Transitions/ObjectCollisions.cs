using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// Collides a transition with the objects of one cell (retail CObjCell::find_obj_collisions and
/// CPhysicsObj::find_obj_collisions), through the retail dispatch ladder.
/// </summary>
internal static class ObjectCollisions
{
    /// <summary>
    /// Retail's binary choice on HAS_PHYSICS_BSP_PS (acclient CPhysicsObj::FindObjCollisions; ACE
    /// PhysicsObj.cs): an object with the bit collides through its parts' BSPs only — its cylspheres and
    /// spheres are never tested — unless the mover is a missile that ignores it or the PvP exemption applies.
    /// </summary>
    public static bool BspOnlyDispatch(PhysicsState targetState, bool missileIgnore, bool exemption) =>
        (targetState & PhysicsState.HasPhysicsBsp) != 0 && !missileIgnore && !exemption;

    /// <summary>
    /// The kind of shape an object collides by for a mover with neither a missile's ignore nor the PvP exemption
    /// (the queries, the outline and the viewer): the dispatch ladder of FindObjectCollisions — its parts'
    /// BSPs when it has HAS_PHYSICS_BSP, else its cylspheres, else its spheres.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static ShadowShapeKind PlainDispatchRung(in ShadowEntry head) =>
        BspOnlyDispatch(head.State, missileIgnore: false, exemption: false) ? ShadowShapeKind.Bsp
            : head.CylSphereCount > 0 ? ShadowShapeKind.Cylinder : ShadowShapeKind.Sphere;

    /// <summary>
    /// The PvP exemption: two players pass through each other (nothing is tested) unless either is
    /// impenetrable or they are both PK or both PK-lite (retail CPhysicsObj::FindObjCollisions, acclient
    /// 0x0050F050; ACE names it `exemption`).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool PvpExemption(ObjectInfoState mover, ShadowFlags target)
    {
        if ((target & ShadowFlags.IsPlayer) == 0 || (mover & ObjectInfoState.IsPlayer) == 0)
            return false;
        if ((mover & ObjectInfoState.IsImpenetrable) != 0 || (target & ShadowFlags.IsImpenetrable) != 0)
            return false;
        if ((mover & ObjectInfoState.IsPK) != 0 && (target & ShadowFlags.IsPK) != 0)
            return false;
        if ((mover & ObjectInfoState.IsPKLite) != 0 && (target & ShadowFlags.IsPKLite) != 0)
            return false;
        return true;
    }

    /// <summary>
    /// Retail OBJECTINFO::missile_ignore: a missile object is ignored by every mover; a missile mover
    /// ignores any weenie object other than its target that is ethereal, or (when it has a target) is a
    /// creature. ACE's "two-way" variant, which lets a player be hit by a missile aimed at it, is not used.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool MissileIgnore(ObjectInfo mover, uint targetId, PhysicsState targetState, ShadowFlags targetFlags)
    {
        if ((targetState & PhysicsState.Missile) != 0)
            return true;
        if ((mover.PhysicsState & PhysicsState.Missile) == 0 || targetId == mover.TargetId)
            return false;
        bool weenie = (targetFlags & (ShadowFlags.HasWeenie | ShadowFlags.IsPlayer | ShadowFlags.IsCreature)) != 0;
        if (!weenie)
            return false;
        return (targetState & PhysicsState.Ethereal) != 0 || (mover.TargetId != 0 && (targetFlags & ShadowFlags.IsCreature) != 0);
    }

    /// <summary>
    /// Collides with every object listed in a cell, in list order (retail CObjCell::find_obj_collisions
    /// walks its shadow objects forwards; ACE walks backwards); the mover itself is skipped and the first
    /// non-OK result returns. An initial placement tests no object. An observer watches this very path: it is
    /// told of every object the shortcuts leave untested as skipped (<see cref="SkipReason.OutOfReach"/>), in the
    /// cell's order among the objects tested.
    /// </summary>
    internal static TransitionState FindInCell(Transition transition, uint cellId)
    {
        if (transition.SpherePath.InsertType == InsertType.InitialPlacement)
            return TransitionState.OK;
        // The usual case, tested at once: no observer and both shortcuts of this pass on. Its loop is the general
        // one below with those three tests answered (the same objects tested in the same order).
        const Shortcuts cullAndPreCheck = Shortcuts.ObjectCull | Shortcuts.ReachBoxPreCheck;
        if (transition.Observer is not null || (transition.Shortcuts & cullAndPreCheck) != cullAndPreCheck)
            return FindInCellInGeneral(transition, cellId);
        var candidates = transition.Cull.CandidateRows(transition, cellId, out var reach);
        if (candidates.Length == 0)
            return TransitionState.OK;
        var path = transition.SpherePath;
        bool boxValid = false;
        Vector3 min = default, max = default;
        for (int i = 0; i < candidates.Length; i++)
        {
            if (!boxValid)
            {
                ObjectCull.SpheresBoxIn(path, cellId, out min, out max);
                boxValid = true;
            }
            if (!reach[i].Meets(min, max))
                continue;
            var state = FindObjectCollisionsUnlessSelf(transition, candidates[i]);
            if (state != TransitionState.OK)
                return state;
            boxValid = false;
        }
        return TransitionState.OK;
    }

    /// <summary>
    /// <see cref="FindInCell"/> with an observer or with <see cref="Shortcuts.ObjectCull"/> or
    /// <see cref="Shortcuts.ReachBoxPreCheck"/> off: each of those is tested as it comes.
    /// </summary>
    private static TransitionState FindInCellInGeneral(Transition transition, uint cellId)
    {
        var observer = transition.Observer;
        // Shortcut ObjectCull (not retail). Skips: the objects of the cell whose reach box misses a region
        // around the check spheres (see ObjectCull). Same result: for each, every retail test returns OK and
        // changes nothing. Proof: ObjectCullTests, CrowdObjectPassTests, and the suite with shortcuts off.
        if ((transition.Shortcuts & Shortcuts.ObjectCull) == 0)
            return FindInEveryObject(transition, cellId);
        // The cull keeps each candidate's rows, so a cell already listed is walked without reading the registry.
        var candidates = transition.Cull.CandidateRows(transition, cellId, out var reach);
        if (candidates.Length == 0 && observer is null)
            return TransitionState.OK;
        // For the observer only: the candidates' places in the cell, to report the objects between them.
        var places = observer is null ? default : transition.Cull.Candidates(transition, cellId);
        int reported = 0;
        // Shortcut ReachBoxPreCheck (not retail). Skips: a candidate whose reach box misses the check spheres'
        // own box, by the very rule the cull's region is made with (in a crowd the region holds tens of
        // creatures, most beyond the spheres themselves). Same result: its retail tests return OK and change
        // nothing. The box is taken again after every object actually tested (a step-up from one object moves
        // the check spheres for the next). Proof: CrowdObjectPassTests, and the suite with shortcuts off.
        bool preCheck = (transition.Shortcuts & Shortcuts.ReachBoxPreCheck) != 0;
        var path = transition.SpherePath;
        bool boxValid = false;
        Vector3 min = default, max = default;
        for (int i = 0; i < candidates.Length; i++)
        {
            if (observer is not null)
            {
                ReportOutOfReach(transition, cellId, observer, reported, places[i]);
                reported = places[i] + 1;
            }
            if (preCheck)
            {
                if (!boxValid)
                {
                    ObjectCull.SpheresBoxIn(path, cellId, out min, out max);
                    boxValid = true;
                }
                if (!reach[i].Meets(min, max))
                {
                    if (observer is not null)
                        NotifySkippedUnlessSelf(transition, observer, candidates[i]);
                    continue;
                }
            }
            var state = FindObjectCollisionsUnlessSelf(transition, candidates[i]);
            if (state != TransitionState.OK)
                return state;
            boxValid = false;
        }
        if (observer is not null)
            ReportOutOfReach(transition, cellId, observer, reported, int.MaxValue);
        return TransitionState.OK;
    }

    /// <summary><see cref="FindInCell"/> without the cull: every object of the cell, in its order, as retail.</summary>
    private static TransitionState FindInEveryObject(Transition transition, uint cellId)
    {
        var objects = transition.World.Objects.ObjectsInCell(cellId);
        for (int i = 0; i < objects.Count; i++)
        {
            var state = FindObjectCollisionsUnlessSelf(transition, objects.RowsOf(i));
            if (state != TransitionState.OK)
                return state;
        }
        return TransitionState.OK;
    }

    /// <summary>Tells the observer the objects of the cell from place <paramref name="from"/> up to (not including) <paramref name="to"/> were left out of reach.</summary>
    private static void ReportOutOfReach(Transition transition, uint cellId, ITransitionObserver observer, int from, int to)
    {
        var objects = transition.World.Objects.ObjectsInCell(cellId);
        for (int i = from; i < objects.Count && i < to; i++)
            NotifySkippedUnlessSelf(transition, observer, objects.RowsOf(i));
    }

    private static void NotifySkippedUnlessSelf(Transition transition, ITransitionObserver observer, ReadOnlySpan<ShadowEntry> rows)
    {
        uint self = transition.ObjectInfo.ObjectId;
        if (rows.Length > 0 && (rows[0].EntityId != self || self == 0))
            NotifySkipped(observer, rows, SkipReason.OutOfReach);
    }

    private static TransitionState FindObjectCollisionsUnlessSelf(Transition transition, ReadOnlySpan<ShadowEntry> shapes)
    {
        uint self = transition.ObjectInfo.ObjectId;
        if (shapes.Length == 0 || (shapes[0].EntityId == self && self != 0))
            return TransitionState.OK;
        return FindObjectCollisions(transition, shapes);
    }

    /// <summary>One object (all its rows): the retail ladder BSP-only → cylspheres → spheres → nothing.</summary>
    private static TransitionState FindObjectCollisions(Transition transition, ReadOnlySpan<ShadowEntry> shapes)
    {
        var path = transition.SpherePath;
        var mover = transition.ObjectInfo;
        var observer = transition.Observer;
        ref readonly var head = ref shapes[0];
        var state = head.State;

        if ((state & PhysicsState.Ethereal) != 0 && (state & PhysicsState.IgnoreCollisions) != 0)
        {
            NotifySkipped(observer, shapes, SkipReason.EtherealIgnoreCollisions);
            return TransitionState.OK;
        }
        bool isCreature = (state & PhysicsState.Missile) != 0 || (head.Flags & ShadowFlags.IsCreature) != 0;
        if ((mover.State & ObjectInfoState.IsViewer) != 0 && (head.Flags & ShadowFlags.IsCreature) != 0)
        {
            NotifySkipped(observer, shapes, SkipReason.ViewerVsCreature);
            return TransitionState.OK;
        }
        bool ethereal = false;
        if ((state & PhysicsState.Ethereal) != 0 || ((state & PhysicsState.Static) == 0 && mover.Ethereal))
        {
            if (path.StepDown)
            {
                NotifySkipped(observer, shapes, SkipReason.EtherealStepDown);
                return TransitionState.OK;
            }
            ethereal = true;
        }
        path.ObstructionEthereal = ethereal;

        bool exemption = PvpExemption(mover.State, head.Flags);
        bool missileIgnore = MissileIgnore(mover, head.EntityId, state, head.Flags);
        ShadowShapeKind rung;
        if (BspOnlyDispatch(state, missileIgnore, exemption))
            rung = ShadowShapeKind.Bsp;
        else if (missileIgnore || exemption)
        {
            NotifySkipped(observer, shapes, SkipReason.Exempt);
            path.ObstructionEthereal = false;
            return TransitionState.OK;
        }
        else if (head.CylSphereCount > 0)
            rung = ShadowShapeKind.Cylinder;
        else
            rung = ShadowShapeKind.Sphere;

        foreach (ref readonly var row in shapes)
        {
            if (row.Kind != rung)
            {
                observer?.OnShapeSkipped(row.EntityId, row.Kind, row.Shape.Index,
                    rung == ShadowShapeKind.Bsp ? SkipReason.BspOnlyDispatch : row.Kind == ShadowShapeKind.Bsp ? SkipReason.NotBspDispatch : SkipReason.HasCylinders);
                continue;
            }
            transition.CollisionInfo.ShapeOwner = row.EntityId;
            var result = TestShape(transition, row, isCreature);
            transition.CollisionInfo.ShapeOwner = 0;
            observer?.OnShapeTested(row.EntityId, row.Kind, row.Shape.Index, result);
            if (result != TransitionState.OK)
            {
                if (observer is not null && transition.CollisionInfo.CollisionNormalValid)
                    observer.OnObjectNormal(row.EntityId, row.Kind, transition.CollisionInfo.CollisionNormal);
                return AfterHit(transition, row, result, ethereal, isCreature);
            }
        }
        path.ObstructionEthereal = false;
        return TransitionState.OK;
    }

    private static TransitionState TestShape(Transition transition, in ShadowEntry row, bool isCreature)
    {
        var path = transition.SpherePath;
        var shape = row.Shape;
        switch (row.Kind)
        {
            case ShadowShapeKind.Bsp:
                // Shortcut PolygonBoxPreCheck (not retail). Skips: a part whose polygons' box no check sphere
                // reaches, in a move's insert. Same result: every branch of the query needs a polygon within a
                // sphere's radius before it changes anything (see PartCollision.MayTouchPolygons). Proof:
                // PolygonBoxTests, and the suite with shortcuts off. The flag is read only when the box would skip
                // (the box test is pure: with the shortcut off its answer is dropped).
                if (!PartCollision.MayTouchPolygons(path, row) && (transition.Shortcuts & Shortcuts.PolygonBoxPreCheck) != 0)
                    return TransitionState.OK;
                return PartCollision.Collide(transition, shape.Model!, row.PartPosition, shape.ModelScale);
            case ShadowShapeKind.Cylinder:
                // Retail quirk: only the low point follows the object's frame; the axis stays world Z. Retail
                // first sets the path's local space to the object (cache_localspace_sphere(p, 1.0)).
                // Shortcut CylinderLocalSpace (not retail). Skips: the local-space spheres, centre and up vector
                // of that call. Same result: of them only the placement is ever read after a cylinder test (see
                // CacheLocalSpaceForCylinder). Proof: CrowdObjectPassTests, and the suite with shortcuts off.
                if ((transition.Shortcuts & Shortcuts.CylinderLocalSpace) != 0)
                    path.CacheLocalSpaceForCylinder(row.Position);
                else
                    path.CacheLocalSpaceSphere(row.Position, 1f);
                var cyl = shape.Cylinder;
                cyl.LowPoint = row.PlacedPoint + LandDefs.BlockOffset(path.CheckPos.CellId, row.Position.CellId);
                return CylSphereResponses.IntersectsSphere(cyl, transition);
            default:
                var sphere = shape.Sphere;
                sphere.Center = row.PlacedPoint + LandDefs.BlockOffset(path.CheckPos.CellId, row.Position.CellId);
                return SphereResponses.IntersectsSphere(sphere, transition, isCreature);
        }
    }

    /// <summary>Retail's bookkeeping after a hit: static objects count as environment; ethereal objects and ignored creatures let the mover through but are recorded.</summary>
    private static TransitionState AfterHit(Transition transition, in ShadowEntry row, TransitionState result, bool ethereal, bool isCreature)
    {
        var path = transition.SpherePath;
        var ci = transition.CollisionInfo;
        var mover = transition.ObjectInfo;
        if (!path.StepDown)
        {
            if ((row.State & PhysicsState.Static) != 0)
            {
                if ((mover.State & ObjectInfoState.Contact) == 0)
                    ci.CollidedWithEnvironment = true;
            }
            else if (ethereal || (isCreature && (mover.State & ObjectInfoState.IgnoreCreatures) != 0))
            {
                result = TransitionState.OK;
                ci.CollisionNormalValid = false;
                ci.AddObject(row.EntityId, TransitionState.OK);
            }
            else
            {
                ci.AddObject(row.EntityId, result);
            }
        }
        path.ObstructionEthereal = false;
        return result;
    }

    private static void NotifySkipped(ITransitionObserver? observer, ReadOnlySpan<ShadowEntry> shapes, SkipReason reason)
    {
        if (observer is null)
            return;
        foreach (ref readonly var row in shapes)
            observer.OnShapeSkipped(row.EntityId, row.Kind, row.Shape.Index, reason);
    }
}
