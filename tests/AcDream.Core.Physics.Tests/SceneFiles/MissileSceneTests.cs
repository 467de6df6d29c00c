using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// Missile movers in scene files (a body mover with the Missile state, its "target", its hit in trajectories) and the
/// built-in <c>arrows</c> scene, checked against numbers worked out from its launches.
/// </summary>
public class MissileSceneTests
{
    private const string Valid = """
        {
          "version": 1,
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "objects": [{ "id": "0x7000_0003", "setup": "creature", "position": [100, 72, 0], "flags": ["IsCreature", "HasWeenie"] }],
          "setups": { "creature": { "cylSpheres": [{ "lowPoint": [0, 0, 0], "radius": 0.35, "height": 1.8 }] } },
          "movers": [{
            "name": "arrow", "spheres": [{ "center": [0, 0, 0], "radius": 0.05 }], "stepUpHeight": 0, "stepDownHeight": 0,
            "state": ["Missile", "PathClipped"], "target": "0x7000_0003",
            "position": [100, 62, 1], "airborne": true,
            "body": { "velocity": [0, 20, 0] },
            "steps": [{ "hz": 30, "count": 20 }]
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

    /// <summary>
    /// The goblin's face is at y = 71.65; the arrow (r = 0.05) from y = 62 at 20 m/s reaches 71.60 after 9.6 m,
    /// 14.4 quanta of 1/30 s: the 15th quantum (frame 14) reports the goblin, once.
    /// </summary>
    [Fact]
    public void AMissileMover_RunsAsAMissile_AndRecordsItsHitOnce()
    {
        var scene = SceneLoader.Load(Valid);
        Assert.True(scene.Movers[0].IsMissile);
        Assert.Equal(0x7000_0003u, scene.Movers[0].Description.TargetId);
        var frames = SceneRunner.Run(scene).Movers[0].Frames;
        var hits = frames.Select((f, i) => (f.Hit, i)).Where(x => x.Hit is not null).ToList();
        var (hit, frame) = Assert.Single(hits);
        Assert.Equal(new TrajectoryHit(MissileHitKind.Object, 0x7000_0003, 15), hit);
        Assert.Equal(14, frame);
    }

    [Fact]
    public void TheHit_SurvivesTheTrajectoryText_AndAChangedHitFailsTheReplay()
    {
        var scene = SceneLoader.Load(Valid);
        var json = SceneRunner.Run(scene).ToJson();
        Assert.True(TrajectoryReplay.Replay(scene, Trajectory.Parse(json), ReplayTests.Exact).Matches);
        var changed = Trajectory.Parse(json.Replace("\"quantum\":15", "\"quantum\":16"));
        var d = TrajectoryReplay.Replay(scene, changed).FirstDifference!;
        Assert.Equal("hit", d.Field);
        Assert.Equal(14, d.Frame);
        Assert.Equal("Object 0x70000003 in quantum 16", d.Expected);
    }

    [Fact]
    public void BadHitRecords_AreRefused_NamingThePath()
    {
        var json = SceneRunner.Run(SceneLoader.Load(Valid)).ToJson();
        var ex = Assert.Throws<SceneFormatException>(() => Trajectory.Parse(json.Replace("\"kind\":\"Object\"", "\"kind\":\"Wall\"")));
        Assert.Equal("movers[0].frames[14].hit.kind", ex.JsonPath);
        ex = Assert.Throws<SceneFormatException>(() => Trajectory.Parse(json.Replace("\"quantum\":15", "\"quantum\":0")));
        Assert.Equal("movers[0].frames[14].hit.quantum", ex.JsonPath);
        ex = Assert.Throws<SceneFormatException>(() => Trajectory.Parse(json.Replace("\"quantum\":15", "\"quantum\":15,\"quantun\":1")));
        Assert.StartsWith("movers[0].frames[14].hit.quantun", ex.JsonPath);
    }

    [Fact]
    public void AMissileStartingOnTheFloor_IsRefused()
    {
        var doc = Doc();
        Mover(doc).Remove("airborne");
        Mover(doc)["floorZ"] = 0;
        Refused(doc, "movers[0].floorZ", "a missile starts in the air");
    }

    [Fact]
    public void AMissileStepWithADesiredVelocityOrJump_IsRefused()
    {
        var doc = Doc();
        Mover(doc)["steps"] = JsonNode.Parse("""[{ "hz": 30, "count": 5 }, { "hz": 30, "velocity": [0, 1, 0] }]""");
        Refused(doc, "movers[0].steps[1]", "a missile's steps give no \"velocity\" or \"jump\"");
        Mover(doc)["steps"] = JsonNode.Parse("""[{ "hz": 30, "jump": 2 }]""");
        Refused(doc, "movers[0].steps[0]", "a missile's steps give no");
    }

    [Fact]
    public void ATargetOnAnythingButAMissile_IsRefused_AndATypoIsNamed()
    {
        var doc = Doc();
        Mover(doc)["state"] = JsonNode.Parse("""["Gravity"]""");
        Refused(doc, "movers[0].target", "only a missile");
        doc = Doc();
        Mover(doc).Remove("target");
        Mover(doc)["taget"] = "0x7000_0003";
        Refused(doc, "movers[0].taget", "did you mean \"target\"?");
    }

    [Fact]
    public void ABadLaunchVelocity_IsRefused_NamingTheBody()
    {
        var doc = Doc();
        Mover(doc)["body"] = JsonNode.Parse("""{ "velocity": [0, 2000, 0] }""");
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.StartsWith("movers[0].body.velocity", ex.Message);
    }

    /// <summary>
    /// The built-in <c>arrows</c> scene against its launches (see the scene's comments): the tree's face is at
    /// y = 69.7 and the first arrow stops in front of it; the second passes the tree and hits the goblin; the 50 m/s
    /// arrows stop before the post's face (x = 139.95 − 0.05) at both rates; the point-blank arrow hits the wall in
    /// quantum 1, in front of its face (y = 100 + 0.05); the arcing arrow lands beyond the wall at x = 70.5 after 1.95 s
    /// (quantum 59), centre at z = 0.05.
    /// </summary>
    [Fact]
    public void TheArrowsScene_HitsWhatItsLaunchesAimAt()
    {
        var t = SceneRunner.Run(SceneLibrary.Load("arrows"));
        (TrajectoryHit Hit, TrajectoryFrame Frame) HitOf(string name)
        {
            var frames = t.Movers.Single(m => m.Name == name).Frames;
            var f = Assert.Single(frames, x => x.Hit is not null);
            return (f.Hit!.Value, f);
        }
        var (tree, treeFrame) = HitOf("at-goblin-into-tree");
        Assert.Equal(MissileHitKind.Environment, tree.Kind);
        Assert.InRange(treeFrame.Position.Y, 69.65f - 0.05f, 69.65f);
        Assert.Equal(new TrajectoryHit(MissileHitKind.Object, 0x7000_0003, 12), HitOf("at-goblin-past-tree").Hit);
        foreach (string name in new[] { "fast-post-10hz", "fast-post-144hz" })
        {
            var (post, f) = HitOf(name);
            Assert.Equal(MissileHitKind.Environment, post.Kind);
            Assert.InRange(f.Position.X, 139.90f - 0.05f, 139.90f);
        }
        var (wall, wallFrame) = HitOf("point-blank-wall");
        Assert.Equal(1, wall.Quantum);
        Assert.True(wallFrame.Position.Y >= 100.05f - 1e-4f);
        var (ground, groundFrame) = HitOf("arc-over-wall");
        Assert.Equal(new TrajectoryHit(MissileHitKind.Environment, 0, 59), ground);
        Assert.Equal(70.5f, groundFrame.Position.X, 0.05f);
        Assert.Equal(0.05f, groundFrame.Position.Z, 1e-3f);
    }
}
