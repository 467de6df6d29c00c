using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// Retail's ALIGNPATH_PS turn (a missile points along its path): each quantum that moves the object,
/// CPhysicsObj::UpdateObjectInternal (CPhysicsObj.c:7219-7223) sets the new frame's heading to the quantum's offset
/// with Frame::set_vector_heading (CFrame.c:723): the yaw from the offset's direction on the ground, the pitch from
/// its climb, no roll (Frame::euler_set_rotate(pitch, 0, yaw), order 0).
/// </summary>
internal static class AlignPath
{
    /// <summary>
    /// The orientation whose +Y axis points along <paramref name="offset"/>: the yaw about world Z of
    /// −((450° − atan2(y, x)) mod 360°) and the pitch about X of asin(z), composed as retail's euler_set_rotate does
    /// (q = q_z(yaw) · q_x(pitch)). An offset too short to have a direction keeps <paramref name="orientation"/>.
    /// </summary>
    /// <remarks>
    /// The decompile prints the angle as atan2(x, y); read that way, set_heading(0°) (due north) would turn the
    /// object to face east. atan2(y, x), as ACE reads it, gives north for heading 0, as the rest of retail's headings
    /// (an identity frame faces +Y); we follow that reading (docs/open-questions.md).
    /// </remarks>
    public static Quaternion Heading(Vector3 offset, Quaternion orientation)
    {
        // UpdateObjectInternal normalizes the offset (Vector3::Normalize), set_vector_heading again (normalize_check_small).
        if (VectorMath.NormalizeCheckSmall(ref offset) || VectorMath.NormalizeCheckSmall(ref offset))
            return orientation;
        const double ToDegrees = 57.29577951308232, ToRadians = 0.0174532925199433;
        float yaw = (float)(-((450.0 - PortableMath.Atan2((double)offset.Y, offset.X) * ToDegrees) % 360.0) * ToRadians);
        // asin(z) as atan2(z, √(1 − z²)): the same angle from the portable routines (the same bits on every platform).
        double z = Math.Clamp((double)offset.Z, -1.0, 1.0);
        float pitch = (float)(PortableMath.Atan2(z, Math.Sqrt((1.0 - z) * (1.0 + z))) * ToDegrees * ToRadians);
        // euler_set_rotate with y = 0: the halves' cosines and sines, their products rounded to float.
        float cp = (float)PortableMath.Cos(pitch * 0.5), sp = (float)PortableMath.Sin(pitch * 0.5);
        float cy = (float)PortableMath.Cos(yaw * 0.5), sy = (float)PortableMath.Sin(yaw * 0.5);
        var q = new Quaternion(sp * cy, sy * sp, cp * sy, cy * cp);
        return Quaternion.Normalize(q);
    }
}
