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
