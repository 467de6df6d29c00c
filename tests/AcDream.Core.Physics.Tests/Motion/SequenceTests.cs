using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// CSequence's root motion: each whole frame crossed adds its root offset and velocity/framerate, so a cycle of N
/// frames at F frames/s covers its authored offset (N root offsets + velocity × N/F) in N/F seconds at speed 1,
/// and in half the time at speed 2 (the framerate and the velocity both double).
/// </summary>
public class SequenceTests
{
    // The humanoid's walk cycle: 8 frames at 30 frames/s, 3.12 m/s, each root offset 0.002 m forward with a sway
    // that sums to zero. One cycle: 8 × (3.12/30 + 0.002) = 0.848 m forward in 8/30 s.
    private const double WalkCycleMetres = 0.848;

    private static (Sequence Sequence, MotionTable Table) Walk(float speed)
    {
        var table = MotionTables.Humanoid();
        var walk = table.Cycles[MotionTable.CycleKey(MotionCommand.NonCombat, MotionCommand.WalkForward)];
        var sequence = new Sequence();
        sequence.Velocity = walk.Velocity * speed;
        sequence.Append(table.Animations[walk.Anims[0].AnimationId], walk.Anims[0], speed);
        return (sequence, table);
    }

    private static Vector3 Play(Sequence sequence, int quanta, float quantum)
    {
        var total = Vector3.Zero;
        for (int i = 0; i < quanta; i++)
        {
            var offset = Frame.Identity;
            sequence.Update(quantum, ref offset);
            total += offset.Origin; // straight ahead: the twists of frames 1 and 5 cancel within a cycle
        }
        return total;
    }

    [Fact]
    public void ACycleOfNFramesAtF_CoversItsAuthoredOffsetInNOverF_AtSpeed1()
    {
        // Ten cycles, 80 quanta of 1/30 s: within one frame's step (3.12/30 + 0.002 m) of ten authored offsets
        // (the first frame of each new cycle is counted on entry, so the count can lead by one frame).
        var (sequence, _) = Walk(1f);
        var moved = Play(sequence, 80, 1f / 30f);
        Assert.InRange(moved.Y, 10 * WalkCycleMetres - 1e-3, 10 * WalkCycleMetres + 0.107);
    }

    [Fact]
    public void AtSpeed2_TheSameOffsetTakesHalfTheTime()
    {
        var (sequence, _) = Walk(2f);
        var moved = Play(sequence, 40, 1f / 30f); // 40/30 s: half of ten cycles' time at speed 1
        // At speed 2 a frame is 6.24/60 + 0.002 m; ten cycles cover 10 × (8 × 0.106) = 8.48 m.
        Assert.InRange(moved.Y, 10 * WalkCycleMetres - 1e-3, 10 * WalkCycleMetres + 0.107);
    }

    [Fact]
    public void AQuantumThatCrossesNoFrame_DoesNotMove()
    {
        var (sequence, _) = Walk(1f);
        var offset = Frame.Identity;
        sequence.Update(1f / 60f, ref offset); // half a frame
        Assert.Equal(Vector3.Zero, offset.Origin);
        sequence.Update(1f / 60f, ref offset); // the other half: frame 0 crossed
        Assert.Equal(3.12 / 30 + 0.002, offset.Origin.Y, 5);
        Assert.Equal(0.003, offset.Origin.X, 5);
    }

    [Fact]
    public void ANegativeSpeed_PlaysBackwards_TakingTheRootOffsetsAway()
    {
        // Speed −1: framerate −30, velocity −3.12 m/s; every frame crossed backwards takes its root offset away and
        // adds velocity/|framerate| (backwards), so ten cycles go back as far as ten forward cycles go forward.
        var (sequence, _) = Walk(-1f);
        var moved = Play(sequence, 80, 1f / 30f);
        Assert.InRange(-moved.Y, 10 * WalkCycleMetres - 0.107, 10 * WalkCycleMetres + 0.107);
    }
}
