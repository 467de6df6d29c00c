using System.Text.Json.Nodes;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>Motion movers in scene files: "commands" through a motion table load, run, replay and name their bad values' JSON paths.</summary>
public class MotionSceneTests
{
    // A mover with an inline table of three cycles (Ready, WalkForward at 2 m/s and RunForward at 4 m/s, no root frames) walking 1 s.
    private const string Valid = """
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{
            "name": "m", "setup": "player", "position": [100, 90, 0], "floorZ": 0,
            "motionTable": {
              "id": "0x09000001", "defaultStyle": "0x8000003D", "styleDefaults": { "0x8000003D": "0x41000003" },
              "cycles": {
                "0x003D0003": { "anims": [{ "animId": "0x03000002", "framerate": 30 }] },
                "0x003D0005": { "flags": 1, "velocity": [0, 2, 0], "anims": [{ "animId": "0x03000001", "framerate": 30 }] },
                "0x003D0007": { "flags": 1, "velocity": [0, 4, 0], "anims": [{ "animId": "0x03000001", "framerate": 30 }] }
              },
              "modifiers": {}, "links": {},
              "animations": { "0x03000001": { "numFrames": 4 }, "0x03000002": { "numFrames": 4 } }
            },
            "skills": { "run": 100, "jump": 300, "burden": 0.5 },
            "frames": 45, "hz": 30,
            "commands": [
              { "frame": 0, "do": "WalkForward" },
              { "time": 1, "stop": "WalkForward" }
            ]
          }]
        }
        """;

    private static JsonObject Doc() => JsonNode.Parse(Valid)!.AsObject();
    private static JsonObject Mover(JsonObject doc) => doc["movers"]![0]!.AsObject();
    private static JsonObject Command(JsonObject doc, int i) => Mover(doc)["commands"]![i]!.AsObject();

    private static void Refused(JsonObject doc, string path, string detail)
    {
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.StartsWith(path + ": ", ex.Message);
        Assert.Contains(detail, ex.Message);
    }

    [Fact]
    public void AMotionMover_Loads_AsABodyWithOneStepAFrame()
    {
        var mover = SceneLoader.Load(Valid).Movers[0];
        Assert.True(mover.IsMotion);
        Assert.True(mover.IsBody);
        Assert.Equal(45, mover.FrameCount);
        Assert.Equal(new SceneStep(1.0 / 30, Vector3.Zero, 0f), mover.Steps[44]);
        Assert.Equal(2, mover.Commands!.Commands.Length);
        Assert.Equal(30, mover.Commands.Commands[1].Frame); // "time": 1 at 30 Hz
        Assert.Equal(100, mover.Commands.Skills!.RunSkill);
        Assert.Equal(0.5f, mover.Commands.Skills.Burden);
    }

    [Fact]
    public void WalkingOneSecond_AtTwoMetresASecond_CoversTwoMetres_ThenStops()
    {
        // The table's walk is 2 m/s of motion-data velocity and no root frames: 30 quanta of 1/30 s cover 2 m
        // (30 × 2/30, float sums: within 1e-4 m). The stop at frame 30 ends it: no link, the Ready cycle at once.
        var trajectory = SceneRunner.Run(SceneLoader.Load(Valid));
        var frames = trajectory.Movers[0].Frames;
        Assert.Equal(92f, frames[29].Position.Y, 1e-4f);
        Assert.Equal(MotionCommand.WalkForward, frames[29].Motion!.Value.Interpreted.ForwardCommand);
        Assert.Equal(MotionCommand.Ready, frames[30].Motion!.Value.Interpreted.ForwardCommand);
        Assert.Equal(92f, frames[44].Position.Y, 1e-4f);
        Assert.True(frames[44].Contact && frames[44].OnWalkable);
    }

    [Fact]
    public void TheRunKey_GivesRunForwardAtTheRunRate_OfTheMoversSkills()
    {
        // Run 100, burden 0.5 (burdenMod 1): (100/300 × 11 + 4)/4 = 1.9166666 (MovementSystem::GetRunRate).
        var doc = Doc();
        Command(doc, 0)["hold"] = "Run";
        var frames = SceneRunner.Run(SceneLoader.Load(doc.ToJsonString())).Movers[0].Frames;
        Assert.Equal(MotionCommand.RunForward, frames[0].Motion!.Value.Interpreted.ForwardCommand);
        Assert.Equal(1.9166666f, frames[0].Motion!.Value.Interpreted.ForwardSpeed, 1e-6f);
    }

    [Fact]
    public void DefaultSkills_AreRun200_AndNoSkills_IsRunRateOne()
    {
        // Run 200: (200/400 × 11 + 4)/4 = 2.375; an object without skills keeps the interpreter's own rate, 1.
        foreach (var (skills, rate) in new (JsonNode?, float)[] { (null, 2.375f), (JsonValue.Create("none"), 1f) })
        {
            var doc = Doc();
            Command(doc, 0)["hold"] = "Run";
            if (skills is null) Mover(doc).Remove("skills"); else Mover(doc)["skills"] = skills;
            var frames = SceneRunner.Run(SceneLoader.Load(doc.ToJsonString())).Movers[0].Frames;
            Assert.Equal(rate, frames[0].Motion!.Value.Interpreted.ForwardSpeed, 1e-6f);
        }
    }

    [Fact]
    public void ATurnOfOneSecondWhileRunning_Turns135Degrees_WithinOneAnimationFrame()
    {
        // run-turn's north mover turns right with the Run key for 1 s (frames 30 to 59): −π/2 rad/s × 1.5 = 135°.
        // The sequence hands out the modifier's omega per animation frame crossed (CSequence::apply_physics per
        // frame of update_internal), and the run cycle plays at 30 × 2.375 = 71.25 frames/s: the turn is quantised
        // to whole frames, within one frame's share, 135° / 71.25 = 1.9°.
        var frames = SceneRunner.Run(SceneLibrary.Load("run-turn")).Movers[0].Frames;
        double Heading(int f)
        {
            var forward = Vector3.Transform(Vector3.UnitY, frames[f].Motion!.Value.Rotation);
            return Math.Atan2(forward.X, forward.Y) * 180 / Math.PI;
        }
        Assert.Equal(0.0, Heading(29), 1e-4);
        Assert.InRange(Heading(59), 135 - 1.9, 135 + 1.9);
        Assert.Equal(Heading(59), Heading(119), 1e-4); // no turn after the stop
    }

    [Fact]
    public void TheBuiltInCreatureWalk_StepsCreaturesWithoutSkills_AtRunRateOne()
    {
        var scene = SceneLibrary.Load("creature-walk");
        Assert.All(scene.Movers, m => Assert.True(m.IsMotion && m.Commands!.Skills is null && (m.Description.Flags & ObjectInfoState.IsPlayer) == 0));
        var frames = SceneRunner.Run(scene).Movers[0].Frames;
        Assert.Equal(MotionCommand.RunForward, frames[125].Motion!.Value.Interpreted.ForwardCommand); // SetHoldKey(Run) at 4 s = frame 120
        Assert.Equal(1f, frames[125].Motion!.Value.Interpreted.ForwardSpeed);
    }

    [Fact]
    public void ATrajectoryOfAMotionMover_RoundTrips_AndAChangedCommandFailsTheReplay()
    {
        var scene = SceneLoader.Load(Valid);
        var trajectory = SceneRunner.Run(scene);
        var json = trajectory.ToJson();
        Assert.True(TrajectoryReplay.Replay(scene, Trajectory.Parse(json), ReplayTests.Exact).Matches);
        var doc = JsonNode.Parse(json)!;
        doc["movers"]![0]!["frames"]![5]!["motion"]!["forward"]!["command"] = "0x44000007";
        var result = TrajectoryReplay.Replay(scene, Trajectory.Parse(doc.ToJsonString()));
        Assert.False(result.Matches);
        Assert.Equal(5, result.FirstDifference!.Frame);
        Assert.Equal("motion.forward.command", result.FirstDifference.Field);
        doc = JsonNode.Parse(json)!;
        doc["movers"]![0]!["frames"]![7]!["motion"]!["rotation"] = new JsonArray(0.9, 0, 0, 0.1);
        Assert.Equal("motion.rotation.w", TrajectoryReplay.Replay(scene, Trajectory.Parse(doc.ToJsonString())).FirstDifference!.Field);
    }

    [Fact]
    public void BadCommands_NameTheirJsonPath()
    {
        var doc = Doc(); Command(doc, 1)["stop"] = "Dance";
        Refused(doc, "movers[0].commands[1].stop", "unknown motion command \"Dance\"");
        doc = Doc(); Command(doc, 1)["stop"] = "SideStepRight";
        Refused(doc, "movers[0].commands[1].stop", "is not in motion table 0x09000001");
        doc = Doc(); Command(doc, 0)["speed"] = 1e9;
        Refused(doc, "movers[0].commands[0].speed", "must be finite and within ±100");
        doc = Doc(); Command(doc, 0)["hold"] = "Sprint";
        Refused(doc, "movers[0].commands[0].hold", "expected \"None\" or \"Run\"");
        doc = Doc(); Command(doc, 1).Remove("stop"); Command(doc, 1)["jump"] = 1.5;
        Refused(doc, "movers[0].commands[1].jump", "must be an extent from 0 to 1");
        doc = Doc(); Command(doc, 1)["jump"] = 0.5;
        Refused(doc, "movers[0].commands[1].jump", "a command does one thing");
        doc = Doc(); Command(doc, 1)["frame"] = 3;
        Refused(doc, "movers[0].commands[1]", "exactly one of \"frame\"");
        doc = Doc(); Command(doc, 1).Remove("time"); Command(doc, 1)["frame"] = 45;
        Refused(doc, "movers[0].commands[1].frame", "must be a frame from 0 to 44");
        doc = Doc(); Command(doc, 1)["time"] = 1.5;
        Refused(doc, "movers[0].commands[1].time", "must be from 0 to the last frame's start");
        doc = Doc(); Command(doc, 0)["frame"] = 40;
        Refused(doc, "movers[0].commands[1]", "commands must be in time order");
        doc = Doc(); Command(doc, 1)["stamina"] = false;
        Refused(doc, "movers[0].commands[1].stamina", "only \"jump\" takes");
        doc = Doc(); Command(doc, 1)["giveUp"] = true;
        Refused(doc, "movers[0].commands[1].giveUp", "only \"moveTo\" takes");
        doc = Doc(); Command(doc, 1).Remove("stop"); Command(doc, 1)["moveTo"] = new JsonArray(100, 95, 0); Command(doc, 1)["giveUp"] = "yes";
        Refused(doc, "movers[0].commands[1].giveUp", "expected true or false");
        doc = Doc(); Command(doc, 1).Remove("stop"); Command(doc, 1)["moveTo"] = new JsonArray(100, 95, 0); Command(doc, 1)["giveup"] = true;
        Refused(doc, "movers[0].commands[1].giveup", "unknown field");
        doc = Doc(); Command(doc, 1)["sped"] = 2;
        Refused(doc, "movers[0].commands[1].sped", "unknown field");
        doc = Doc(); Command(doc, 1).Remove("stop");
        Refused(doc, "movers[0].commands[1]", "a command needs one of");
    }

    [Fact]
    public void BadMoverFields_NameTheirJsonPath()
    {
        var doc = Doc(); Mover(doc)["motionTable"] = "dragon";
        Refused(doc, "movers[0].motionTable", "unknown built-in motion table \"dragon\"");
        doc = Doc(); Mover(doc)["motionTable"]!["cycles"]!["0x003D0005"]!["anims"]![0]!["framerate"] = 0;
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.Contains("framerate", ex.Message);
        doc = Doc(); Mover(doc)["skills"]!["run"] = -1;
        Refused(doc, "movers[0].skills", "runSkill");
        doc = Doc(); Mover(doc)["frames"] = 0;
        Refused(doc, "movers[0].frames", "must be 1 to");
        doc = Doc(); Mover(doc)["dt"] = 0.1;
        Refused(doc, "movers[0]", "exactly one of \"dt\"");
        doc = Doc(); Mover(doc)["hz"] = -30;
        Refused(doc, "movers[0].hz", "more than zero");
        doc = Doc(); Mover(doc)["steps"] = new JsonArray(JsonNode.Parse("""{ "hz": 30 }"""));
        Refused(doc, "movers[0]", "exactly one of \"motion\"");
        doc = JsonNode.Parse(Valid)!.AsObject(); Mover(doc).Remove("commands"); Mover(doc)["motion"] = new JsonArray(new JsonArray(0, 0.1, 0));
        Refused(doc, "movers[0].motionTable", "only a mover with \"commands\"");
    }

    [Fact]
    public void SteppingAMotionMover_AllocatesNothingOnceWarm()
    {
        // The scene's run of a motion mover, per frame: its commands (a warm ObjectMotion) then the motion step.
        var scene = SceneLibrary.Load("run-jump-land");
        var mover = scene.Movers[0];
        var engine = new PhysicsEngine(scene.World);
        var start = mover.Start;
        var startBody = mover.StartBody;
        var cursor = mover.Commands!.Start(mover.Description, start, ref startBody);
        var state = start;
        var body = startBody;
        void Round()
        {
            // A fresh pass over the same motion layer: stop completely, put back at the start, then the frames.
            state = start;
            body = startBody;
            cursor.Motion.StopCompletely(mover.Description, ref state, ref body);
            for (int f = 0; f < mover.FrameCount; f++)
            {
                if (f == 0) cursor.Motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), mover.Description, ref state, ref body);
                if (f == 40) { cursor.Motion.ChargeJump(mover.Description, state, body); cursor.Motion.Jump(0.5f, true, mover.Description, ref state, ref body); }
                if (f == 100) cursor.Motion.StopMotion(MotionCommand.WalkForward, new MotionParameters(), mover.Description, ref state, ref body);
                var r = engine.Step(mover.Description, state, body, cursor.Motion, mover.Steps[f].Elapsed);
                (state, body) = (r.Next, r.Body);
            }
        }
        Assert.Equal(0, Allocations.PerRound(Round, Round));
    }
}
