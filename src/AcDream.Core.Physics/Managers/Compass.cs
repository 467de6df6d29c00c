using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail's compass headings: degrees clockwise seen from above, 0 = facing +Y, 90 = facing +X, in [0, 360).
/// A frame's heading is where its local +Y points (Frame::get_heading); a heading is set as a turn about Z only
/// (Frame::set_heading through set_vector_heading, for the upright frames the managers use).
/// </summary>
internal static class Compass
{
    private const double DegreesPerRadian = 57.29577951308232;
    private const double RadiansPerDegree = 0.0174532925199433;

    /// <summary>The heading of a horizontal direction (Position::heading's formula: fmod(450 − atan2·deg, 360)).</summary>
    public static float Of(float x, float y) => (float)Wrap(450.0 - PortableMath.Atan2(y, x) * DegreesPerRadian);

    /// <summary>Frame::get_heading: the heading of the frame's local +Y axis.</summary>
    public static float Of(in Frame frame)
    {
        var forward = frame.LocalToGlobalVec(Vector3.UnitY);
        return Of(forward.X, forward.Y);
    }

    /// <summary>
    /// Position::heading: the heading from <paramref name="from"/> to <paramref name="to"/> on the ground plane
    /// (across landblocks); 0 when they stand on the same vertical line (normalize_check_small).
    /// </summary>
    public static float Between(in Position from, in Position to)
    {
        var d = from.GetOffset(to);
        double len = Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y);
        if (len < PhysicsConstants.Epsilon)
            return 0f;
        return Of((float)(d.X / len), (float)(d.Y / len));
    }

    /// <summary>Frame::set_heading for an upright frame: the orientation becomes a turn of −heading about Z.</summary>
    public static void Set(ref Frame frame, float degrees)
    {
        double half = -degrees * RadiansPerDegree * 0.5;
        frame.Orientation = new Quaternion(0f, 0f, (float)PortableMath.Sin(half), (float)PortableMath.Cos(half));
    }

    private static double Wrap(double degrees)
    {
        double r = degrees % 360.0;
        return r < 0.0 ? r + 360.0 : r;
    }
}
