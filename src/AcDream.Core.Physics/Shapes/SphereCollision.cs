using System;
using System.Numerics;

namespace AcDream.Core.Physics.Shapes;

/// <summary>
/// The retail CSphere geometric tests: whether two spheres touch, when a moving point first comes within
/// reach of a sphere, and placing a sphere from its owner's space. They answer with plain values; the
/// responses a transition chooses from them (step up, slide, land…) are Transitions.Responses.SphereResponses.
/// Nothing here allocates.
/// </summary>
internal static class SphereCollision
{
    /// <summary>
    /// Places a sphere given in an owner's space into <paramref name="checkPos"/>'s landblock space: the
    /// centre and radius are scaled, the centre is rotated and moved by the owner's frame, and the
    /// landblock difference is added (retail Position::localtoglobal).
    /// </summary>
    internal static Sphere ToCheckSpace(in Sphere localTarget, in Position owner, float scale, in Position checkPos)
    {
        Vector3 center = owner.Frame.LocalToGlobal(localTarget.Center * scale)
                         + LandDefs.BlockOffset(checkPos.CellId, owner.CellId);
        return new Sphere(center, localTarget.Radius * scale);
    }

    /// <summary>
    /// Retail CSphere::collides_with_sphere: true when a displacement is within <paramref name="radsum"/>
    /// (touching counts).
    /// </summary>
    internal static bool CollidesWithSphere(Vector3 disp, float radsum) => disp.LengthSquared() <= radsum * radsum;

    /// <summary>
    /// Retail CSphere::find_time_of_collision: the fraction of <paramref name="movement"/> at which a point
    /// starting at <paramref name="disp"/> from a sphere's centre first comes within <paramref name="radsum"/>
    /// of it, or -1 when it starts inside (within EPSILON), does not move, or never gets there.
    /// Retail quirk: when the near root is negative the far root is returned (CSphere.c, acclient.c:358480).
    /// </summary>
    internal static double FindTimeOfCollision(Vector3 movement, Vector3 disp, float radsum)
    {
        double moveLenSq = movement.LengthSquared();
        double closing = -(double)Vector3.Dot(disp, movement);
        double startGap = (double)disp.LengthSquared() - (double)radsum * radsum;
        if (startGap < PhysicsConstants.Epsilon || moveLenSq < PhysicsConstants.Epsilon)
            return -1.0;
        double discriminant = closing * closing - startGap * moveLenSq;
        if (discriminant < 0.0)
            return -1.0;
        double root = Math.Sqrt(discriminant);
        double near = closing - root;
        return near < 0.0 ? (closing + root) / moveLenSq : near / moveLenSq;
    }
}
