using System.IO;
using System.Text.Json;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>The ace-motion-parity reader: a malformed file is one error naming the JSON path.</summary>
public class MotionParityReaderTests
{
    private const string Table = """
        { "format": "ace-motion-table", "version": 1, "id": "0x09000001", "defaultStyle": "0x8000003D",
          "styleDefaults": { "0x8000003D": "0x41000003" },
          "cycles": { "0x003D0003": { "anims": [{ "animId": "0x03000001", "framerate": 30 }] },
                      "0x003D0005": { "flags": 1, "velocity": [0, 3.12, 0], "anims": [{ "animId": "0x03000001", "framerate": 30 }] } },
          "modifiers": {}, "links": {},
          "animations": { "0x03000001": { "numFrames": 4 } } }
        """;

    private static string File(string command) => $$"""
        { "format": "ace-motion-parity", "version": 1, "table": "table.json", "rateHz": 30,
          "mover": { "setup": "retail player: spheres", "stepUpHeight": 0.6, "stepDownHeight": 0.04, "stateBits": 1024,
                     "motionTable": "0x09000001", "scale": 1, "elasticity": 0.05, "friction": 0.95 },
          "skills": { "run": 200, "jump": 200, "burden": 0, "runRate": 2.375 },
          "start": { "cell": "0xA9B40013", "origin": [60, 60, 0], "orientation": [1, 0, 0, 0] },
          "frames": [ { "commands": ["{{command}}"], "quantumRan": true, "origin": [60, 60.104, 0.004999995], "cell": "0xA9B40013",
                        "contact": true, "onWalkable": true,
                        "interpreted": { "style": "0x8000003D", "forwardCommand": "0x45000005", "forwardSpeed": 1, "sidestepCommand": "0x00000000",
                                         "sidestepSpeed": 1, "turnCommand": "0x00000000", "turnSpeed": 1 } } ] }
        """;

    private static (ParitySet Set, string Dir) Read(string command)
    {
        string dir = Path.Combine(Path.GetTempPath(), "motion-parity-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        System.IO.File.WriteAllText(Path.Combine(dir, "table.json"), Table);
        using var doc = JsonDocument.Parse(File(command));
        try
        {
            return (ParityReader.Read(doc.RootElement, "test.json.gz", dir), dir);
        }
        finally
        {
            Directory.Delete(dir, true);
        }
    }

    [Fact]
    public void AWellFormedFile_IsReadWithItsCalls()
    {
        var (set, _) = Read("DoMotion(0x45000005, speed 1, hold None) -> None");
        Assert.NotNull(set.Motion);
        Assert.Single(set.Motion!.Frames);
        Assert.Equal(0x45000005u, set.Motion.Frames[0].Calls[0].Motion);
    }

    [Theory]
    [InlineData("Dance()", "frames[0].commands[0]")]
    [InlineData("DoMotion(0x4500, speed fast, hold None) -> None", "frames[0].commands[0]")]
    [InlineData("DoMotion(walk, speed 1) -> None", "frames[0].commands[0]")]
    public void AnUnknownOrUnreadableCall_NamesItsPath(string command, string path)
    {
        var ex = Assert.Throws<SceneFormatException>(() => Read(command));
        Assert.Equal(path, ex.JsonPath);
    }
}
