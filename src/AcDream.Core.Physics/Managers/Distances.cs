using System;

namespace AcDream.Core.Physics.Managers;

/// <summary>Retail Position::distance and Position::cylinder_distance_no_z: across landblocks, the root taken in double.</summary>
internal static class Distances
{
    /// <summary>Position::distance: the length of get_offset.</summary>
    public static double Between(in Position a, in Position b)
    {
        var d = a.GetOffset(b);
        return Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y + (double)d.Z * d.Z);
    }

    /// <summary>
    /// Position::cylinder_distance_no_z (Position.c:351): the centre distance (in 3-D, despite the name) less
    /// both radii.
    /// </summary>
    public static double CylinderNoZ(float r1, in Position p1, float r2, in Position p2) => Between(p1, p2) - (r1 + r2);
}
