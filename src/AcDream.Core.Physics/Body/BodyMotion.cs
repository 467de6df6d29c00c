using System;
using System.Numerics;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// Retail's per-quantum body arithmetic (CPhysicsObj, acclient-src PORTAL/cphysobj/CPhysicsObj.c):
/// acceleration, friction, integration, the collision response and the leave-ground velocity. Pure
/// functions of their arguments; <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/> strings them together.
/// </summary>
internal static class BodyMotion
{
    /// <summary>
    /// calc_acceleration (CPhysicsObj.c:2229): a body in contact with walkable ground and not sledding has no
    /// acceleration (and loses its spin, see <see cref="StopsSpin"/>); otherwise gravity when it has the
    /// Gravity state, else none.
    /// </summary>
    public static Vector3 Acceleration(PhysicsState physicsState, bool contact, bool onWalkable) =>
        StopsSpin(physicsState, contact, onWalkable) || (physicsState & PhysicsState.Gravity) == 0
            ? Vector3.Zero
            : new Vector3(0f, 0f, PhysicsConstants.Gravity);

    /// <summary>calc_acceleration's ground branch, which zeroes the omega too.</summary>
    public static bool StopsSpin(PhysicsState physicsState, bool contact, bool onWalkable) =>
        contact && onWalkable && (physicsState & PhysicsState.Sledding) == 0;

    /// <summary>
    /// UpdatePhysicsInternal (CPhysicsObj.c:2143): clamps the velocity to <see cref="PhysicsConstants.MaxVelocity"/>,
    /// applies ground friction, zeroes a small velocity, and returns the quantum's offset v·q + ½·a·q² (with
    /// the velocity after friction); then adds a·q to the velocity. A body whose velocity is zero moves
    /// nothing this quantum, whatever its acceleration (retail quirk: the offset is only integrated when
    /// |v|² &gt; 0, so a body released at rest starts falling one quantum late).
    /// </summary>
    public static Vector3 Integrate(ref Vector3 velocity, Vector3 acceleration, float quantum, in MoverState state,
        PhysicsState physicsState, float friction)
    {
        var offset = Vector3.Zero;
        if (PrepareVelocity(ref velocity, quantum, state, physicsState, friction, retailRounding: false))
            offset = velocity * quantum + acceleration * (0.5f * quantum * quantum);
        velocity += acceleration * quantum;
        return offset;
    }

    /// <summary>
    /// UpdatePhysicsInternal as retail rounds it (CPhysicsObj.c:2143-2227; its x87 code runs at 53 bits): the same
    /// steps as <see cref="Integrate"/>, but the displacement v·q + ½·a·q² is computed in double per axis with
    /// retail's float stores and added to <paramref name="origin"/> directly (after the animation's offset, as
    /// UpdatePositionInternal orders them), and the velocity advanced as v + q·a per axis. The motion-layer
    /// body step uses it; the desired-velocity step keeps <see cref="Integrate"/>'s float arithmetic.
    /// </summary>
    public static void IntegrateInto(ref Vector3 origin, ref Vector3 velocity, Vector3 acceleration, float quantum, in MoverState state,
        PhysicsState physicsState, float friction)
    {
        double q = quantum;
        if (PrepareVelocity(ref velocity, quantum, state, physicsState, friction, retailRounding: true))
        {
            var v = velocity;
            var a = acceleration;
            float tx = (float)(a.X * 0.5 * q);
            tx = (float)(tx * q);
            float dx = (float)(q * v.X + tx);
            origin.X = (float)(dx + origin.X);
            float ty = (float)(a.Y * 0.5 * q * q);
            origin.Y = (float)(q * v.Y + ty + origin.Y);
            float hz = (float)(a.Z * 0.5);
            float pz = (float)(q * v.Z);
            float dz = (float)(pz + hz * q * q);
            origin.Z = (float)(dz + origin.Z);
        }
        velocity.X = (float)(q * acceleration.X + velocity.X);
        velocity.Y = (float)(q * acceleration.Y + velocity.Y);
        velocity.Z = (float)((float)(q * acceleration.Z) + velocity.Z);
    }

    // The part of UpdatePhysicsInternal before the displacement: the cap, friction and the small-speed cut; false
    // when the body is at rest (no displacement this quantum).
    private static bool PrepareVelocity(ref Vector3 velocity, float quantum, in MoverState state, PhysicsState physicsState, float friction,
        bool retailRounding)
    {
        float mag2 = velocity.LengthSquared();
        if (!(mag2 > 0f))
            return false;
        if (mag2 > PhysicsConstants.MaxVelocity * PhysicsConstants.MaxVelocity)
        {
            velocity = Vector3.Normalize(velocity) * PhysicsConstants.MaxVelocity;
            mag2 = PhysicsConstants.MaxVelocity * PhysicsConstants.MaxVelocity;
        }
        ApplyFriction(ref velocity, quantum, mag2, state, physicsState, friction, retailRounding);
        // Retail quirk: the small-speed test uses |v|² from before friction (CPhysicsObj.c:2192).
        if (mag2 - PhysicsConstants.SmallVelocity * PhysicsConstants.SmallVelocity < PhysicsConstants.Epsilon)
            velocity = Vector3.Zero;
        return true;
    }

    /// <summary>
    /// calc_friction (CPhysicsObj.c:533): only on walkable ground, and only while the velocity does not leave
    /// the contact plane at <see cref="PhysicsConstants.FrictionSeparationSpeed"/> or more: the part of the
    /// velocity into the plane is removed, then the rest is scaled by (1 − friction)^quantum. A sledding body
    /// uses friction 1 below 1.25 m/s and <see cref="PhysicsConstants.SleddingFriction"/> from 2.5 m/s on a
    /// slope steeper than 10°. (ACE reads the sledding slope test the other way round; retail is followed.)
    /// </summary>
    /// <param name="velocity">The velocity, changed in place.</param>
    /// <param name="quantum">The quantum, seconds.</param>
    /// <param name="velocityMag2">|v|² before friction (for the sledding speeds).</param>
    /// <param name="state">The contact state.</param>
    /// <param name="physicsState">The PhysicsState (Sledding).</param>
    /// <param name="friction">The body's friction.</param>
    /// <param name="retailRounding">
    /// Retail multiplies each component by the double (1 − friction)^quantum and rounds once (CPhysicsObj.c:533-590,
    /// x87 at 53 bits); false rounds the factor to float first (the desired-velocity step's arithmetic, as ACE).
    /// </param>
    public static void ApplyFriction(ref Vector3 velocity, float quantum, float velocityMag2, in MoverState state,
        PhysicsState physicsState, float friction, bool retailRounding = false)
    {
        if (!state.OnWalkable)
            return;
        var normal = state.ContactPlane.Normal;
        float into = Vector3.Dot(velocity, normal);
        if (into >= PhysicsConstants.FrictionSeparationSpeed)
            return;
        velocity -= normal * into;
        float f = friction;
        if ((physicsState & PhysicsState.Sledding) != 0)
        {
            if (velocityMag2 < PhysicsConstants.SleddingSlowSpeedSquared)
                f = 1f;
            else if (velocityMag2 >= PhysicsConstants.SleddingFastSpeedSquared && normal.Z < PhysicsConstants.SleddingLevelZ)
                f = PhysicsConstants.SleddingFriction;
        }
        double factor = Geometry.PortableMath.Pow(1.0 - f, quantum);
        if (retailRounding)
            velocity = new Vector3((float)(velocity.X * factor), (float)(velocity.Y * factor), (float)(velocity.Z * factor));
        else
            velocity *= (float)factor;
    }

    /// <summary>
    /// Frame::grotate (CFrame.c:477, acclient.c:357421): turns an orientation by the rotation vector
    /// <paramref name="w"/> (axis × angle, world axes), applied on the world side; vectors shorter than
    /// EPSILON do nothing. As retail: in double (its x87 runs at 53 bits), the product in retail's order,
    /// then normalized by set_rotate (times the reciprocal length; an invalid result keeps the old one).
    /// </summary>
    public static Quaternion Rotate(Quaternion q, Vector3 w)
    {
        double length2 = (double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z;
        if (length2 < (double)PhysicsConstants.Epsilon * PhysicsConstants.Epsilon)
            return q;
        double theta = Math.Sqrt(length2);
        float thetaInv = (float)(1.0 / theta);
        double sinHalf = Geometry.PortableMath.Sin(theta * 0.5);
        float c = (float)Geometry.PortableMath.Cos(theta * 0.5);
        float f = (float)(sinHalf * w.X * thetaInv);
        float g = (float)(thetaInv * sinHalf * w.Y);
        double h = sinHalf * thetaInv * w.Z;
        double qw = q.W, qx = q.X, qy = q.Y, qz = q.Z;
        var frame = new Frame(Vector3.Zero, q);
        frame.SetRotate(
            (float)(c * qw - f * qx - g * qy - h * qz),
            (float)(c * qx + g * qz + f * qw - h * qy),
            (float)(c * qy - f * qz + h * qx + g * qw),
            (float)(f * qy + c * qz - g * qx + h * qw));
        return frame.Orientation;
    }

    /// <summary>
    /// The velocity CMotionInterp::LeaveGround sets (get_leave_ground_velocity, CMotionInterp.c:530): the
    /// desired motion with the jump's vertical speed; when all three are below EPSILON the body keeps its
    /// velocity. set_velocity then caps it at <see cref="PhysicsConstants.MaxVelocity"/>.
    /// </summary>
    public static Vector3 LeaveGroundVelocity(Vector3 current, Vector3 desired, float jumpSpeed)
    {
        const float e = PhysicsConstants.Epsilon;
        if (MathF.Abs(desired.X) < e && MathF.Abs(desired.Y) < e && MathF.Abs(jumpSpeed) < e)
            return current;
        var v = new Vector3(desired.X, desired.Y, jumpSpeed);
        return v.LengthSquared() > PhysicsConstants.MaxVelocity * PhysicsConstants.MaxVelocity
            ? Vector3.Normalize(v) * PhysicsConstants.MaxVelocity
            : v;
    }

    /// <summary>
    /// handle_all_collisions' velocity response (CPhysicsObj.c:6227): unless the body was and stays on
    /// walkable ground (and is not sledding), a collision normal reflects the part of the velocity into it,
    /// keeping <paramref name="elasticity"/> of it (an Inelastic body stops); two or more stationary-fall
    /// frames stop the body. Returns the stationary-fall counter to carry (see <see cref="BodyState.StationaryFall"/>).
    /// </summary>
    public static int HandleCollisions(ref Vector3 velocity, PhysicsState physicsState, float elasticity, bool prevOnWalkable,
        bool onWalkable, bool collisionNormalValid, Vector3 collisionNormal, int framesStationaryFall, int carried)
    {
        bool applyBounce = !prevOnWalkable || !onWalkable || (physicsState & PhysicsState.Sledding) != 0;
        if (framesStationaryFall <= 1)
        {
            if (applyBounce && collisionNormalValid)
            {
                if ((physicsState & PhysicsState.Inelastic) != 0)
                {
                    velocity = Vector3.Zero;
                }
                else
                {
                    float into = Vector3.Dot(velocity, collisionNormal);
                    if (into < 0f)
                        velocity += collisionNormal * (-(into * (elasticity + 1f)));
                }
            }
        }
        else
        {
            velocity = Vector3.Zero;
        }
        // Retail ors STATIONARY_FALL/STOP bits in and clears them all at 0 or 3; the transition is seeded from the highest.
        return framesStationaryFall is 0 or >= 3 ? 0 : Math.Max(carried, framesStationaryFall);
    }
}
