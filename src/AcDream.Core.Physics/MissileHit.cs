using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The one hit of a missile's flight (see <see cref="Missile"/>): what it hit, where the missile stopped and
/// the surface's normal. Retail reports it from CPhysicsObj::handle_all_collisions after the quantum's
/// transition (objects first, in the order they were met, then the environment) and clears the missile's
/// Missile bit there, so a flight reports once.
/// </summary>
public readonly struct MissileHit
{
    internal MissileHit(MissileHitKind kind, uint objectId, Position position, bool normalValid, Vector3 normal, int quantum)
    {
        Kind = kind;
        ObjectId = objectId;
        Position = position;
        NormalValid = normalValid;
        Normal = normal;
        Quantum = quantum;
    }

    /// <summary>Object, environment, or <see cref="MissileHitKind.None"/> (no hit).</summary>
    public MissileHitKind Kind { get; }

    /// <summary>The object hit (an <see cref="MissileHitKind.Object"/> hit, or an object reported as environment); 0 for cell geometry, terrain, buildings and static objects.</summary>
    public uint ObjectId { get; }

    /// <summary>
    /// Where the missile stopped in the quantum of the hit (its position after the transition: with
    /// PathClipped the transition ends at the sub-step that first recorded a collision, so the missile's
    /// sphere is at the surface, not through it). The contact point is the sphere's surface along −<see cref="Normal"/>.
    /// </summary>
    public Position Position { get; }

    /// <summary>The transition recorded a collision normal (false for a hit without one, e.g. an object only passed through).</summary>
    public bool NormalValid { get; }

    /// <summary>The collision normal of the hit, unit length, landblock space (zero when <see cref="NormalValid"/> is false).</summary>
    public Vector3 Normal { get; }

    /// <summary>Which quantum of the flight hit, counted from 1 (retail steps a body in quanta of 1/30 to 1/5 s).</summary>
    public int Quantum { get; }

    /// <inheritdoc />
    public override string ToString() =>
        Kind == MissileHitKind.None ? "no hit" : $"{Kind} 0x{ObjectId:X8} at {Position.Frame.Origin} normal {Normal} (quantum {Quantum})";
}
