using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// A placement: an origin and a unit orientation (retail AFrame). Local↔global transforms rotate
/// first, then translate.
/// </summary>
public struct Frame
{
    /// <summary>The origin in the parent space.</summary>
    public Vector3 Origin;

    /// <summary>The orientation, a unit quaternion.</summary>
    public Quaternion Orientation;

    /// <summary>Creates a frame.</summary>
    public Frame(Vector3 origin, Quaternion orientation)
    {
        Origin = origin;
        Orientation = orientation;
    }

    /// <summary>A frame at <paramref name="origin"/> with no rotation.</summary>
    public Frame(Vector3 origin) : this(origin, Quaternion.Identity) { }

    /// <summary>The identity frame.</summary>
    public static Frame Identity => new(Vector3.Zero, Quaternion.Identity);

    /// <summary>Maps a point from this frame's space into the parent space.</summary>
    public readonly Vector3 LocalToGlobal(Vector3 point) => Origin + Vector3.Transform(point, Orientation);

    /// <summary>Maps a point from the parent space into this frame's space.</summary>
    public readonly Vector3 GlobalToLocal(Vector3 point) => Vector3.Transform(point - Origin, Quaternion.Conjugate(Orientation));

    /// <summary>Rotates a direction from this frame's space into the parent space.</summary>
    public readonly Vector3 LocalToGlobalVec(Vector3 vector) => Vector3.Transform(vector, Orientation);

    /// <summary>Rotates a direction from the parent space into this frame's space.</summary>
    public readonly Vector3 GlobalToLocalVec(Vector3 vector) => Vector3.Transform(vector, Quaternion.Conjugate(Orientation));

    /// <summary>Composes: a child frame given in this frame's space, expressed in the parent space.</summary>
    public readonly Frame Combine(in Frame child) =>
        new(LocalToGlobal(child.Origin), Quaternion.Normalize(Orientation * child.Orientation));

    /// <summary>Sets the orientation to the normalized linear blend of two frames' orientations (retail interpolate_rotation).</summary>
    public void InterpolateRotation(in Frame from, in Frame to, float t)
    {
        Orientation = Quaternion.Normalize(Quaternion.Lerp(from.Orientation, to.Orientation, t));
    }

    /// <inheritdoc />
    public override readonly string ToString() => $"{Origin} {Orientation}";
}
