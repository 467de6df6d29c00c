using System;
using System.Numerics;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// What a mover is: its spheres, step heights and flags. Validated on construction (radii, heights and
/// scale finite, radii and scale positive, all at most <see cref="InputLimits.MaxExtent"/> also after
/// scaling); immutable, so one description may be shared by engines on several threads.
/// </summary>
public sealed class MoverDescription
{
    private readonly Sphere[] _spheres;

    /// <summary>Creates a mover description.</summary>
    /// <param name="objectId">The mover's retail object id (it never collides with itself); 0 for none.</param>
    /// <param name="spheres">One or two spheres in the mover's space (retail uses at most two).</param>
    /// <param name="stepUpHeight">How high it may step up, metres.</param>
    /// <param name="stepDownHeight">How far it steps down to stay grounded, metres.</param>
    /// <param name="physicsState">Its PhysicsState (Gravity, EdgeSlide, Missile, Ethereal…).</param>
    /// <param name="flags">Its ObjectInfo bits that describe what it is (IsPlayer, IsPK, IsViewer…); Contact and OnWalkable come from <see cref="MoverState"/>.</param>
    /// <param name="scale">Its scale, applied to spheres and step heights.</param>
    /// <param name="targetId">A missile's target id, or 0.</param>
    public MoverDescription(uint objectId, ReadOnlySpan<Sphere> spheres, float stepUpHeight, float stepDownHeight,
        PhysicsState physicsState = PhysicsState.Gravity, ObjectInfoState flags = ObjectInfoState.None, float scale = 1f, uint targetId = 0)
    {
        if (spheres.Length < 1 || spheres.Length > 2)
            throw new ArgumentException($"mover.spheres: a mover has one or two spheres, got {spheres.Length}.", nameof(spheres));
        for (int i = 0; i < spheres.Length; i++)
            Guard.Sphere(spheres[i], $"mover.spheres[{i}]");
        Guard.Extent(stepUpHeight, true, "mover.stepUpHeight");
        Guard.Extent(stepDownHeight, true, "mover.stepDownHeight");
        Guard.Extent(scale, false, "mover.scale");
        for (int i = 0; i < spheres.Length; i++)
        {
            Guard.Extent(spheres[i].Radius * scale, false, $"mover.spheres[{i}].radius × scale");
            Guard.Finite(spheres[i].Center * scale, $"mover.spheres[{i}].center × scale");
        }
        if ((flags & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
            throw new ArgumentException("mover.flags: Contact and OnWalkable are per-frame state; pass them in MoverState.", nameof(flags));
        ObjectId = objectId;
        _spheres = spheres.ToArray();
        foreach (var sphere in spheres)
            Reach = MathF.Max(Reach, (sphere.Center.Length() + sphere.Radius) * scale);
        StepUpHeight = stepUpHeight;
        StepDownHeight = stepDownHeight;
        PhysicsState = physicsState;
        Flags = flags;
        Scale = scale;
        TargetId = targetId;
    }

    /// <summary>The farthest point of the (scaled) spheres from the mover's origin, in metres.</summary>
    internal float Reach { get; }

    /// <summary>The retail player setup's step-down height (Setup 0x02000001: step-up 0.6, step-down 1.5; holtburger notes).</summary>
    public const float PlayerStepDownHeight = 1.5f;

    /// <summary>
    /// The retail player (Setup 0x02000001): spheres of radius 0.48 at heights 0.475 and 1.35, step-up 0.6,
    /// step-down 1.5 (<see cref="PlayerStepDownHeight"/>), gravity, edge slide, a player. The seed's door
    /// tests used a step-down of 0.04; pass it as <paramref name="stepDownHeight"/> to reproduce them.
    /// </summary>
    /// <remarks>
    /// <see cref="PhysicsState.EdgeSlide"/> (retail's player state word 0x00400408 carries EDGE_SLIDE_PS) means
    /// a mover on walkable ground does not walk off a drop deeper than its step-down height: at such an edge
    /// it slides along it or stops there (CTransition::edge_slide), in <see cref="PhysicsEngine.Resolve"/> and
    /// <c>PhysicsEngine.Step</c> alike. A drop within the step-down is stepped down; a mover in the air
    /// (a jump) is not held. For a mover that walks or runs off such an edge and falls, drop the flag:
    /// <c>MoverDescription.Player().With(physicsState: PhysicsState.Gravity)</c> (see <see cref="With"/>).
    /// </remarks>
    public static MoverDescription Player(uint objectId = 0x50000001, float stepDownHeight = PlayerStepDownHeight, ObjectInfoState extraFlags = ObjectInfoState.None) =>
        new(objectId, [new Sphere(new Vector3(0, 0, 0.475f), 0.48f), new Sphere(new Vector3(0, 0, 1.35f), 0.48f)],
            0.6f, stepDownHeight, PhysicsState.Gravity | PhysicsState.EdgeSlide, ObjectInfoState.IsPlayer | extraFlags);

    /// <summary>
    /// A copy of this description with the given fields replaced and every other field, the spheres too, kept:
    /// the <c>with</c> of a record, for this immutable class. The copy is checked like a new description
    /// (the same exceptions as the constructor); this one is not changed. For example the retail player
    /// without <see cref="PhysicsState.EdgeSlide"/>, which walks off a drop deeper than its step-down instead
    /// of stopping at it: <c>MoverDescription.Player().With(physicsState: PhysicsState.Gravity)</c>.
    /// </summary>
    /// <param name="objectId">The new <see cref="ObjectId"/>, or null to keep it.</param>
    /// <param name="stepUpHeight">The new <see cref="StepUpHeight"/>, or null to keep it.</param>
    /// <param name="stepDownHeight">The new <see cref="StepDownHeight"/>, or null to keep it.</param>
    /// <param name="physicsState">The new <see cref="PhysicsState"/> (all the bits), or null to keep it.</param>
    /// <param name="flags">The new <see cref="Flags"/> (all the bits), or null to keep them.</param>
    /// <param name="scale">The new <see cref="Scale"/>, or null to keep it.</param>
    /// <param name="targetId">The new <see cref="TargetId"/>, or null to keep it.</param>
    public MoverDescription With(uint? objectId = null, float? stepUpHeight = null, float? stepDownHeight = null,
        PhysicsState? physicsState = null, ObjectInfoState? flags = null, float? scale = null, uint? targetId = null) =>
        new(objectId ?? ObjectId, _spheres, stepUpHeight ?? StepUpHeight, stepDownHeight ?? StepDownHeight,
            physicsState ?? PhysicsState, flags ?? Flags, scale ?? Scale, targetId ?? TargetId);

    /// <summary>The mover's id.</summary>
    public uint ObjectId { get; }
    /// <summary>The spheres, mover space, unscaled.</summary>
    public ReadOnlySpan<Sphere> Spheres => _spheres;
    /// <summary>Step-up height, unscaled.</summary>
    public float StepUpHeight { get; }
    /// <summary>Step-down height, unscaled.</summary>
    public float StepDownHeight { get; }
    /// <summary>PhysicsState bits.</summary>
    public PhysicsState PhysicsState { get; }
    /// <summary>ObjectInfo bits describing the mover.</summary>
    public ObjectInfoState Flags { get; }
    /// <summary>Scale.</summary>
    public float Scale { get; }
    /// <summary>Missile target id or 0.</summary>
    public uint TargetId { get; }
}
