using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tool;

/// <summary>
/// Where a drawn path is broken: a frame that moves the mover farther than it asked to go (a blip back to a server's
/// position, a teleport). A line drawn across such a jump would show a path the mover never took, and a 150 m teleport
/// would set a plot's scale and squash the rest of the path into a smear.
/// </summary>
internal static class PathBreaks
{
    /// <summary>How far (metres) a frame may move beyond what it asked for before it breaks the path.</summary>
    public const float Slack = 1f;

    /// <summary>A break longer than this (metres) is a teleport: the plot leaves what follows it out of its scale.</summary>
    public const float TeleportDistance = 50f;

    /// <summary>
    /// How far each frame asked to go: an offset mover's frame, the distance from where it started to its target; a body's
    /// frame, twice the elapsed time times the fastest of its velocity before and after the step and its desired velocity
    /// (a fall gains speed within the step). <paramref name="points"/> holds the start, then every frame's position, in
    /// one landblock's frame (<paramref name="frameCell"/>).
    /// </summary>
    public static float[] Asked(IReadOnlyList<TrajectoryFrame> frames, IReadOnlyList<Vector3> points, uint frameCell)
    {
        var asked = new float[frames.Count];
        float speedBefore = 0f;
        for (int f = 0; f < frames.Count; f++)
        {
            var frame = frames[f];
            if (frame.Step is { } step)
            {
                float speed = MathF.Max(MathF.Max(speedBefore, frame.Velocity.Length()), step.DesiredVelocity.Length());
                asked[f] = 2f * speed * (float)step.Elapsed;
                speedBefore = frame.Velocity.Length();
            }
            else if (frame.Target.CellId != 0)
                asked[f] = Vector3.Distance(points[f], frame.Target.Origin + LandDefs.BlockOffset(frameCell, frame.Target.CellId));
        }
        return asked;
    }

    /// <summary>
    /// The frames <c>f</c> before which the path breaks: the move from point <c>f</c> (the start, or frame <c>f - 1</c>) to
    /// point <c>f + 1</c> (frame <c>f</c>) is longer than <paramref name="asked"/>[f] plus <see cref="Slack"/>.
    /// </summary>
    public static List<int> Find(IReadOnlyList<Vector3> points, IReadOnlyList<float> asked)
    {
        var breaks = new List<int>();
        for (int f = 0; f + 1 < points.Count && f < asked.Count; f++)
            if (Vector3.Distance(points[f], points[f + 1]) > asked[f] + Slack)
                breaks.Add(f);
        return breaks;
    }

    /// <summary>The breaks of one mover's path (<see cref="Find"/> with <see cref="Asked"/>).</summary>
    public static List<int> Of(IReadOnlyList<TrajectoryFrame> frames, IReadOnlyList<Vector3> points, uint frameCell) =>
        Find(points, Asked(frames, points, frameCell));
}
