using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>SmoothFrames and BodyStepResult.SmoothPose: drawing a body between quanta.</summary>
public class SmoothFramesTests
{
    private const float Speed = 4f;

    private static List<(double Time, BodyStepResult Step)> Run(double dt, double seconds)
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var state = MoverState.OnFloor(TestGeometry.At(100, 20, 0), 0f);
        var body = BodyState.Creature();
        var log = new List<(double, BodyStepResult)>();
        int frames = (int)Math.Round(seconds / dt);
        for (int i = 1; i <= frames; i++)
        {
            var r = engine.Step(MoverDescription.Player(), state, body, dt, new Vector3(0, Speed, 0));
            state = r.Next;
            body = r.Body;
            log.Add((i * dt, r));
        }
        return log;
    }

    [Fact]
    public void At144Hz_AStraightRunDrawsPositionsThatAdvanceEveryFrame_WithinOneQuantumOfThe30HzPath()
    {
        var fast = Run(1.0 / 144, 2.0);
        var slow = Run(1.0 / 30, 2.2);
        // The 30 Hz path at any time: its positions at the frame times, joined by straight lines.
        double Path(double t)
        {
            int j = (int)Math.Floor(t * 30);
            double y0 = j == 0 ? 20 : slow[j - 1].Step.Next.Position.Frame.Origin.Y;
            double y1 = slow[j].Step.Next.Position.Frame.Origin.Y;
            return y0 + (y1 - y0) * (t * 30 - j);
        }
        int firstQuantum = fast.FindIndex(f => f.Step.Quanta > 0);
        Assert.Equal(4, firstQuantum); // 5/144 s is the first gathering above 1/30 s
        // One quantum's travel: at 144 Hz a quantum runs once 5/144 s have gathered (the first sum above
        // 1/30 s), and the drawn pose is at most that quantum behind the physics.
        float oneQuantum = Speed * 5f / 144f;
        int quantaFrames = 0;
        for (int i = firstQuantum; i < fast.Count; i++)
        {
            var pose = fast[i].Step.SmoothPose;
            Assert.Equal(100f, pose.Origin.X);
            if (i > firstQuantum)
                Assert.True(pose.Origin.Y > fast[i - 1].Step.SmoothPose.Origin.Y, $"frame {i}: {pose.Origin.Y} after {fast[i - 1].Step.SmoothPose.Origin.Y}");
            double gap = Math.Abs(pose.Origin.Y - Path(fast[i].Time));
            Assert.True(gap <= oneQuantum + 1e-4, $"frame {i}: drawn {pose.Origin.Y}, 30 Hz path {Path(fast[i].Time)}");
            // Never ahead of the physics.
            Assert.True(pose.Origin.Y <= fast[i].Step.Next.Position.Frame.Origin.Y);
            if (fast[i].Step.Quanta > 0) quantaFrames++;
        }
        // Without blending only the frames with a quantum would move.
        Assert.InRange(quantaFrames, 50, 60);
    }

    [Fact]
    public void Blend_AcrossALandblockBorder_IsInTheLaterBlocksSpace()
    {
        var before = new Position((0xA9B4u << 16) | 0x39, new Frame(new Vector3(191f, 10, 1)));
        var after = new Position((0xAAB4u << 16) | 0x01, new Frame(new Vector3(1f, 10, 1)));
        var mid = SmoothFrames.Blend(before, after, 0.25f);
        Assert.Equal(new Vector3(-0.5f, 10, 1), mid.Origin);
        Assert.Equal(after.Frame.Origin, SmoothFrames.Blend(before, after, 1f).Origin);
        Assert.Equal(after.Frame.Origin, SmoothFrames.Blend(default, after, 0.5f).Origin);
    }

    [Theory]
    [InlineData(5f)]
    [InlineData(30f)]
    public void Nlerp_FollowsSlerp_WithinATenthOfADegree(float degrees)
    {
        var a = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f);
        var b = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f + degrees * MathF.PI / 180f);
        for (float t = 0; t <= 1.0001f; t += 0.125f)
        {
            var n = SmoothFrames.Nlerp(a, -b, t); // the other hemisphere: the shorter arc is still taken
            var s = Quaternion.Slerp(a, b, t);
            float cos = MathF.Min(1f, MathF.Abs(Quaternion.Dot(n, s)));
            float apart = 2f * MathF.Acos(cos) * 180f / MathF.PI;
            Assert.True(apart < 0.1f, $"t {t}: {apart}° from slerp");
            Assert.Equal(1f, n.Length(), 5);
        }
    }
}
