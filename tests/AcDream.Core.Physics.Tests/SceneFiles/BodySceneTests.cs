using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>Body movers in scene files: "steps" and "body" load, bad values name their JSON path, and trajectories round-trip.</summary>
public class BodySceneTests
{
    private const string Valid = """
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{
            "name": "b", "setup": "player", "position": [100, 98, 0], "floorZ": 0,
            "body": { "velocity": [1, 0, 0], "friction": 0.5, "elasticity": 0.1, "motionInterpreter": false },
            "steps": [{ "hz": 30, "velocity": [0, 2, 0], "jump": 4 }, { "dt": 0.05, "count": 3 }]
          }]
        }
        """;

    private static JsonObject Doc() => JsonNode.Parse(Valid)!.AsObject();
    private static JsonObject Mover(JsonObject doc) => doc["movers"]![0]!.AsObject();

    private static void Refused(JsonObject doc, string path, string detail)
    {
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.StartsWith(path + ": ", ex.Message);
        Assert.Contains(detail, ex.Message);
    }

    [Fact]
    public void ABodyMover_Loads_WithItsStepsAndBody()
    {
        var mover = SceneLoader.Load(Valid).Movers[0];
        Assert.True(mover.IsBody);
        Assert.Equal(4, mover.FrameCount);
        Assert.Equal(new SceneStep(1.0 / 30, new Vector3(0, 2, 0), 4f), mover.Steps[0]);
        Assert.Equal(new SceneStep(0.05, Vector3.Zero, 0f), mover.Steps[3]);
        Assert.Equal(new Vector3(1, 0, 0), mover.StartBody.Velocity);
        Assert.Equal(0.5f, mover.StartBody.Friction);
        Assert.Equal(0.1f, mover.StartBody.Elasticity);
        Assert.False(mover.StartBody.HasMotionInterpreter);
    }

    [Fact]
    public void WithoutABody_TheDefaultsAreRetailsCreature()
    {
        var doc = Doc();
        Mover(doc).Remove("body");
        var body = SceneLoader.Load(doc.ToJsonString()).Movers[0].StartBody;
        Assert.Equal(PhysicsConstants.DefaultFriction, body.Friction);
        Assert.Equal(PhysicsConstants.DefaultElasticity, body.Elasticity);
        Assert.True(body.HasMotionInterpreter);
    }

    [Fact]
    public void MotionAndSteps_Together_AreRefused()
    {
        var doc = Doc();
        Mover(doc)["motion"] = JsonNode.Parse("[[0, 0.1, 0]]");
        Refused(doc, "movers[0]", "exactly one of \"motion\"");
    }

    [Fact]
    public void ABodyWithoutSteps_IsRefused()
    {
        var doc = Doc();
        Mover(doc).Remove("steps");
        Mover(doc)["motion"] = JsonNode.Parse("[[0, 0.1, 0]]");
        Refused(doc, "movers[0].body", "only a mover with \"steps\"");
    }

    [Theory]
    [InlineData("steps", 1, "dt", "-0.1", "movers[0].steps[1].dt", "zero or more seconds")]
    [InlineData("steps", 0, "hz", "0", "movers[0].steps[0].hz", "more than zero")]
    [InlineData("steps", 0, "jump", "-2", "movers[0].steps[0].jump", "zero or more")]
    [InlineData("steps", 1, "count", "0", "movers[0].steps[1].count", "1 or more")]
    [InlineData("steps", 0, "velocity", "[1e30, 0, 0]", "movers[0].steps[0].velocity", "per second")]
    [InlineData("body", -1, "friction", "1.5", "movers[0].body.friction", "from 0 to 1")]
    [InlineData("body", -1, "elasticity", "-0.1", "movers[0].body.elasticity", "from 0 to 1")]
    [InlineData("body", -1, "spin", "[0, 0, 1]", "movers[0].body.spin", "unknown")]
    public void BadBodyValues_NameTheirPath(string where, int index, string field, string value, string path, string detail)
    {
        var doc = Doc();
        var target = index < 0 ? Mover(doc)[where]!.AsObject() : Mover(doc)[where]![index]!.AsObject();
        target[field] = JsonNode.Parse(value);
        Refused(doc, path, detail);
    }

    [Fact]
    public void AStepWithBothDtAndHz_IsRefused()
    {
        var doc = Doc();
        Mover(doc)["steps"]![0]!["dt"] = 0.1;
        Refused(doc, "movers[0].steps[0]", "exactly one of \"dt\"");
    }

    [Fact]
    public void ABodyTrajectory_RoundTrips_AndReplays()
    {
        var scene = SceneLoader.Load(Valid);
        var trajectory = SceneRunner.Run(scene);
        var frame = trajectory.Movers[0].Frames[0];
        Assert.Equal(scene.Movers[0].Steps[0], frame.Step);
        Assert.Equal(1, frame.Quanta);
        var read = Trajectory.Parse(trajectory.ToJson());
        Assert.Equal(trajectory.ToJson(), read.ToJson());
        Assert.True(TrajectoryReplay.Replay(scene, read, ReplayTests.Exact).Matches);
    }

    [Fact]
    public void ACorruptedBodyVelocity_FailsTheReplay_NamingTheField()
    {
        var scene = SceneLoader.Load(Valid);
        var doc = JsonNode.Parse(SceneRunner.Run(scene).ToJson())!;
        doc["movers"]![0]!["frames"]![2]!["body"]!["velocity"]![0] = 7.5;
        var result = TrajectoryReplay.Replay(scene, Trajectory.Parse(doc.ToJsonString()));
        Assert.False(result.Matches);
        Assert.Equal(2, result.FirstDifference!.Frame);
        Assert.Equal("body.velocity.x", result.FirstDifference.Field);
    }

    [Fact]
    public void ABodyFrameWithoutItsBodyOutput_IsRefused()
    {
        var doc = JsonNode.Parse(SceneRunner.Run(SceneLoader.Load(Valid)).ToJson())!;
        doc["movers"]![0]!["frames"]![1]!.AsObject().Remove("body");
        var ex = Assert.Throws<SceneFormatException>(() => Trajectory.Parse(doc.ToJsonString()));
        Assert.StartsWith("movers[0].frames[1].body: ", ex.Message);
    }
}
