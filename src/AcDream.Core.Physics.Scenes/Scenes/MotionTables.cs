using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Scenes;

/// <summary>Built-in motion tables.</summary>
public static class MotionTables
{
    /// <summary>The synthetic humanoid's id.</summary>
    public const uint HumanoidId = 0x09000F00;

    /// <summary>
    /// A small synthetic humanoid (our own data, not the DAT's): the NonCombat style with cycles Ready, WalkForward
    /// (0, 3.12, 0) m/s, RunForward (0, 4, 0) m/s, SideStepRight (1.25, 0, 0) m/s and TurnRight −π/2 rad/s about z
    /// (both entered only from Ready, bitfield 2; while moving they apply as modifiers) and Falling; links
    /// Ready→WalkForward, WalkForward→Ready and RunForward→Ready. All framerates 30; only the walk cycle (8 frames)
    /// has root frames: 0.002 m forward per frame with a ±0.003 m sway and a ±0.01 rad twist on frames 1 and 5.
    /// WalkBackwards, TurnLeft and SideStepLeft have no entries: the interpreter's adjust_motion maps them to the
    /// right-handed ones at negative speed.
    /// </summary>
    public static MotionTable Humanoid()
    {
        const uint style = MotionCommand.NonCombat;
        const float turn = -1.5707964f;
        var animations = new List<Animation>
        {
            Plain(0x03000F01, 4), Walk(), Plain(0x03000F03, 6), Plain(0x03000F04, 6), Plain(0x03000F05, 6), Plain(0x03000F06, 4),
            Plain(0x03000F07, 3), Plain(0x03000F08, 3), Plain(0x03000F09, 3),
        };
        var cycles = new Dictionary<uint, MotionData>
        {
            [MotionTable.CycleKey(style, MotionCommand.Ready)] = Cycle(0, 0x03000F01, Vector3.Zero, Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.WalkForward)] = Cycle(0, 0x03000F02, new Vector3(0f, 3.12f, 0f), Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.RunForward)] = Cycle(0, 0x03000F03, new Vector3(0f, 4f, 0f), Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.SideStepRight)] = Cycle(2, 0x03000F04, new Vector3(1.25f, 0f, 0f), Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.TurnRight)] = Cycle(2, 0x03000F05, Vector3.Zero, new Vector3(0f, 0f, turn)),
            [MotionTable.CycleKey(style, MotionCommand.Falling)] = Cycle(0, 0x03000F06, Vector3.Zero, Vector3.Zero),
        };
        var modifiers = new Dictionary<uint, MotionData>
        {
            [MotionTable.CycleKey(style, MotionCommand.SideStepRight)] = new(0, MotionDataFlags.HasVelocity, [], new Vector3(1.25f, 0f, 0f), Vector3.Zero),
            [MotionTable.CycleKey(style, MotionCommand.TurnRight)] = new(0, MotionDataFlags.HasOmega, [], Vector3.Zero, new Vector3(0f, 0f, turn)),
        };
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>
        {
            [MotionTable.CycleKey(style, MotionCommand.Ready)] = new Dictionary<uint, MotionData> { [MotionCommand.WalkForward] = Link(0x03000F07) },
            [MotionTable.CycleKey(style, MotionCommand.WalkForward)] = new Dictionary<uint, MotionData> { [MotionCommand.Ready] = Link(0x03000F08) },
            [MotionTable.CycleKey(style, MotionCommand.RunForward)] = new Dictionary<uint, MotionData> { [MotionCommand.Ready] = Link(0x03000F09) },
        };
        return new MotionTable(HumanoidId, style, new Dictionary<uint, uint> { [style] = MotionCommand.Ready }, cycles, modifiers, links, animations);
    }

    private static Animation Plain(uint id, int frames) => new(id, frames, []);

    // The walk cycle's root frames: forward 0.002 m a frame, swaying ±0.003 m, twisting +0.01 rad on frame 1 and −0.01 rad on frame 5
    // (the quaternions of ±0.01 rad about z, rounded to float).
    private static Animation Walk()
    {
        var identity = Quaternion.Identity;
        var left = new Quaternion(0f, 0f, 0.004999979f, 0.9999875f);
        var right = new Quaternion(-0f, -0f, -0.004999979f, 0.9999875f);
        return new Animation(0x03000F02, 8,
        [
            new(new Vector3(0.003f, 0.002f, 0f), identity), new(new Vector3(0.003f, 0.002f, 0f), left),
            new(new Vector3(-0.003f, 0.002f, 0f), identity), new(new Vector3(-0.003f, 0.002f, 0f), identity),
            new(new Vector3(-0.003f, 0.002f, 0f), identity), new(new Vector3(-0.003f, 0.002f, 0f), right),
            new(new Vector3(0.003f, 0.002f, 0f), identity), new(new Vector3(0.003f, 0.002f, 0f), identity),
        ]);
    }

    private static MotionData Cycle(byte bitfield, uint anim, Vector3 velocity, Vector3 omega)
    {
        var flags = (velocity != Vector3.Zero ? MotionDataFlags.HasVelocity : 0) | (omega != Vector3.Zero ? MotionDataFlags.HasOmega : 0);
        return new MotionData(bitfield, flags, [new AnimData(anim, 0, -1, 30f)], velocity, omega);
    }

    private static MotionData Link(uint anim) => new(0, MotionDataFlags.None, [new AnimData(anim, 0, -1, 30f)], Vector3.Zero, Vector3.Zero);
}
