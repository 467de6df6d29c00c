using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Tool;

/// <summary>
/// Where a drawn path is broken: a frame that jumps farther than any walk, run, fall or flight of the mover could (a
/// blip back to a server's position, a teleport). Drawing a line across such a jump would show a path the mover never
/// took, and a 150 m teleport would set a plot's scale and squash the rest of the path into a smear.
/// </summary>
internal static class PathBreaks
{
    /// <summary>A frame moving less than this (metres) is never a break.</summary>
    public const float MinimumJump = 1f;

    /// <summary>A break moves more than this many times the mover's median frame move.</summary>
    public const float MedianMultiple = 4f;

    /// <summary>A break longer than this (metres) is a teleport: the plot leaves what follows it out of its scale.</summary>
    public const float TeleportDistance = 50f;

    /// <summary>
    /// The indices <c>i</c> (1 or more) of <paramref name="points"/> where the path breaks between point <c>i - 1</c> and point
    /// <c>i</c>: the move is more than <see cref="MinimumJump"/> and more than <see cref="MedianMultiple"/> times the median
    /// of the path's moves (so a fast arrow's 5 m frames are not breaks, while a run's 2 m blip is).
    /// </summary>
    public static List<int> Find(IReadOnlyList<Vector3> points)
    {
        var breaks = new List<int>();
        if (points.Count < 2)
            return breaks;
        var moves = new float[points.Count - 1];
        for (int i = 1; i < points.Count; i++)
            moves[i - 1] = Vector3.Distance(points[i - 1], points[i]);
        var sorted = (float[])moves.Clone();
        Array.Sort(sorted);
        float median = sorted[sorted.Length / 2];
        float limit = MathF.Max(MinimumJump, MedianMultiple * median);
        for (int i = 0; i < moves.Length; i++)
            if (moves[i] > limit)
                breaks.Add(i + 1);
        return breaks;
    }
}
