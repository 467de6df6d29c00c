using System;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// The last physics BSP that a move's collision test found sphere 0 touching a polygon of, remembered by
/// its owner (a placed model or an env cell: the owner fixes the tree and, for a model, the bounding sphere
/// tested before it), the placement and scale of its space and the check position (not retail; changes no
/// result).
/// A mover walking into a wall too tall to climb tries to step up (retail step_up): the step-down probe
/// finds no higher ground, so the placement insert that ends the attempt tests the same wall at the same
/// check position, where retail's solid test (BSPTREE::find_collisions' placement branch,
/// sphere_intersects_solid) must find the polygon again: the tree's walk visits the leaves in the same
/// order with the same routing, and its polygon test (<see cref="Geometry.PolygonQuery.HitsSphere"/>) is
/// the very test that found the hit (<see cref="Geometry.PolygonQuery.PosHitsSphere"/> records a polygon
/// only when it is true). That test's answer, Collided, is therefore known without walking the tree.
/// The local-space sphere 0 is a function of the space, the scale, the check position and the mover's
/// spheres (<see cref="SpherePath.CacheLocalSpaceSphere"/>); the spheres do not change within a move, and
/// the memo is forgotten when a move starts or the spheres are set.
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.SolidHitMemo"/> (not retail; taken in <see cref="SpherePath.KnownSolidHit"/>).
/// Skips: the placement insert's solid walk of a BSP that sphere 0, at the same check position, was just found
/// touching. Same result: that walk must find the same polygon by the same test (above). Proof:
/// SolidHitMemoTests, and the suite with shortcuts off.
/// </remarks>
internal struct SolidHitMemo
{
    private object? _owner;
    private Position _space;
    private Position _check;
    private float _scale;

    /// <summary>
    /// Remembers that <paramref name="path"/>'s local-space sphere 0 (prepared for the tree of
    /// <paramref name="owner"/>, scale <paramref name="scale"/>) touches a polygon of the tree.
    /// </summary>
    public void Remember(object owner, SpherePath path, float scale)
    {
        _owner = owner;
        _space = path.LocalSpacePos;
        _check = path.CheckPos;
        _scale = scale;
    }

    /// <summary>Forgets the hit.</summary>
    public void Forget() => _owner = null;

    /// <summary>
    /// True when sphere 0 at <paramref name="check"/>, in the space of <paramref name="owner"/>'s tree placed
    /// at <paramref name="space"/> with scale <paramref name="scale"/>, is known to touch a polygon of the
    /// tree: the same owner, and the same space, scale and check position to the bit.
    /// </summary>
    public readonly bool Holds(object owner, in Position space, float scale, in Position check) =>
        ReferenceEquals(_owner, owner)
        && BitConverter.SingleToInt32Bits(_scale) == BitConverter.SingleToInt32Bits(scale)
        && Position.SameBits(check, _check)
        && Position.SameBits(space, _space);
}
