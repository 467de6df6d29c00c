using System.Numerics;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>The benchmark's approach grid.</summary>
public static class DoorApproaches
{
    /// <summary>Headings every 5° over the half-plane facing the door.</summary>
    public static readonly int[] Headings = Range(-85, 85, 5);

    /// <summary>Lateral offsets of the aim point (the outer two aim beyond the slab's edge, within a radius of it).</summary>
    public static readonly float[] Laterals = [-0.7f, -0.45f, -0.2f, 0f, 0.2f, 0.45f, 0.7f];

    /// <summary>Speeds, metres per second.</summary>
    public static readonly float[] Speeds = [1f, 2f, 5f, 10f, 20f, 50f];

    /// <summary>Frame rates, hertz.</summary>
    public static readonly int[] Rates = [30, 10];

    /// <summary>Every combination, in a fixed order (rate, speed, lateral, heading).</summary>
    public static DoorApproach[] Grid(bool fromBack = false, int[]? rates = null, float[]? speeds = null, int[]? headings = null, float[]? laterals = null)
    {
        var list = new List<DoorApproach>();
        foreach (int hz in rates ?? Rates)
            foreach (float speed in speeds ?? Speeds)
                foreach (float lateral in laterals ?? Laterals)
                    foreach (int heading in headings ?? Headings)
                        list.Add(new DoorApproach(heading, lateral, speed, hz, fromBack));
        return list.ToArray();
    }

    private static int[] Range(int from, int to, int step)
    {
        var list = new List<int>();
        for (int i = from; i <= to; i += step)
            list.Add(i);
        return list.ToArray();
    }
}
