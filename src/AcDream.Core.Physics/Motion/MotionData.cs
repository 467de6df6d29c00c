using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// What one motion plays (the DAT's MotionData): its animations in order, and the velocity and omega it adds
/// to the sequence (body axes: x right, y forward, z up; omega in rad/s about the body axes), both multiplied
/// by the motion's speed. A cycle's last animation loops; a link's animations play once.
/// </summary>
public sealed class MotionData
{
    private readonly AnimData[] _anims;

    /// <summary>Creates a motion's data; the motion table checks it (see <see cref="MotionTable"/>).</summary>
    /// <param name="bitfield">Bit 1: entering this cycle clears the modifiers, and it takes none; bit 2: the cycle may only be entered from the style's default substate.</param>
    /// <param name="flags">Which vectors are present; a vector whose flag is clear must be zero.</param>
    /// <param name="anims">The animations, in order (copied).</param>
    /// <param name="velocity">m/s, body axes.</param>
    /// <param name="omega">rad/s, body axes.</param>
    public MotionData(byte bitfield, MotionDataFlags flags, IReadOnlyList<AnimData> anims, Vector3 velocity, Vector3 omega)
    {
        ArgumentNullException.ThrowIfNull(anims);
        Bitfield = bitfield;
        Flags = flags;
        _anims = new AnimData[anims.Count];
        for (int i = 0; i < _anims.Length; i++)
            _anims[i] = anims[i];
        Velocity = velocity;
        Omega = omega;
    }

    /// <summary>Bit 1 (value 1): no modifiers with this cycle; bit 2 (value 2): entered only from the style's default substate.</summary>
    public byte Bitfield { get; }
    /// <summary>Which vectors are present.</summary>
    public MotionDataFlags Flags { get; }
    /// <summary>The animations, in order.</summary>
    public ReadOnlySpan<AnimData> Anims => _anims;
    internal AnimData[] AnimArray => _anims;
    /// <summary>The velocity this motion adds at speed 1, m/s, body axes.</summary>
    public Vector3 Velocity { get; }
    /// <summary>The omega this motion adds at speed 1, rad/s, body axes.</summary>
    public Vector3 Omega { get; }
}
