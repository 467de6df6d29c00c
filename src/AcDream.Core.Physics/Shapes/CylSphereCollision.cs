using System;
using System.Numerics;

namespace AcDream.Core.Physics.Shapes;

/// <summary>
/// The retail CCylSphere geometric tests. The cylinder is an upright slab: its axis is always world +Z
/// (retail quirk, see <see cref="CylSphere"/>), it spans Z from its low point to low point + height, and a
/// sphere touches it when its centre is within radsum of the axis in XY and its body overlaps that Z span.
/// They answer with plain values; the responses a transition chooses from them (step up, slide, land…) are
/// Transitions.Responses.CylSphereResponses. Everything is in the check cell's landblock space. Nothing here
/// allocates.
/// </summary>
internal static class CylSphereCollision
{
    /// <summary>
    /// Places a cylinder given in an owner's space into <paramref name="checkPos"/>'s landblock space:
    /// radius, height and low point are scaled; only the low point is rotated and moved by the owner's
    /// frame; the axis stays world +Z (retail quirk; holtburger, acclient.c:347305-347338).
    /// </summary>
    internal static CylSphere ToCheckSpace(in CylSphere localCylinder, in Position owner, float scale, in Position checkPos)
    {
        Vector3 low = owner.Frame.LocalToGlobal(localCylinder.LowPoint * scale)
                      + LandDefs.BlockOffset(checkPos.CellId, owner.CellId);
        return new CylSphere(low, localCylinder.Radius * scale, localCylinder.Height * scale);
    }

    /// <summary>
    /// Retail CCylSphere::collides_with_sphere: a slab test, not a capsule test. True when the XY distance
    /// of <paramref name="disp"/> (sphere centre minus low point) is within <paramref name="radsum"/> and
    /// the sphere (radius less EPSILON) overlaps the Z span [0, height].
    /// </summary>
    internal static bool CollidesWithSphere(in CylSphere cylinder, in Sphere checkSphere, Vector3 disp, float radsum)
    {
        if (disp.X * disp.X + disp.Y * disp.Y > radsum * radsum)
            return false;
        float halfHeight = cylinder.Height * 0.5f;
        return checkSphere.Radius - PhysicsConstants.Epsilon + halfHeight >= MathF.Abs(halfHeight - disp.Z);
    }

    /// <summary>
    /// Retail CCylSphere::normal_of_collision: the unnormalized collision normal for a check sphere
    /// (<paramref name="checkSphere"/>, <paramref name="disp"/> from the low point), judged from where it is
    /// now, <paramref name="current"/> (its centre at the current position). Starting outside the XY circle gives the
    /// radial normal (dx, dy, 0); starting inside gives +Z when the check position is not above the current
    /// one, else -Z. Returns whether the normal is definite: always for ±Z; for radial, when the current
    /// position already overlaps the Z span or the move is (within EPSILON) horizontal.
    /// Retail quirk: the current centre is used without the landblock offset (CCylSphere.c, acclient.c:361651).
    /// </summary>
    internal static bool CollisionNormal(in CylSphere cylinder, Vector3 current, in Sphere checkSphere, Vector3 disp, float radsum, out Vector3 normal)
    {
        Vector3 fromLow = current - cylinder.LowPoint;
        if (radsum * radsum < fromLow.X * fromLow.X + fromLow.Y * fromLow.Y)
        {
            normal = new Vector3(fromLow.X, fromLow.Y, 0f);
            float halfHeight = cylinder.Height * 0.5f;
            return checkSphere.Radius - PhysicsConstants.Epsilon + halfHeight >= MathF.Abs(halfHeight - fromLow.Z)
                   || MathF.Abs(fromLow.Z - disp.Z) <= PhysicsConstants.Epsilon;
        }
        normal = disp.Z - fromLow.Z <= 0.0f ? Vector3.UnitZ : -Vector3.UnitZ;
        return true;
    }

    /// <summary>
    /// The time along <paramref name="moveZ"/> at which a sphere of <paramref name="sphereRadius"/> starting
    /// at height <paramref name="startZ"/> above the low point meets a cap: the bottom cap when rising
    /// (normal -Z), the top cap when falling (normal +Z).
    /// </summary>
    internal static float CapTime(in CylSphere cylinder, float sphereRadius, float startZ, float moveZ, out Vector3 capNormal)
    {
        if (moveZ > 0.0f)
        {
            capNormal = -Vector3.UnitZ;
            return -((startZ + sphereRadius) / moveZ);
        }
        capNormal = Vector3.UnitZ;
        return (sphereRadius + cylinder.Height - startZ) / moveZ;
    }

    /// <summary>
    /// The swept-circle quadratic in XY: the time along <paramref name="movement"/> at which a centre
    /// starting at <paramref name="startDisp"/> from the axis reaches distance <paramref name="reach"/>.
    /// False when there is no real root. Retail quirk: a negative near root takes the far root.
    /// </summary>
    internal static bool WallTime(Vector3 movement, Vector3 startDisp, float reach, float moveXYSq, out float time)
    {
        double closing = -((double)movement.X * startDisp.X + (double)movement.Y * startDisp.Y);
        double startGap = (double)startDisp.X * startDisp.X + (double)startDisp.Y * startDisp.Y - (double)reach * reach;
        double discriminant = closing * closing - startGap * moveXYSq;
        if (!(discriminant >= 0.0))
        {
            time = 0f;
            return false;
        }
        double root = Math.Sqrt(discriminant);
        double near = closing - root;
        time = (float)((near < 0.0 ? closing + root : near) / moveXYSq);
        return true;
    }
}
