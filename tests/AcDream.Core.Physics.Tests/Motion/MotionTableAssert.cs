using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Motion;

// Also compiled into the Dat tests (linked), which compare tables read through DAT files.

/// <summary>Two motion tables are the same to the bit: every key, bitfield, flag, animation, frame range, framerate, vector and root frame.</summary>
internal static class MotionTableAssert
{
    public static void Same(MotionTable expected, MotionTable actual)
    {
        Assert.Equal(expected.Id, actual.Id);
        Assert.Equal(expected.DefaultStyle, actual.DefaultStyle);
        Assert.Equal(expected.StyleDefaults.OrderBy(p => p.Key), actual.StyleDefaults.OrderBy(p => p.Key));
        SameMotions(expected.Cycles, actual.Cycles);
        SameMotions(expected.Modifiers, actual.Modifiers);
        Assert.Equal(expected.LinkKeys.Order(), actual.LinkKeys.Order());
        foreach (uint key in expected.LinkKeys)
            SameMotions(expected.LinksFrom(key)!, actual.LinksFrom(key)!);
        Assert.Equal(expected.Animations.Keys.Order(), actual.Animations.Keys.Order());
        foreach (var (id, a) in expected.Animations)
        {
            var b = actual.Animations[id];
            Assert.Equal(a.FrameCount, b.FrameCount);
            Assert.Equal(a.RootFrames.Length, b.RootFrames.Length);
            for (int i = 0; i < a.RootFrames.Length; i++)
            {
                Assert.True(SameBits(a.RootFrames[i].Origin, b.RootFrames[i].Origin), $"animation 0x{id:X8} root frame {i} origin");
                Assert.True(SameBits(a.RootFrames[i].Orientation, b.RootFrames[i].Orientation), $"animation 0x{id:X8} root frame {i} orientation");
            }
        }
    }

    private static void SameMotions(IReadOnlyDictionary<uint, MotionData> a, IReadOnlyDictionary<uint, MotionData> b)
    {
        Assert.Equal(a.Keys.Order(), b.Keys.Order());
        foreach (var (key, x) in a)
        {
            var y = b[key];
            Assert.Equal(x.Bitfield, y.Bitfield);
            Assert.Equal(x.Flags, y.Flags);
            Assert.True(SameBits(x.Velocity, y.Velocity), $"0x{key:X8} velocity");
            Assert.True(SameBits(x.Omega, y.Omega), $"0x{key:X8} omega");
            Assert.Equal(x.Anims.Length, y.Anims.Length);
            for (int i = 0; i < x.Anims.Length; i++)
            {
                Assert.Equal(x.Anims[i].AnimationId, y.Anims[i].AnimationId);
                Assert.Equal(x.Anims[i].LowFrame, y.Anims[i].LowFrame);
                Assert.Equal(x.Anims[i].HighFrame, y.Anims[i].HighFrame);
                Assert.Equal(BitConverter.SingleToInt32Bits(x.Anims[i].Framerate), BitConverter.SingleToInt32Bits(y.Anims[i].Framerate));
            }
        }
    }

    private static bool SameBits(Vector3 a, Vector3 b) =>
        BitConverter.SingleToInt32Bits(a.X) == BitConverter.SingleToInt32Bits(b.X) && BitConverter.SingleToInt32Bits(a.Y) == BitConverter.SingleToInt32Bits(b.Y)
        && BitConverter.SingleToInt32Bits(a.Z) == BitConverter.SingleToInt32Bits(b.Z);

    private static bool SameBits(Quaternion a, Quaternion b) =>
        BitConverter.SingleToInt32Bits(a.X) == BitConverter.SingleToInt32Bits(b.X) && BitConverter.SingleToInt32Bits(a.Y) == BitConverter.SingleToInt32Bits(b.Y)
        && BitConverter.SingleToInt32Bits(a.Z) == BitConverter.SingleToInt32Bits(b.Z) && BitConverter.SingleToInt32Bits(a.W) == BitConverter.SingleToInt32Bits(b.W);
}
