using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Bench.Accuracy;

/// <summary>
/// One approach to the door: a heading (degrees from straight at the face, positive towards +X), a
/// lateral offset of the aim point from the door's centre line, a speed and a frame rate. The mover
/// starts on the line through the aim point (where its centre would touch the face) a lead of at least
/// 0.3 m and 2.5 frames away, and walks a fixed step per frame until it has covered at least 1.5 m (and
/// six frames) beyond the aim point. <see cref="FromBack"/> mirrors the approach to the back face.
/// </summary>
public readonly record struct DoorApproach(int Heading, float Lateral, float Speed, int Hz, bool FromBack = false)
{
    /// <summary>The unit direction of motion.</summary>
    public Vector3 Direction
    {
        get
        {
            float rad = Heading * MathF.PI / 180f;
            return new Vector3(MathF.Sin(rad), FromBack ? -MathF.Cos(rad) : MathF.Cos(rad), 0);
        }
    }

    /// <summary>The distance walked per frame.</summary>
    public float StepLength => Speed / Hz;

    /// <summary>The requested offset per frame.</summary>
    public Vector3 StepOffset => Direction * StepLength;

    /// <summary>Where the centre would first touch the face on a head-on path.</summary>
    public Vector3 Aim => new(DoorScene.DoorOrigin.X + Lateral,
        FromBack ? DoorScene.DoorOrigin.Y + DoorScene.SlabBack + DoorScene.PlayerRadius : DoorScene.FrontStop, 0);

    /// <summary>The distance from the start to the aim point.</summary>
    public float Lead => MathF.Max(0.3f, 2.5f * StepLength);

    /// <summary>The start position.</summary>
    public Vector3 Start => Aim - Direction * Lead;

    /// <summary>The number of frames walked.</summary>
    public int Frames => Math.Min(80, (int)MathF.Ceiling(Lead / StepLength) + Math.Max(6, (int)MathF.Ceiling(1.5f / StepLength)));

    /// <summary>The tangential (along the face, X) part of one frame's step.</summary>
    public float TangentialStep => MathF.Abs(StepOffset.X);

    /// <inheritdoc />
    public override string ToString() => $"{(FromBack ? "back" : "front")} {Heading}° lateral {Lateral} m {Speed} m/s {Hz} Hz";
}

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
