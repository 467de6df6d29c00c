using System.IO;
using System.Text.Json.Nodes;
using System.Threading;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>The committed trajectories replay bit for bit, a corrupted one fails with a readable diff, and the JSON door is the hand-built door.</summary>
public class ReplayTests
{
    /// <summary>
    /// The tolerance the suite replays committed trajectories at: none. At the replay's default (1e-5 m) the
    /// trunk, boulder and cellar replays drifted by a float step or two (from 109902e on) without a failure.
    /// </summary>
    internal const float Exact = 0f;
    private static readonly string ReplayDirectory = Path.Combine(AppContext.BaseDirectory, "Replays");

    private static string ReplayPath(string scene) => Path.Combine(ReplayDirectory, scene + ".trajectory.json");

    public static TheoryData<string> BuiltInScenes()
    {
        var data = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            data.Add(name);
        return data;
    }

    [Fact]
    public void TheLibraryHasTheBuiltInScenes()
    {
        Assert.Contains("door", SceneLibrary.Names);
        Assert.Contains("trunk", SceneLibrary.Names);
        Assert.Contains("boulder", SceneLibrary.Names);
    }

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void EveryBuiltInScene_HasACommittedReplay_ThatMatches(string name)
    {
        Assert.True(File.Exists(ReplayPath(name)), $"no committed replay for built-in scene '{name}'; record one with: acdream-physics record {name} --out tests/AcDream.Core.Physics.Tests/Replays/{name}.trajectory.json");
        var scene = SceneLibrary.Load(name);
        var trajectory = Trajectory.LoadFile(ReplayPath(name));
        var result = TrajectoryReplay.Replay(scene, trajectory, Exact);
        Assert.True(result.Matches, $"{name}: {result.FirstDifference} (re-record after a deliberate change: acdream-physics record {name} --out tests/AcDream.Core.Physics.Tests/Replays/{name}.trajectory.json)");
        Assert.Equal(trajectory.FrameCount, result.FramesCompared);
        Assert.True(result.FramesCompared > 0);
    }

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void EveryBuiltInScene_HasMoversAtSeveralHeadings(string name)
    {
        var scene = SceneLibrary.Load(name);
        // A motion mover heads where its start rotation faces (+Y of the rotation); a missile where it is launched.
        var headings = scene.Movers.Select(m => m.IsMotion ? Vector3.Transform(Vector3.UnitY, m.Start.Position.Frame.Orientation)
                : m.IsMissile ? m.StartBody.Velocity : m.IsBody ? m.Steps[0].DesiredVelocity : m.Motion[0])
            .Select(d => MathF.Round(MathF.Atan2(d.Y, d.X) * 180 / MathF.PI)).Distinct().Count();
        Assert.True(headings >= 3, $"{name}: only {headings} distinct headings");
    }

    /// <summary>
    /// One float step on one field of a committed frame fails the suite's replay: the trunk's glancing mover at
    /// frame 16, whose collision normal x is the value 109902e's double-precision normalization moved by a
    /// step. The replay's default tolerance lets the same change through.
    /// </summary>
    [Fact]
    public void OneFloatStepOnACommittedValue_FailsTheSuitesReplay()
    {
        var doc = JsonNode.Parse(File.ReadAllText(ReplayPath("trunk")))!;
        var mover = doc["movers"]!.AsArray().Single(m => m!["name"]!.GetValue<string>() == "north-glancing")!;
        var x = mover["frames"]![16]!["collisionNormal"]!["vector"]!;
        float recorded = x[0]!.GetValue<float>();
        float nextUp = BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(recorded) + 1);
        x[0] = nextUp;
        var trajectory = Trajectory.Parse(doc.ToJsonString());
        Assert.Equal(nextUp, trajectory.Movers[1].Frames[16].CollisionNormal.X);

        var result = TrajectoryReplay.Replay(SceneLibrary.Load("trunk"), trajectory, Exact);

        Assert.False(result.Matches, "a one-step change to a committed collision normal went unnoticed");
        Assert.Equal("north-glancing", result.FirstDifference!.Mover);
        Assert.Equal(16, result.FirstDifference.Frame);
        Assert.Equal("collisionNormal.vector.x", result.FirstDifference.Field);
        Assert.True(TrajectoryReplay.Replay(SceneLibrary.Load("trunk"), trajectory).Matches, "the default tolerance no longer hides a float step; this test's reason changed");
    }

    /// <summary>
    /// Two threads running the same scene at once, from one loaded scene (one world), each produce the committed
    /// trajectory bit for bit.
    /// </summary>
    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void EveryBuiltInScene_RunOnTwoThreadsAtOnce_GivesItsCommittedReplayBitForBit(string name)
    {
        var scene = SceneLibrary.Load(name);
        var committed = Trajectory.LoadFile(ReplayPath(name));
        var runs = new Trajectory?[2];
        var failures = new Exception?[2];
        using var start = new Barrier(2);
        var threads = new Thread[2];
        for (int i = 0; i < 2; i++)
        {
            int t = i;
            threads[t] = new Thread(() =>
            {
                try
                {
                    start.SignalAndWait();
                    runs[t] = SceneRunner.Run(scene);
                }
                catch (Exception ex)
                {
                    failures[t] = ex;
                }
            });
            threads[t].Start();
        }
        foreach (var thread in threads)
            thread.Join();

        for (int t = 0; t < 2; t++)
        {
            Assert.True(failures[t] is null, $"{name}, thread {t}: {failures[t]}");
            var run = runs[t]!;
            Assert.Equal(committed.Movers.Count, run.Movers.Count);
            for (int m = 0; m < run.Movers.Count; m++)
            {
                var expected = committed.Movers[m];
                Assert.Equal(expected.Frames.Count, run.Movers[m].Frames.Count);
                for (int f = 0; f < expected.Frames.Count; f++)
                {
                    var d = TrajectoryReplay.Compare(expected.Name, f, expected.Frames[f], run.Movers[m].Frames[f], Exact);
                    Assert.True(d is null, $"{name}, thread {t}: {d}");
                }
            }
        }
    }

    [Fact]
    public void ACorruptedNumber_FailsTheReplay_NamingMoverFrameAndField()
    {
        var doc = JsonNode.Parse(File.ReadAllText(ReplayPath("door")))!;
        var y = doc["movers"]![0]!["frames"]![20]!["position"]![1]!;
        float recorded = y.GetValue<float>();
        doc["movers"]![0]!["frames"]![20]!["position"]![1] = recorded + 0.001f;
        var trajectory = Trajectory.Parse(doc.ToJsonString());

        var result = TrajectoryReplay.Replay(SceneLibrary.Load("door"), trajectory);

        Assert.False(result.Matches);
        var d = result.FirstDifference!;
        Assert.Equal("front-centre", d.Mover);
        Assert.Equal(20, d.Frame);
        Assert.Equal("position.y", d.Field);
        Assert.Equal(20, result.FramesCompared);
        string text = d.ToString();
        Assert.Contains("mover 'front-centre', frame 20, field position.y", text);
        Assert.Contains($"expected {(recorded + 0.001f).ToString("R", System.Globalization.CultureInfo.InvariantCulture)}", text);
        Assert.Contains($"actual {recorded.ToString("R", System.Globalization.CultureInfo.InvariantCulture)}", text);
    }

    [Fact]
    public void ADifferenceWithinTheTolerance_StillMatches_ButIdsAreExact()
    {
        var text = File.ReadAllText(ReplayPath("door"));
        var doc = JsonNode.Parse(text)!;
        var frame = doc["movers"]![0]!["frames"]![20]!;
        frame["position"]![1] = frame["position"]![1]!.GetValue<float>() + 4e-6f;
        Assert.True(TrajectoryReplay.Replay(SceneLibrary.Load("door"), Trajectory.Parse(doc.ToJsonString())).Matches);

        doc = JsonNode.Parse(text)!;
        var hit = doc["movers"]![0]!["frames"]!.AsArray().First(f => f!["collided"]!.AsArray().Count > 0)!;
        int index = doc["movers"]![0]!["frames"]!.AsArray().IndexOf(hit);
        hit["collided"]![0] = "0x70000002";
        var result = TrajectoryReplay.Replay(SceneLibrary.Load("door"), Trajectory.Parse(doc.ToJsonString()));
        Assert.False(result.Matches);
        Assert.Equal(index, result.FirstDifference!.Frame);
        Assert.Equal("collided", result.FirstDifference.Field);
    }

    [Fact]
    public void AReplayOfAnotherScene_FailsOnTheSceneHash()
    {
        var result = TrajectoryReplay.Replay(SceneLibrary.Load("trunk"), Trajectory.LoadFile(ReplayPath("door")));
        Assert.False(result.Matches);
        Assert.Equal("sceneSha256", result.FirstDifference!.Field);
    }

    [Fact]
    public void ATrajectory_RoundTripsThroughJson_Exactly()
    {
        var trajectory = SceneRunner.Run(SceneLibrary.Load("boulder"));
        var again = Trajectory.Parse(trajectory.ToJson());
        Assert.Equal(trajectory.ToJson(), again.ToJson());
        Assert.True(TrajectoryReplay.Replay(SceneLibrary.Load("boulder"), again, Exact).Matches);
    }

    /// <summary>The door scene loaded from JSON walks like the hand-built door scene of the apparatus tests.</summary>
    [Fact]
    public void TheJsonDoor_BehavesLikeTheHandBuiltDoor()
    {
        var scene = SceneLibrary.Load("door");
        var player = Support.TestScenes.SeedPlayer();
        var trajectory = SceneRunner.Run(scene);
        Assert.Equal(scene.Movers.Count, trajectory.Movers.Count);
        for (int m = 0; m < scene.Movers.Count; m++)
        {
            var sm = scene.Movers[m];
            Assert.Equal(player.ObjectId, sm.Description.ObjectId);
            Assert.Equal(player.Spheres.ToArray(), sm.Description.Spheres.ToArray());
            Assert.Equal(player.StepUpHeight, sm.Description.StepUpHeight);
            Assert.Equal(player.StepDownHeight, sm.Description.StepDownHeight);
            Assert.Equal(player.PhysicsState, sm.Description.PhysicsState);
            Assert.Equal(player.Flags, sm.Description.Flags);

            var start = sm.Start.Position.Origin;
            var world = Support.TestScenes.Door();
            var mover = Support.TestScenes.Player(world, start.X, start.Y);
            Assert.Equal(sm.Start.Position.CellId, mover.State.Position.CellId);
            for (int f = 0; f < sm.FrameCount; f++)
            {
                var result = mover.Step(sm.Motion[f]);
                var recorded = trajectory.Movers[m].Frames[f];
                string where = $"{sm.Name} frame {f}";
                Assert.True(Vector3.Distance(recorded.Position, result.Position.Origin) <= 1e-6f, $"{where}: {recorded.Position} vs {result.Position.Origin}");
                Assert.Equal(recorded.Cell, result.Position.CellId);
                Assert.Equal(recorded.Contact, result.Next.Contact);
                Assert.Equal(recorded.OnWalkable, result.Next.OnWalkable);
                Assert.Equal(recorded.SlidingNormalValid, result.Next.SlidingNormalValid);
                Assert.True(Vector3.Distance(recorded.SlidingNormal, result.Next.SlidingNormal) <= 1e-6f, where);
                Assert.Equal(recorded.CollisionNormalValid, result.CollisionNormalValid);
                Assert.True(Vector3.Distance(recorded.CollisionNormal, result.CollisionNormal) <= 1e-6f, where);
                Assert.Equal(recorded.CollidedObjects, result.CollidedObjects.ToArray());
                Assert.Equal(recorded.Succeeded, result.Succeeded);
            }
        }
    }

    [Fact]
    public void TheJsonDoor_HasTheHandBuiltDoorsGeometry()
    {
        var json = SceneLibrary.Load("door").World.Objects.RowsInCell(0xA9B40025).ToArray();
        var hand = Support.TestScenes.Door().Objects.RowsInCell(0xA9B40025).ToArray();
        Assert.Equal(hand.Length, json.Length);
        for (int i = 0; i < hand.Length; i++)
        {
            Assert.Equal(hand[i].Kind, json[i].Kind);
            Assert.Equal(hand[i].State, json[i].State);
            Assert.Equal(hand[i].Position.Origin, json[i].Position.Origin);
            Assert.Equal(hand[i].Shape.Bounds.Center, json[i].Shape.Bounds.Center);
            Assert.Equal(hand[i].Shape.Bounds.Radius, json[i].Shape.Bounds.Radius);
            if (hand[i].Kind == ShadowShapeKind.Bsp)
            {
                var a = hand[i].Shape.Model!.Bsp;
                var b = json[i].Shape.Model!.Bsp;
                Assert.Equal(a.Nodes.Length, b.Nodes.Length);
                for (int p = 0; p < a.Polygons.Length; p++)
                {
                    Assert.Equal(a.Polygons[p].Plane, b.Polygons[p].Plane);
                    Assert.Equal(a.Polygons[p].Vertices.ToArray(), b.Polygons[p].Vertices.ToArray());
                }
                for (int n = 0; n < a.Nodes.Length; n++)
                {
                    Assert.Equal(a.Nodes[n].SplitPlane, b.Nodes[n].SplitPlane);
                    Assert.Equal(a.Nodes[n].Solid, b.Nodes[n].Solid);
                    Assert.Equal(a.Nodes[n].Front, b.Nodes[n].Front);
                    Assert.Equal(a.Nodes[n].Back, b.Nodes[n].Back);
                }
            }
        }
    }
}
