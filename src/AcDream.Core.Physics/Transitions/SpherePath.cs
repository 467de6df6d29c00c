using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The moving spheres and every position along one transition (retail SPHEREPATH): where the mover
/// started, where it is now (current), where it is being tried (check), and the step-up, step-down,
/// walkable and negative-polygon bookkeeping the collision routines share. Reused between transitions:
/// nothing here allocates after construction.
/// </summary>
internal sealed class SpherePath
{
    /// <summary>A path taking the default shortcuts (<see cref="ShortcutSettings.Default"/>).</summary>
    public SpherePath() : this(ShortcutSettings.Default) { }

    /// <summary>A path taking <paramref name="shortcuts"/> (its transition's).</summary>
    public SpherePath(Shortcuts shortcuts)
    {
        Shortcuts = shortcuts;
        _pointsKept = (shortcuts & Shortcuts.PointsMemo) != 0;
        _moverMatrix = new(shortcuts);
        _spaceMatrix = new(shortcuts);
    }

    /// <summary>The shortcuts this path takes (its transition's).</summary>
    public readonly Shortcuts Shortcuts;

    /// <summary>How many spheres the mover has (1 or 2).</summary>
    public int NumSphere;
    /// <summary>The mover's spheres in its own space, scaled.</summary>
    public SpherePair LocalSphere;
    /// <summary>The lowest point of sphere 0 in the mover's space.</summary>
    public Vector3 LocalLowPoint;
    /// <summary>The spheres at the check position, landblock space of the check cell.</summary>
    public SpherePair GlobalSphere;
    /// <summary>The lowest point at the check position.</summary>
    public Vector3 GlobalLowPoint;
    /// <summary>The spheres at the check position in the space of the object or cell being tested.</summary>
    public SpherePair LocalSpaceSphere;
    /// <summary>
    /// Sphere 0 at the current position in the space being tested. Retail keeps every sphere's current
    /// centre and a local low point too; no test reads them, so they are not computed.
    /// </summary>
    public Sphere LocalSpaceCurrCenter;
    /// <summary>The spheres at the current position, landblock space of the current cell.</summary>
    public SpherePair GlobalCurrCenter;
    /// <summary>The placement of the space being tested.</summary>
    public Position LocalSpacePos;
    /// <summary>World up expressed in the space being tested.</summary>
    public Vector3 LocalSpaceZ;

    /// <summary>The cell the transition began in.</summary>
    public Cell? BeginCell;
    /// <summary>The begin position; meaningless when <see cref="HasBeginPos"/> is false (a placement).</summary>
    public Position BeginPos;
    /// <summary>False for placements, which have no begin position.</summary>
    public bool HasBeginPos;
    /// <summary>The requested end position.</summary>
    public Position EndPos;
    /// <summary>The cell of the current (last accepted) position.</summary>
    public Cell? CurCell;
    /// <summary>The current (last accepted) position.</summary>
    public Position CurPos;
    /// <summary>The offset of the sub-step being tried.</summary>
    public Vector3 GlobalOffset;

    /// <summary>True while stepping up.</summary>
    public bool StepUp;
    /// <summary>The normal of the obstacle being stepped up.</summary>
    public Vector3 StepUpNormal;
    /// <summary>A step-up candidate collision was recorded; resolve it after the insert.</summary>
    public bool Collide;
    /// <summary>The cell of the check position.</summary>
    public Cell? CheckCell;
    /// <summary>The position being tried.</summary>
    public Position CheckPos;
    /// <summary>How the path is being inserted.</summary>
    public InsertType InsertType;
    /// <summary>True while stepping down.</summary>
    public bool StepDown;
    /// <summary>Saved insert type while a nested insert runs.</summary>
    public InsertType Backup;
    /// <summary>Saved check cell.</summary>
    public Cell? BackupCell;
    /// <summary>Saved check position.</summary>
    public Position BackupCheckPos;
    /// <summary>The obstruction found was ethereal.</summary>
    public bool ObstructionEthereal;
    /// <summary>The sphere touches an indoor cell.</summary>
    public bool HitsInteriorCell;
    /// <summary>A building's shell is being tested.</summary>
    public bool BuildingCheck;
    /// <summary>The least normal Z accepted as ground while stepping.</summary>
    public float WalkableAllowance;
    /// <summary>How far along the step-down the ground was found (1 = not yet).</summary>
    public float WalkInterp;
    /// <summary>The depth of the current step-down probe.</summary>
    public float StepDownAmt;
    /// <summary>The sphere at which the walkable polygon was found, in its space.</summary>
    public Sphere WalkableCheckPos;
    /// <summary>The walkable polygon under the mover, or null.</summary>
    public Polygon? Walkable;
    /// <summary>True while probing whether the ground continues (edge slide).</summary>
    public bool CheckWalkable;
    /// <summary>World up in the walkable polygon's space.</summary>
    public Vector3 WalkableUp;
    /// <summary>The placement of the walkable polygon's space.</summary>
    public Position WalkablePos;
    /// <summary>The scale of the walkable polygon's space.</summary>
    public float WalkableScale;
    /// <summary>The cell list matches the check position.</summary>
    public bool CellArrayValid;
    /// <summary>The pending negative-polygon hit asks for a step up.</summary>
    public bool NegStepUp;
    /// <summary>The normal of the pending negative-polygon hit (reversed).</summary>
    public Vector3 NegCollisionNormal;
    /// <summary>A polygon was hit from behind during this insert.</summary>
    public bool NegPolyHit;
    /// <summary>Placement may slide out of overlaps.</summary>
    public bool PlacementAllowsSliding = true;
    /// <summary>The last BSP found touching sphere 0, whose placement test is then known (see <see cref="SolidHitMemo"/>).</summary>
    public SolidHitMemo SolidHit;

    /// <summary>
    /// True when a placement insert's test of the BSP of <paramref name="owner"/> (placed at
    /// <paramref name="space"/>, scale <paramref name="scale"/>) is known to be Collided: the insert is a
    /// placement, whose BSP test is the solid test, and sphere 0 at the check position was found touching
    /// a polygon of that tree (<see cref="SolidHitMemo"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool KnownSolidHit(object owner, in Position space, float scale) =>
        InsertType == InsertType.Placement && (Shortcuts & Shortcuts.SolidHitMemo) != 0 && SolidHit.Holds(owner, space, scale, CheckPos);

    /// <summary>
    /// Clears the per-move state, ready for a new transition: the flags, cells, walkable and step fields.
    /// Left as they are: the mover's spheres (<see cref="NumSphere"/>, <see cref="LocalSphere"/>,
    /// <see cref="LocalLowPoint"/>), which the move sets next (<see cref="InitSphere(MoverDescription)"/>)
    /// and which stay when the mover is the same, and the positions and spheres every move writes before
    /// it reads them (listed below).
    /// </summary>
    public void Reset()
    {
        // Retail (SPHEREPATH::init) zeroes every field. The spheres and positions that each move writes
        // before it reads them are left as they are (a test runs every fuzz move on a busy engine and on a
        // new one): BeginPos, EndPos and CurPos and the current spheres are written by InitPath, which
        // always follows; CheckPos and the check spheres by the first SetCheckPos of both searches;
        // the local-space spheres, position and up vector by CacheLocalSpaceSphere before every shape test
        // that reads them; WalkablePos only with Walkable, cleared below. Sphere entries past NumSphere are
        // never read. These stores were ~5 % of a sliding frame.
        GlobalOffset = default;
        BackupCheckPos = default;
        BeginCell = CurCell = CheckCell = BackupCell = null;
        HasBeginPos = false;
        StepUp = Collide = StepDown = ObstructionEthereal = HitsInteriorCell = BuildingCheck = false;
        CheckWalkable = CellArrayValid = NegStepUp = NegPolyHit = false;
        StepUpNormal = NegCollisionNormal = WalkableUp = default;
        InsertType = Backup = InsertType.Transition;
        WalkableAllowance = WalkInterp = StepDownAmt = WalkableScale = 0f;
        WalkableCheckPos = default;
        Walkable = null;
        PlacementAllowsSliding = true;
        SolidHit.Forget();
        // What is remembered for a position (the current spheres, the object tests' centres) stays: it
        // depends on the position and the spheres only, and InitSphere forgets it when the spheres change.
    }

    /// <summary>Starts a path. With no begin position it is a placement at <paramref name="endPos"/>.</summary>
    public void InitPath(Cell? beginCell, Position? beginPos, Position endPos)
    {
        if (beginPos is { } begin)
        {
            InitPath(beginCell, begin, endPos);
            return;
        }
        BeginCell = beginCell;
        EndPos = endPos;
        HasBeginPos = false;
        BeginPos = default;
        InsertType = InsertType.Placement;
        CurPos = endPos;
        CurCell = beginCell;
        CacheGlobalCurrCenter();
    }

    /// <summary>Starts a move from <paramref name="beginPos"/> (the per-frame path: no nullable copies).</summary>
    public void InitPath(Cell? beginCell, in Position beginPos, in Position endPos)
    {
        BeginCell = beginCell;
        EndPos = endPos;
        HasBeginPos = true;
        BeginPos = beginPos;
        InsertType = InsertType.Transition;
        CurPos = beginPos;
        CurCell = beginCell;
        CacheGlobalCurrCenter();
    }

    /// <summary>
    /// Sets a mover's spheres (<see cref="InitSphere(System.ReadOnlySpan{Sphere}, float)"/> of its spheres
    /// and scale). A description is immutable, so the spheres set for the same one last time are kept.
    /// </summary>
    public void InitSphere(MoverDescription mover)
    {
        if (ReferenceEquals(mover, _spheresOf))
            return;
        InitSphere(mover.Spheres, mover.Scale);
        _spheresOf = mover;
    }

    // The mover whose spheres LocalSphere holds, or null when they were set otherwise.
    private MoverDescription? _spheresOf;

    /// <summary>Sets the mover's spheres (at most two are used, as retail), scaled; an unused second one is zero.</summary>
    public void InitSphere(System.ReadOnlySpan<Sphere> spheres, float scale)
    {
        _spheresOf = null;
        NumSphere = spheres.Length <= 2 ? spheres.Length : 2;
        LocalSphere = default;
        for (int i = 0; i < NumSphere; i++)
            LocalSphere[i] = new Sphere(spheres[i].Center * scale, spheres[i].Radius * scale);
        LocalLowPoint = LocalSphere[0].Center - new Vector3(0, 0, LocalSphere[0].Radius);
        // Side by side for the transforms: lane 2 is the low point for the global spheres, and the
        // current sphere 0 for the local-space ones (hence radius 0 there too).
        _localPoints = PointLanes.Of(LocalSphere[0].Center, LocalSphere[1].Center, LocalLowPoint, Vector3.Zero);
        _radii = Vector128.Create(LocalSphere[0].Radius, LocalSphere[1].Radius, LocalSphere[0].Radius, 0f);
        // Everything remembered for a position depends on the spheres too.
        _curFresh.Valid = _checkFresh.Valid = false;
        SolidHit.Forget();
    }

    /// <summary>Moves the check position and its spheres by an offset.</summary>
    public void AddOffsetToCheckPos(Vector3 offset)
    {
        CellArrayValid = false;
        CheckPos.Frame.Origin += offset;
        ShiftGlobalSpheres(offset);
    }

    /// <summary>
    /// Re-labels the check position with another cell; an outdoor cell in another landblock moves the
    /// origin into that landblock's frame.
    /// </summary>
    public void AdjustCheckPos(uint cellId)
    {
        if (LandDefs.IsLandCell(cellId))
        {
            var offset = LandDefs.BlockOffset(cellId, CheckPos.CellId);
            ShiftGlobalSpheres(offset);
            CheckPos.Frame.Origin += offset;
        }
        CheckPos.CellId = cellId;
    }

    /// <summary>Recomputes the spheres at the current position.</summary>
    public void CacheGlobalCurrCenter()
    {
        // A move usually starts where the previous one ended, and accepting a sub-step makes the check
        // position current: the points were then computed for this very position already (the same
        // transforms of the same inputs give the same bits).
        ref var cur = ref _curFresh;
        if (!cur.Valid || !Position.SameBits(CurPos, cur.For))
        {
            if (_checkFresh.Valid && Position.SameBits(CurPos, _checkFresh.For))
                cur = _checkFresh;
            else
                Compute(ref cur, CurPos);
        }
        cur.Points.Rows(_radii, out var sphere0, out var sphere1, out _);
        Store(ref GlobalCurrCenter[0], sphere0);
        if (NumSphere > 1)
            Store(ref GlobalCurrCenter[1], sphere1);
    }

    /// <summary>Recomputes the spheres at the check position.</summary>
    public void CacheGlobalSphere()
    {
        // Usually the current position (retail sets the check position to it after init_path and after
        // accepting a sub-step), or one an object test or a step-up computed already.
        ref readonly var points = ref _curFresh.Valid && Position.SameBits(CheckPos, _curFresh.For)
            ? ref _curFresh.Points
            : ref PointsAt(CheckPos, ref _checkFresh);
        points.Rows(_radii, out var sphere0, out var sphere1, out var lowPoint);
        Store(ref GlobalSphere[0], sphere0);
        if (NumSphere > 1)
            Store(ref GlobalSphere[1], sphere1);
        GlobalLowPoint = lowPoint.AsVector3();
    }

    // A sphere is its centre then its radius: one row (x, y, z, radius).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Store(ref Sphere sphere, Vector128<float> row) => Unsafe.As<Sphere, Vector128<float>>(ref sphere) = row;

    // The mover's orientation changes rarely along a path, and the spaces tested one after another often
    // share one: each keeps the last matrix built.
    private readonly RotationMatrixMemo _moverMatrix, _spaceMatrix;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void ShiftGlobalSpheres(Vector3 offset)
    {
        for (int i = 0; i < NumSphere; i++)
            GlobalSphere[i].Center += offset;
        GlobalLowPoint += offset;
    }

    /// <summary>
    /// Expresses the current and check spheres in the space of <paramref name="space"/> (an object part
    /// or a cell), dividing by its scale, ready for a BSP query.
    /// </summary>
    public void CacheLocalSpaceSphere(in Position space, float scale)
    {
        ref readonly var spaceMatrix = ref _spaceMatrix.LanesOf(space.Frame);
        // Position::localtolocal is the other position's localtoglobal, then this one's globaltolocal. The
        // first half is the same for every object tested from one path position: it is the points
        // remembered for the position (same expression, same bits) instead of once per object.
        ref readonly var cur = ref PointsAt(CurPos, ref _curFresh);
        ref readonly var check = ref PointsAt(CheckPos, ref _checkFresh);
        // Lanes 0 and 1: the check spheres; lane 2: the current sphere 0. Each crosses into the space's
        // landblock (a float sum, as retail), then all three go through the space's transpose at once.
        var points = check.WithLane2From(cur);
        uint block = space.CellId >> 16;
        if (block != CheckPos.CellId >> 16 || block != CurPos.CellId >> 16 || HasPositiveZero(space.Frame.Origin))
        {
            var offsets = PointLanes.Pairs(LandDefs.BlockOffset(space.CellId, CheckPos.CellId), LandDefs.BlockOffset(space.CellId, CurPos.CellId));
            points = new PointLanes(offsets.X + points.X, offsets.Y + points.Y, offsets.Z + points.Z);
        }
        // Else every offset is zero, and adding it is left out: x + 0 is x except that −0 becomes +0, and the
        // difference with the space's origin that follows is the same for either zero unless that origin
        // coordinate is +0 (+0 − +0 = +0, −0 − +0 = −0; against −0 or any other value both give the same).
        var inSpace = spaceMatrix.FrameToLocal(points, space.Frame.Origin);
        inSpace.Rows(_radii, out var sphere0, out var sphere1, out var current0);
        if (scale != 1f)
        {
            // Dividing by a scale of 1 would multiply by 1, which changes no value.
            var invScale = Vector128.Create(1.0f / scale);
            sphere0 *= invScale;
            sphere1 *= invScale;
            current0 *= invScale;
        }
        Store(ref LocalSpaceSphere[0], sphere0);
        if (NumSphere > 1)
            Store(ref LocalSpaceSphere[1], sphere1);
        Store(ref LocalSpaceCurrCenter, current0);
        LocalSpacePos = space;
        LocalSpaceZ = _spaceMatrix.LocalUp();
    }

    /// <summary>
    /// What retail's cache_localspace_sphere(p, 1.0) before a cylinder test leaves that anything reads: the
    /// space's placement (<see cref="LocalSpacePos"/>, which CCylSphere::step_sphere_up turns its normal by).
    /// The spheres, current centre and up vector it would compute in that space are not computed: every reader
    /// of them (the BSP queries of a part or a cell, the edge slide's walkable test) prepares its own space first
    /// with <see cref="CacheLocalSpaceSphere"/>, with no other test in between, so no result changes. In a pile
    /// of creatures this was a rotation matrix and three transforms per cylinder tested (a fifth of the tick).
    /// </summary>
    public void CacheLocalSpaceForCylinder(in Position space) => LocalSpacePos = space;

    // Whether a coordinate is +0 (all bits clear).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool HasPositiveZero(Vector3 v) =>
        (System.BitConverter.SingleToUInt32Bits(v.X) == 0) | (System.BitConverter.SingleToUInt32Bits(v.Y) == 0) | (System.BitConverter.SingleToUInt32Bits(v.Z) == 0);

    /// <summary>
    /// The matrix of the space last prepared by <see cref="CacheLocalSpaceSphere"/> (<see cref="LocalSpacePos"/>'s
    /// orientation), remembered: the BSP queries turn normals and offsets back through it.
    /// </summary>
    public ref readonly RotationMatrix LocalSpaceMatrix => ref _spaceMatrix.Of(LocalSpacePos.Frame);

    /// <summary>
    /// The mover's points (sphere centres, low point) at a position, Position::localtoglobal, and the
    /// position they are for; kept from one move to the next, forgotten when the spheres change.
    /// </summary>
    private struct FreshPoints
    {
        public bool Valid;
        public Position For;
        public PointLanes Points;
    }

    // The mover's sphere centres and low point in its own space (lanes 0, 1, 2), and the radii for rows.
    private PointLanes _localPoints;
    private Vector128<float> _radii;

    // The points at the current position and at the last check position computed.
    private FreshPoints _curFresh, _checkFresh;
    // False when the shortcut is off: no points are kept, each request computes them.
    private readonly bool _pointsKept;

    /// <summary>
    /// The position's matrix · (local point) + origin, for each point, exactly as
    /// <see cref="Position.LocalToLocal(in RotationMatrix, in Position, in RotationMatrix, Vector3)"/>
    /// computes its first half; recomputed only when the position differs in any bit from the last one.
    /// Shortcut <see cref="Shortcuts.PointsMemo"/> (not retail). Skips: the transforms of the mover's points at a
    /// position whose bits were seen last (a move starting where the last ended, an accepted sub-step, each
    /// object tested from one position). Same result: the same transforms of the same bits. Proof:
    /// SpherePathSpheresTests, RememberedWorkTests, and the suite with shortcuts off.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private ref readonly PointLanes PointsAt(in Position position, ref FreshPoints fresh)
    {
        if (!fresh.Valid || !Position.SameBits(position, fresh.For))
            Compute(ref fresh, position);
        return ref fresh.Points;
    }

    private void Compute(ref FreshPoints fresh, in Position position)
    {
        fresh.Points = _moverMatrix.LanesOf(position.Frame).PositionToGlobal(_localPoints, position.Frame.Origin);
        fresh.For = position;
        fresh.Valid = _pointsKept;
    }

    /// <summary>True when the remembered walkable polygon still holds the mover (or there is none).</summary>
    public bool CheckWalkables()
    {
        if (Walkable is null)
            return true;
        var probe = new Sphere(WalkableCheckPos.Center, WalkableCheckPos.Radius * 0.5f);
        return PolygonQuery.CheckWalkable(Walkable, probe, WalkableUp, small: false);
    }

    /// <summary>The offset from the current cell's landblock to the check cell's.</summary>
    public Vector3 CurToCheckBlockOffset() => LandDefs.BlockOffset(CurPos.CellId, CheckPos.CellId);

    /// <summary>True when a normal Z is steep enough to count as ground for the current step.</summary>
    public bool IsWalkableAllowable(float normalZ) => normalZ > WalkableAllowance;

    /// <summary>Restores the saved check position and cell.</summary>
    public void RestoreCheckPos()
    {
        CheckPos = BackupCheckPos;
        CheckCell = BackupCell;
        CellArrayValid = false;
        CacheGlobalSphere();
    }

    /// <summary>Saves the check position and cell.</summary>
    public void SaveCheckPos()
    {
        BackupCell = CheckCell;
        BackupCheckPos = CheckPos;
    }

    /// <summary>Sets the check position and cell.</summary>
    public void SetCheckPos(in Position position, Cell? cell)
    {
        CheckPos = position;
        CheckCell = cell;
        CellArrayValid = false;
        CacheGlobalSphere();
    }

    /// <summary>Records a step-up candidate: the obstacle's normal, and the position to come back to.</summary>
    public void SetCollide(Vector3 collisionNormal)
    {
        Collide = true;
        BackupCell = CheckCell;
        BackupCheckPos = CheckPos;
        StepUpNormal = collisionNormal;
        WalkInterp = 1.0f;
    }

    /// <summary>Records a polygon hit from behind, to resolve after the insert.</summary>
    public void SetNegPolyHit(bool stepUp, Vector3 collisionNormal)
    {
        NegStepUp = stepUp;
        NegPolyHit = true;
        NegCollisionNormal = -collisionNormal;
    }

    /// <summary>Remembers the walkable polygon found under the mover.</summary>
    public void SetWalkable(in Sphere sphere, Polygon polygon, Vector3 up, in Position localPos, float scale)
    {
        WalkableCheckPos = sphere;
        Walkable = polygon;
        WalkableUp = up;
        WalkablePos = localPos;
        WalkableScale = scale;
    }
}
