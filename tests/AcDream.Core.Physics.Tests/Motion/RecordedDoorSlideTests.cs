using System.Text.Json;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// The recorded world's door is the built-in door scene's slab with its face order (−Y, +Y, +X, −X, +Z, −Z). A hold-run at
/// heading −60° (30° to the slab's −Y face) touches the face at frame 5 and slides 0.231 m along it at frame 6, as ACE
/// recorded it (ace-motion-2's run-into-door, whose first seven positions are copied here). With the box shorthand's face
/// order the swept sphere meets the −X face first at the slab's corner and the mover does not move at frame 6.
/// </summary>
public class RecordedDoorSlideTests
{
    private static readonly Vector3[] AcePositions =
    [
        new(98.100945f, 98.64333f, 0.005000025f),
        new(98.33189f, 98.776665f, 0.005000025f),
        new(98.6783f, 98.97666f, 0.005000025f),
        new(98.90924f, 99.10999f, 0.005000025f),
        new(99.14018f, 99.243324f, 0.005000025f),
        new(99.486595f, 99.44332f, 0.005000025f),
        new(99.71754f, 99.44332f, 0.005000025f),
    ];

    [Fact]
    public void AHoldRunAt30DegreesToTheDoorFace_SlidesAlongItAtFrame6()
    {
        const string world = """
            { "landblock": "0xA9B4, flat terrain at z 0 (all 81 heights index 0)",
              "door": "door slab box x -0.5..0.5, y -0.009..0.252, z 0..2.2 (object frame) at landblock-local (100,100,0), identity orientation, static",
              "platform": "box x -4..4, y -4..4, z 0..2 (object frame) at landblock-local (60,150,0), identity orientation, static" }
            """;
        using var doc = JsonDocument.Parse(world);
        var built = RecordedWorld.FromMotionFile(new JsonObj(doc.RootElement, "world"));
        var mover = MoverDescription.Player().With(stepUpHeight: 0.6f, stepDownHeight: 0.04f, physicsState: PhysicsState.Gravity, scale: 1f);
        var body = BodyState.Creature();
        body.SetElasticity(0.05f);
        body.Friction = 0.95f;
        var start = MoverState.OnFloor(new Position(0xA9B40025, new Frame(new Vector3(97.87f, 98.51f, 0f), new Quaternion(0, 0, -0.5f, 0.8660254f))), 0f);
        var run = new InterpretedMotionState
        {
            Style = 0x8000003D, ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 2.375f,
            SideStepCommand = 0, SideStepSpeed = 1f, TurnCommand = 0, TurnSpeed = 1f,
        };
        var frames = new MotionParityFrame[AcePositions.Length];
        for (int f = 0; f < frames.Length; f++)
        {
            MotionCall[] calls = f == 0
                ?
                [
                    new(MotionCallKind.HoldRun, 0, 1f, HoldKey.Run, 0f, 0, "None"),
                    new(MotionCallKind.DoMotion, MotionCommand.Ready, 1f, HoldKey.Run, 0f, 0, "None"),
                    new(MotionCallKind.DoMotion, MotionCommand.WalkForward, 1f, HoldKey.Run, 0f, 0, "None"),
                ]
                : [];
            frames[f] = new MotionParityFrame(calls, true, AcePositions[f], 0xA9B40025, true, true, run, null);
        }
        var file = new MotionParityFile("run-into-door (first 7 frames)", built, mover, MotionTables.Humanoid(), new RetailSkills(200, 200, 0f), start, body,
            1.0 / 30, frames);

        var report = MotionParityCheck.Check(file);

        Assert.True(report.Passed, report.ToString());
        Assert.Equal(7, report.Frames);
    }
}
