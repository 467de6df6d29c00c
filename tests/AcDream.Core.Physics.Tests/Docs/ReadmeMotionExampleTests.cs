using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Docs;

/// <summary>
/// The README's motion example (hold run 1 s, jump at extent 0.5, run until landed) against the numbers derived
/// by hand in docs/motion-example.md: 9.4667 m running (71 whole animation frames of 0.13333 m), 34 quanta in
/// the air at 9.5 m/s (10.7667 m), 33 frames ending in the air, 64 frames, the peak within 0.0007 m of 1.505 m.
/// </summary>
public class ReadmeMotionExampleTests
{
    // Float sums of about a hundred offsets at y ≈ 60 (an ulp of 4e-6 m): see the document's tolerance.
    private const float Tolerance = 1e-3f;

    [Fact]
    public void TheRunAndTheJump_CoverTheDistancesDerivedInTheDocs()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var player = MoverDescription.Player();
        var motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill: 200, jumpSkill: 200));
        var body = BodyState.Creature();
        var runner = engine.Place(player, TestGeometry.At(60f, 40f, 0f)).Next;
        motion.Place(player, runner, ref body);
        motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), player, ref runner, ref body);
        int stepped = 0, airborne = 0;
        float afterRun = float.NaN, peak = 0f;
        for (; stepped <= 30 || !runner.OnWalkable; stepped++)
        {
            Assert.True(stepped < 200, "the runner never landed");
            if (stepped == 30)
            {
                afterRun = runner.Position.Origin.Y;
                Assert.Equal(MotionError.None, motion.ChargeJump(player, runner, body));
                Assert.Equal(MotionError.None, motion.Jump(0.5f, staminaOk: true, player, ref runner, ref body));
                Assert.Equal(5.4312f, body.Velocity.Z, 1e-4f);                  // √(19.6 × 1.505)
                Assert.Equal(9.5f, body.Velocity.Y, 1e-6f);                     // 4 × 2.375
            }
            var step = engine.Step(player, runner, body, motion, 1.0 / 30);
            runner = step.Next;
            body = step.Body;
            airborne += runner.Contact ? 0 : 1;
            peak = MathF.Max(peak, runner.Position.Origin.Z - 0.005f);
        }
        Assert.Equal(40f + 71 * (9.5f / 71.25f), afterRun, Tolerance);          // 9.4667 m, not 9.5
        Assert.Equal(64, stepped);
        Assert.Equal(33, airborne);
        Assert.Equal(40f + 9.46667f + 34 * 9.5f / 30f, runner.Position.Origin.Y, Tolerance);   // 60.2333
        Assert.Equal(60f, runner.Position.Origin.X, Tolerance);
        Assert.InRange(peak, 1.505f - 0.0007f - Tolerance, 1.505f + Tolerance);
        Assert.True(runner.Contact && runner.OnWalkable);
    }
}
