using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// EvenFrames: a steady 9.5 m/s run (RunForward at Run 200: 4 m/s × 2.375) drawn at 144 Hz. Retail's blended pose
/// steps unevenly (root motion comes in whole animation frames per quantum); the follower steps evenly, trails by its
/// lag, and changes nothing in the physics.
/// </summary>
public class EvenFramesTests
{
    private const double Dt = 1.0 / 144;
    private const float RunSpeed = 4f * 2.375f;                        // retail RunForward at Run 200
    private const float Step = RunSpeed / 144f;                        // 0.0660 m a frame

    /// <summary>Runs north for <paramref name="runSeconds"/>, then stops and stands until <paramref name="seconds"/>.</summary>
    private static List<BodyStepResult> Run(double runSeconds, double seconds)
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(100, 10, 0), 0f);
        var body = BodyState.Creature();
        var motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill: 200, jumpSkill: 200));
        motion.Place(mover, state, ref body);
        motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), mover, ref state, ref body);
        var log = new List<BodyStepResult>();
        int frames = (int)Math.Round(seconds / Dt), runFrames = (int)Math.Round(runSeconds / Dt);
        for (int i = 0; i < frames; i++)
        {
            if (i == runFrames)
                motion.StopCompletely(mover, ref state, ref body);
            var r = engine.Step(mover, state, body, motion, Dt);
            state = r.Next;
            body = r.Body;
            log.Add(r);
        }
        return log;
    }

    /// <summary>Per-frame travel of the drawn origins over frames [from, to).</summary>
    private static (float Min, float Max, float Mean) Steps(IReadOnlyList<Frame> drawn, int from, int to)
    {
        float min = float.MaxValue, max = 0f;
        for (int i = from; i < to; i++)
        {
            float d = Vector3.Distance(drawn[i].Origin, drawn[i - 1].Origin);
            min = Math.Min(min, d);
            max = Math.Max(max, d);
        }
        return (min, max, Vector3.Distance(drawn[to - 1].Origin, drawn[from - 1].Origin) / (to - from));
    }

    [Theory]
    [InlineData(0.2f, 0.02f)]                                            // the default
    [InlineData(0.1f, 0.06f)]
    public void ASteadyRunAt144Hz_RetailsPoseStepsUnevenly_EvenFramesStepsEvenly(float lag, float spread)
    {
        var run = Run(5.0, 5.0);
        var even = new EvenFrames(lag);
        var retail = run.Select(r => r.SmoothPose).ToList();
        var drawn = run.Select(r => even.Draw(r, Dt)).ToList();
        int from = 2 * 144, to = 5 * 144;                               // from 2 s: the run is steady
        var (rMin, rMax, rMean) = Steps(retail, from, to);
        var (eMin, eMax, eMean) = Steps(drawn, from, to);
        // Both travel at the run speed on average (derived above, not measured).
        Assert.InRange(rMean, Step * 0.99f, Step * 1.01f);
        Assert.InRange(eMean, Step * 0.99f, Step * 1.01f);
        // Retail's pose: 0.0444 to 0.0833 m a frame (docs/performance.md, "Drawing: even frames"): quanta of 5/144 s
        // carry two or three animation frames of 0.1333 m (9.5 m/s over 71.25 animation frames a second).
        Assert.True(rMin < Step * 0.7f && rMax > Step * 1.2f, $"retail steps {rMin:F4}..{rMax:F4} m: no longer uneven? update the docs");
        // Even frames: every step within the spread of the mean.
        Assert.True(eMin >= Step * (1 - spread) && eMax <= Step * (1 + spread),
            $"even steps {eMin:F4}..{eMax:F4} m against {Step:F4} ± {spread:P0} (retail {rMin:F4}..{rMax:F4})");
    }

    [Fact]
    public void AtASteadyRun_TheDrawnPoseTrailsTheRetailPoseByTheLag_AndNeverPassesIt()
    {
        var run = Run(5.0, 5.0);
        var even = new EvenFrames(lag: 0.1f);
        for (int i = 0; i < run.Count; i++)
        {
            var drawn = even.Draw(run[i], Dt);
            float retailY = run[i].SmoothPose.Origin.Y;
            Assert.True(drawn.Origin.Y <= retailY + 1e-4f, $"frame {i}: drawn {drawn.Origin.Y} ahead of retail {retailY}");
            // The retail pose itself strays up to half an animation frame (0.067 m) from an even path.
            if (i >= 4 * 144)
                Assert.InRange(retailY - drawn.Origin.Y, RunSpeed * 0.1f - 0.1f, RunSpeed * 0.1f + 0.1f);
        }
    }

    [Fact]
    public void AfterAStop_TheDrawnPoseComesToRestWhereTheBodyRests_WithoutOvershoot()
    {
        var run = Run(3.0, 5.0);
        var even = new EvenFrames();
        Frame drawn = default;
        foreach (var r in run)
        {
            drawn = even.Draw(r, Dt);
            Assert.True(drawn.Origin.Y <= r.Next.Position.Frame.Origin.Y + 1e-4f);
        }
        Assert.Equal(run[^1].Next.Position.Frame.Origin.Y, drawn.Origin.Y, 0.001f);
    }

    [Fact]
    public void AcrossALandblockBorder_StepsStayEven_InTheNewLandblocksSpace()
    {
        // A pose moving 0.066 m a frame from landblock 0xA9B4 into 0xA9B5 (north), in each cell's own space.
        var even = new EvenFrames();
        float last = 0f, prev = float.NaN;
        for (int i = 0; i < 600; i++)                                   // the border at frame 485
        {
            float y = 160f + i * Step;                                  // global y within the column
            uint cell = y < 192f ? 0xA9B4_0001u : 0xA9B5_0001u;
            var pose = new Frame(new Vector3(10f, y < 192f ? y : y - 192f, 0f), Quaternion.Identity);
            var drawn = even.Draw(pose, cell, Dt);
            float global = drawn.Origin.Y + (cell == 0xA9B5_0001u ? 192f : 0f);
            if (i > 300)                                                // the start's transient has died away
                Assert.InRange(global - last, Step * 0.999f, Step * 1.001f);
            prev = last;
            last = global;
        }
        Assert.False(float.IsNaN(prev));
    }

    [Fact]
    public void AJumpFartherThanTheSnapDistance_IsDrawnAtOnce_ASmallerOneIsFollowed()
    {
        var even = new EvenFrames(snapDistance: 5f);
        var at = new Frame(new Vector3(10f, 10f, 0f), Quaternion.Identity);
        Assert.Equal(at.Origin, even.Draw(at, 0xA9B4_0001u, Dt).Origin);          // the first pose is drawn as it is
        var near = new Frame(new Vector3(10f, 14f, 0f), Quaternion.Identity);
        Assert.True(even.Draw(near, 0xA9B4_0001u, Dt).Origin.Y < 11f);              // 4 m: followed
        var far = new Frame(new Vector3(10f, 40f, 0f), Quaternion.Identity);
        Assert.Equal(far.Origin, even.Draw(far, 0xA9B4_0001u, Dt).Origin);         // 30 m: a teleport
        even.Reset();
        Assert.Equal(near.Origin, even.Draw(near, 0xA9B4_0001u, Dt).Origin);
    }

    [Theory]
    [InlineData(0f, 5f, "lag")]
    [InlineData(float.NaN, 5f, "lag")]
    [InlineData(3f, 5f, "lag")]
    [InlineData(0.1f, 0f, "snapDistance")]
    [InlineData(0.1f, float.PositiveInfinity, "snapDistance")]
    public void BadSettings_AreRefused_Named(float lag, float snap, string name) =>
        Assert.Equal(name, Assert.Throws<ArgumentOutOfRangeException>(() => new EvenFrames(lag, snap)).ParamName);

    [Theory]
    [InlineData(-1.0)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void ABadElapsed_IsRefused_Named(double elapsed) =>
        Assert.Equal("elapsed", Assert.Throws<ArgumentOutOfRangeException>(() => new EvenFrames().Draw(Frame.Identity, 0xA9B4_0001u, elapsed)).ParamName);
}
