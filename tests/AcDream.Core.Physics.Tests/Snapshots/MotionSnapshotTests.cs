using System.IO;
using AcDream.Core.Physics.Tests.Motion;

namespace AcDream.Core.Physics.Tests.Snapshots;

/// <summary>Snapshot section 4: a motion mover saved mid-jump continues bit for bit; a corrupted motion section is refused naming its field.</summary>
public class MotionSnapshotTests
{
    private static string B(float f) => BitConverter.SingleToInt32Bits(f).ToString("X8");
    private static string V(Vector3 v) => $"{B(v.X)},{B(v.Y)},{B(v.Z)}";

    private static string Bits(MotionRig rig)
    {
        var f = rig.State.Position.Frame;
        var q = f.Orientation;
        var i = rig.Motion.Interpreted;
        return $"{rig.State.Position.CellId:X8} {V(f.Origin)} {B(q.X)},{B(q.Y)},{B(q.Z)},{B(q.W)} {rig.State.OnWalkable} {V(rig.Body.Velocity)} | " +
            $"{i.Style:X8} {i.ForwardCommand:X8} {B(i.ForwardSpeed)} {i.SideStepCommand:X8} {B(i.SideStepSpeed)} {i.TurnCommand:X8} {B(i.TurnSpeed)} | " +
            $"{rig.Motion.Substate:X8} {rig.Motion.CurrentAnimation:X8} {BitConverter.DoubleToInt64Bits(rig.Motion.FrameNumber):X16}";
    }

    // The commands, by frame: run forward (Run key), turn right, jump (charged to 0.6), stop turning.
    private static void Command(MotionRig rig, int frame)
    {
        if (frame == 0) rig.Do(MotionCommand.WalkForward, HoldKey.Run);
        if (frame == 8) rig.Do(MotionCommand.TurnRight, HoldKey.Run);
        if (frame == 30) Assert.Equal(MotionError.None, rig.Jump(0.6f));
        if (frame == 70) rig.Stop(MotionCommand.TurnRight, HoldKey.Run);
    }

    private static (List<string> Frames, byte[] Saved) Run(MotionRig rig, int from, int to, int saveAt)
    {
        var frames = new List<string>();
        byte[] saved = [];
        for (int i = from; i < to; i++)
        {
            if (i == saveAt)
                saved = Snapshot.SaveMover(rig.State, rig.Body, rig.Motion);
            Command(rig, i);
            rig.Frames(1);
            frames.Add(Bits(rig));
        }
        return (frames, saved);
    }

    [Fact]
    public void ARunningTurningJumperSavedMidAirAtFrame40_RestoredIntoANewEngineAndObjectMotion_ContinuesBitIdentically()
    {
        var whole = Run(new MotionRig(), 0, 100, 40);

        var rig = new MotionRig();
        Snapshot.LoadMover(whole.Saved, out rig.State, out rig.Body, rig.Motion);
        Assert.Equal(whole.Frames[39], Bits(rig));
        // Saved in the air, in the jump's cycle, with a sequence in mid-frame.
        Assert.False(rig.State.OnWalkable);
        Assert.NotEqual(0.0, rig.Motion.FrameNumber % 1.0);
        var resumed = Run(rig, 40, 100, -1);

        for (int i = 40; i < 100; i++)
            Assert.True(whole.Frames[i] == resumed.Frames[i - 40], $"frame {i}:\n  whole:   {whole.Frames[i]}\n  resumed: {resumed.Frames[i - 40]}");
        // The run lands again: the continuation covers the landing.
        Assert.True(rig.State.OnWalkable);
    }

    // The motion section's start in a snapshot (the header, then tag, length, data sections).
    private static (int Start, int End) MotionSection(byte[] bytes)
    {
        int at = 6;
        while (true)
        {
            byte tag = bytes[at];
            int length = BitConverter.ToInt32(bytes, at + 1);
            if (tag == 4)
                return (at + 5, at + 5 + length);
            at += 5 + length;
        }
    }

    [Theory]
    [InlineData("table", "snapshot motion.table (byte")]
    [InlineData("animation", "snapshot motion.sequence[")]
    [InlineData("frame number", "snapshot motion.sequence.frameNumber (byte")]
    [InlineData("modifier count", "snapshot motion.manager.modifiers.count (byte")]
    [InlineData("cut short", "snapshot motion.sequence.omega.z (byte")]
    [InlineData("missing", "snapshot motion (byte")]
    // A sequence the step could not bound (a bit-flip sweep found the first two hanging Step) or would throw on.
    [InlineData("framerate 1.29e11", "snapshot motion.sequence[")]
    [InlineData("framerate 1e6", "snapshot motion.sequence[")]
    [InlineData("frame number 1e10", "snapshot motion.sequence.frameNumber (byte")]
    [InlineData("frame number -5", "snapshot motion.sequence.frameNumber (byte")]
    [InlineData("frame number 1e6", "snapshot motion.sequence.frameNumber (byte")] // past any animation (at most 100 000 frames)
    [InlineData("velocity 1e30", "snapshot motion.sequence.velocity.x (byte")]
    [InlineData("omega 1e30", "snapshot motion.sequence.omega.z (byte")]
    public void ACorruptedMotionSection_IsRefusedNamingTheField_AndTheTargetIsUnchanged(string row, string message)
    {
        var source = new MotionRig();
        Run(source, 0, 12, -1);
        var good = Snapshot.SaveMover(source.State, source.Body, source.Motion);
        var (start, end) = MotionSection(good);
        // The sequence's tail: nodes (16 bytes each), first cyclic, current, frame number, velocity, omega.
        int frameAt = end - 32, lastNodeAt = end - 40 - 16;
        // The modifier count follows the interpreter (33 + 44 + 28 + 9 bytes, then its pending list) and four manager fields.
        int modifiersAt = start + 114 + 4 + 8 * source.Motion.Interpreter.PendingCount + 16;
        byte[] bad = row switch
        {
            "table" => Patch(good, start, BitConverter.GetBytes(0x09000F01u)),
            "animation" => Patch(good, lastNodeAt, BitConverter.GetBytes(0xDEADBEEFu)),
            "frame number" => Patch(good, frameAt, BitConverter.GetBytes(double.NaN)),
            "modifier count" => Patch(good, modifiersAt, BitConverter.GetBytes(1_000_000u)),
            "cut short" => [.. good[..(start - 4)], .. BitConverter.GetBytes(end - start - 1), .. good[start..(end - 1)]],
            "missing" => good[..(start - 5)],
            "framerate 1.29e11" => Patch(good, lastNodeAt + 12, BitConverter.GetBytes(1.29e11f)),
            "framerate 1e6" => Patch(good, lastNodeAt + 12, BitConverter.GetBytes(1e6f)),
            "frame number 1e10" => Patch(good, frameAt, BitConverter.GetBytes(1e10)),
            "frame number -5" => Patch(good, frameAt, BitConverter.GetBytes(-5.0)),
            "frame number 1e6" => Patch(good, frameAt, BitConverter.GetBytes(1e6)),
            "velocity 1e30" => Patch(good, frameAt + 8, BitConverter.GetBytes(1e30f)),
            "omega 1e30" => Patch(good, frameAt + 28, BitConverter.GetBytes(1e30f)),
            _ => throw new ArgumentException(row),
        };
        Assert.Equal((uint)source.Motion.ModifierCount, BitConverter.ToUInt32(good, modifiersAt));

        var target = new MotionRig();
        string before = Bits(target) + $" {target.Motion.AnimationCount} {target.Motion.FirstCyclicAnimation} {V(target.Motion.SequenceVelocity)}";
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadMover(bad, out _, out _, target.Motion));
        Assert.StartsWith(message, ex.Message);
        Assert.Equal(before, Bits(target) + $" {target.Motion.AnimationCount} {target.Motion.FirstCyclicAnimation} {V(target.Motion.SequenceVelocity)}");
        // The good bytes load into the same target.
        Snapshot.LoadMover(good, out _, out _, target.Motion);
        Assert.Equal(source.Motion.FrameNumber, target.Motion.FrameNumber);
    }

    private static byte[] Patch(byte[] data, int at, byte[] with)
    {
        var copy = (byte[])data.Clone();
        with.CopyTo(copy, at);
        return copy;
    }
}
