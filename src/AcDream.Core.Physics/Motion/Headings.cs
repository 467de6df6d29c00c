using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Retail's compass headings: degrees in [0, 360), 0 facing +Y, 90 facing +X (clockwise seen from above; a
/// TurnRight increases it). The arithmetic follows the decompile in double (retail's x87 code), with its float
/// stores; the trigonometry is portable (the same bits on every machine). A server uses them for
/// <see cref="MoveToParameters.DesiredHeading"/> and to read where a creature faces.
/// </summary>
public static class Headings
{
    // The decompile's degree/radian factors (acclient.c:357667 set_vector_heading, 467050 Position::heading).
    private const double DegreesPerRadian = 57.29577951308232;
    private const double RadiansPerDegree = 0.0174532925199433;

    /// <summary>The heading of a horizontal direction (x, y): fmod(450 − atan2(y, x) in degrees, 360).</summary>
    private static double OfDirection(double x, double y) => FromAtan2(PortableMath.Atan2(y, x));

    // fmod(450 − angle in degrees, 360): angle is atan2's, in [−π, π], so the result is never negative.
    private static double FromAtan2(double radians) => (450.0 - radians * DegreesPerRadian) % 360.0;

    // Frame::get_heading's vector: where the frame's local +Y points.
    private static Vector3 Forward(in Frame frame) => frame.LocalToGlobalVec(Vector3.UnitY);

    // Position::heading's offset on the ground plane and its length; false when shorter than EPSILON (normalize_check_small).
    private static bool Horizontal(in Position from, in Position to, out Vector3 d, out double length)
    {
        d = from.GetOffset(to);
        length = Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y);
        return !(length < PhysicsConstants.Epsilon);
    }

    /// <summary>Frame::get_heading: the heading the frame's +Y axis points at, compass degrees in [0, 360).</summary>
    /// <param name="frame">The frame (a position's orientation).</param>
    public static float Of(in Frame frame)
    {
        var forward = Forward(frame);
        return (float)OfDirection(forward.X, forward.Y);
    }

    /// <summary>
    /// Position::heading (acclient.c:467050): the heading from <paramref name="from"/> towards <paramref name="to"/>
    /// (across landblocks), ignoring height; 0 when they are closer than EPSILON horizontally (normalize_check_small).
    /// </summary>
    /// <param name="from">Where from.</param>
    /// <param name="to">Where to.</param>
    public static float Towards(in Position from, in Position to)
    {
        if (!Horizontal(from, to, out var d, out double length))
            return 0f;
        float inv = (float)(1.0 / length);
        return (float)OfDirection(d.X * inv, d.Y * inv);
    }

    /// <summary>
    /// Frame::set_heading (acclient.c:357691) through set_vector_heading and euler_set_rotate: the frame turned about
    /// world Z to face <paramref name="degrees"/>. Retail also keeps the frame's pitch (asin of the forward vector's
    /// z); a creature's motion turns it only about Z, so its pitch is 0 and the result is a pure yaw.
    /// </summary>
    /// <param name="degrees">The compass heading, degrees.</param>
    public static Quaternion Facing(float degrees)
    {
        double radians = degrees * RadiansPerDegree;
        float x = (float)PortableMath.Sin(radians), y = (float)PortableMath.Cos(radians);
        // normalize_check_small, then the heading back from the direction (set_vector_heading).
        double length = Math.Sqrt((double)x * x + (double)y * y);
        float nx = (float)(x * (1.0 / length)), ny = (float)(y * (1.0 / length));
        float yaw = (float)(-OfDirection(nx, ny) * RadiansPerDegree);
        // euler_set_rotate with no pitch or roll: (cos(z/2), 0, 0, sin(z/2)), in floats, then set_rotate's normalization.
        float half = yaw * 0.5f;
        float c = (float)PortableMath.Cos((double)half), s = (float)PortableMath.Sin((double)half);
        var frame = new Frame(Vector3.Zero);
        frame.SetRotate(c, 0f, 0f, s);
        return frame.Orientation;
    }

    /// <summary>
    /// heading_diff (acclient.c:344737): how far <paramref name="x"/> is past <paramref name="y"/> in the turn's
    /// direction, in [0, 360): x − y, zero within EPSILON, wrapped up by 360 when negative, and measured the other
    /// way (360 − d) for any motion but TurnRight.
    /// </summary>
    internal static double Diff(float x, float y, uint motion)
    {
        const double e = PhysicsConstants.Epsilon;
        double d = (double)x - y;
        if (Math.Abs(d) < e)
            d = 0.0;
        if (d < -e)
            d += 360.0;
        if (d > e && motion != MotionCommand.TurnRight)
            d = 360.0 - d;
        return d;
    }

    /// <summary>
    /// heading_greater (acclient.c:344714): whether <paramref name="x"/> has passed <paramref name="y"/> for a turn
    /// in <paramref name="motion"/>'s direction, comparing the short way round (a TurnRight has passed when x &gt; y,
    /// any other turn when x ≤ y).
    /// </summary>
    internal static bool Greater(float x, float y, uint motion)
    {
        bool lessOrEqual = Math.Abs((double)x - y) <= 180.0 ? x <= y : y <= x;
        return motion == MotionCommand.TurnRight ? !lessOrEqual : lessOrEqual;
    }

    /// <summary>
    /// Position::cylinder_distance (acclient.c:467220): the gap between two upright cylinders (radius, height) standing
    /// at the positions: the horizontal-and-vertical reach between their surfaces, negative when they overlap. When one
    /// stands above the other (a vertical gap) and they overlap horizontally, retail returns the vertical gap.
    /// </summary>
    internal static float CylinderDistance(float r1, float h1, in Position p1, float r2, float h2, in Position p2)
    {
        var o = p1.GetOffset(p2);
        float reach = (float)(Math.Sqrt((double)o.X * o.X + (double)o.Y * o.Y + (double)o.Z * o.Z) - ((double)r1 + r2));
        double z1 = p1.Frame.Origin.Z, z2 = p2.Frame.Origin.Z;
        double gap = z1 <= z2 ? z2 - (z1 + h1) : z1 - (z2 + h2);
        if (gap <= 0.0)
            return reach > 0f ? reach : (float)-Math.Sqrt(gap * gap + (double)reach * reach);
        return reach > 0f ? (float)Math.Sqrt(gap * gap + (double)reach * reach) : (float)gap;
    }

    /// <summary>Position::distance: the distance between the positions' origins (across landblocks), as a float (one formula: <see cref="Managers.Distances.Between"/>).</summary>
    internal static float Distance(in Position a, in Position b) => (float)Managers.Distances.Between(a, b);
}
