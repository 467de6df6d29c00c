using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The position managers in scenes: the built-in remote-smoothing and sticky-melee scenes show retail's outcomes
/// (worked out from the constants in the comments), and the manager commands name their bad values' JSON paths.
/// </summary>
public class ManagerSceneTests
{
    private static IReadOnlyList<TrajectoryFrame> Frames(Trajectory t, string mover) => t.Movers.First(m => m.Name == mover).Frames;

    [Fact]
    public void RemoteSmoothing_StopsAtTheDoor_BlipsBehindIt_ThenTeleports150m()
    {
        var frames = Frames(SceneRunner.Run(SceneLibrary.Load("remote-smoothing")), "remote");
        // Each 5 Hz update is reached at 19 m/s (0.8 m in 2 quanta) and the object waits: at frame 5 it stands on the first update.
        Assert.Equal(new Vector2(100.06f, 84.76f), new Vector2(frames[5].Position.X, frames[5].Position.Y));
        // Frames 90-103: towards (100, 101.5) but stopped by the slab's −Y face (y 99.991) at the player's radius 0.48.
        for (int f = 90; f <= 103; f++)
            Assert.True(frames[f].Position.Y < 99.991f - 0.48f + 0.01f, $"frame {f}: y {frames[f].Position.Y} is in the door");
        // The progress check of frame 99 passes (0.95 m since frame 94), frame 104's finds none: the last node fails and UseTime
        // blips to it (SetPositionSimple: retail's placement settles it 0.005 m up).
        Assert.Equal(new Vector2(100f, 101.5f), new Vector2(frames[104].Position.X, frames[104].Position.Y));
        // Frame 120: 150 m away, beyond the 100 m autonomy blip distance: teleported into the north landblock.
        Assert.Equal(0xA9B5u, frames[120].Cell >> 16);
        Assert.Equal(new Vector2(100f, 59.5f), new Vector2(frames[120].Position.X, frames[120].Position.Y));
    }

    [Fact]
    public void ReportedPositions_AreTheInterpolateToCommands_InOrder_EmptyWithoutThem()
    {
        // The remote mover's 17 updates (remote-smoothing.json): the first at frame 0, the last 150 m north in 0xA9B5.
        var scene = SceneLibrary.Load("remote-smoothing");
        var remote = scene.Movers.First(m => m.Name == "remote").ReportedPositions;
        Assert.Equal(17, remote.Count);
        Assert.Equal(new Vector3(100.06f, 84.76f, 0f), remote[0].Origin);
        Assert.Equal(new Vector3(100f, 101.5f, 0f), remote[15].Origin);
        Assert.Equal(0xA9B5u, remote[16].CellId >> 16);
        Assert.Equal(new Vector3(100f, 59.5f, 0f), remote[16].Origin);
        Assert.Equal(37, scene.Movers.Sum(m => m.ReportedPositions.Count));
        Assert.Empty(SceneLibrary.Load("run-turn").Movers[0].ReportedPositions);
    }

    [Fact]
    public void StickyMelee_KeepsThe30cmGap_UntilTheLastStickTimesOut()
    {
        var run = SceneRunner.Run(SceneLibrary.Load("sticky-melee"));
        var target = Frames(run, "target");
        var attacker = Frames(run, "attacker");
        // While stuck the cylinders keep 0.3 m apart: centres 0.48 + 0.48 + 0.3 = 1.26 m from the target where the frame
        // began (the attacker moves before the target in its frame: the target's previous frame). Checked where the target
        // walks steadily (the catch-up at 47.5 m/s closes any gap within a quantum).
        for (int f = 40; f <= 84; f++)
        {
            var d = new Vector2(target[f - 1].Position.X - attacker[f].Position.X, target[f - 1].Position.Y - attacker[f].Position.Y);
            Assert.True(Math.Abs(d.Length() - 1.26f) < 2e-3f, $"frame {f}: centres {d.Length()} m apart");
        }
        // The last StickTo (frame 55) ends 1 s later on the quantum clock: 30 quanta of (float)(1/30) exceed 1 s, so the stick ends
        // in frame 84's UseTime; from frame 85 the attacker stands while the target walks on.
        Assert.NotEqual(attacker[83].Position, attacker[84].Position);
        for (int f = 85; f < attacker.Count; f++)
            Assert.Equal(attacker[84].Position, attacker[f].Position);
        Assert.True(target[99].Position.X > target[85].Position.X + 1f);
    }

    private const string Scene = """
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [
            { "name": "a", "id": "0x5000_0002", "setup": "player", "position": [100, 90, 0], "floorZ": 0, "motionTable": "humanoid", "frames": 10, "hz": 30,
              "commands": [{ "frame": 0, "interpolateTo": [100, 95, 0] }] },
            { "name": "b", "setup": "player", "position": [100, 80, 0], "floorZ": 0, "motionTable": "humanoid", "frames": 10, "hz": 30,
              "commands": [{ "frame": 1, "stickTo": "a", "radius": 0.48, "height": 1.8 }, { "frame": 5, "unstick": true }] }
          ]
        }
        """;

    private static JsonObject Command(JsonObject doc, int mover, int i) => doc["movers"]![mover]!["commands"]![i]!.AsObject();

    private static void Refused(JsonObject doc, string path, string detail)
    {
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.StartsWith(path + ": ", ex.Message);
        Assert.Contains(detail, ex.Message);
    }

    [Fact]
    public void ManagerCommands_LoadAndRun()
    {
        var run = SceneRunner.Run(SceneLoader.Load(Scene));
        Assert.Equal(95f, Frames(run, "a")[9].Position.Y, 3); // 5 m at 19/30 m a quantum: 8 quanta
        Assert.True(Frames(run, "b")[4].Position.Y > 80.5f); // stuck to a from frame 1 (47.5 m/s), then let go at 5
        Assert.Equal(Frames(run, "b")[5].Position, Frames(run, "b")[9].Position);
    }

    [Fact]
    public void StickingToALaterOrUnknownMover_IsRefusedByPath()
    {
        var doc = JsonNode.Parse(Scene)!.AsObject();
        Command(doc, 1, 0)["stickTo"] = "c";
        Refused(doc, "movers[1].commands[0].stickTo", "not a mover given before this one");
    }

    [Fact]
    public void StickingToAMoverWithTheSameId_IsRefusedByPath()
    {
        var doc = JsonNode.Parse(Scene)!.AsObject();
        doc["movers"]![1]!["id"] = "0x5000_0002";
        Refused(doc, "movers[1].commands[0].stickTo", "different");
    }

    [Fact]
    public void AnInterpolationTargetOutsideTheLandblock_IsRefusedByPath()
    {
        var doc = JsonNode.Parse(Scene)!.AsObject();
        Command(doc, 0, 0)["interpolateTo"] = new JsonArray(100, 200, 0);
        Refused(doc, "movers[0].commands[0].interpolateTo", "landblock-local");
        doc = JsonNode.Parse(Scene)!.AsObject();
        Command(doc, 0, 0)["landblock"] = "0xFFFF";
        Refused(doc, "movers[0].commands[0].landblock", "not a landblock");
    }

    [Fact]
    public void AManagerFieldOnAnotherCommand_IsRefusedByPath()
    {
        var doc = JsonNode.Parse(Scene)!.AsObject();
        Command(doc, 1, 1)["radius"] = 1;
        Refused(doc, "movers[1].commands[1].radius", "only \"stickTo\"");
    }
}
