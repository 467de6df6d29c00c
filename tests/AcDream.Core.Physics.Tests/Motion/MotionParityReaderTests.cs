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

    private const string Door = "door slab box x -0.5..0.5, y -0.009..0.252, z 0..2.2 (object frame) at landblock-local (100,100,0), identity orientation, static";
    private const string Platform = "box x -4..4, y -4..4, z 0..2 (object frame) at landblock-local (60,150,0), identity orientation, static";
    private const string Box2 = "second box x -4..4, y -4..4, z 0..1 (object frame) at landblock-local (60,130,0), identity orientation, static (this recording only)";

    // The recorded world's elements as the files name them: "world" without box2 unless given.
    private static string World(string extra = "", string door = Door) =>
        $$"""{ "landblock": "0xA9B4, flat terrain at z 0 (all 81 heights index 0)", "door": "{{door}}", "platform": "{{Platform}}"{{extra}} }""";

    private static string File(string command, string world = "", string frameExtra = "") => $$"""
        { "format": "ace-motion-parity", "version": 1, "table": "table.json", "rateHz": 30,
          "mover": { "setup": "retail player: spheres", "stepUpHeight": 0.6, "stepDownHeight": 0.04, "stateBits": 1024,
                     "motionTable": "0x09000001", "scale": 1, "elasticity": 0.05, "friction": 0.95 },
          "skills": { "run": 200, "jump": 200, "burden": 0, "runRate": 2.375 },
          "start": { "cell": "0xA9B40013", "origin": [60, 60, 0], "orientation": [1, 0, 0, 0] },
          "world": {{(world.Length > 0 ? world : World())}},
          "frames": [ { "commands": ["{{command}}"], "quantumRan": true,{{frameExtra}} "origin": [60, 60.104, 0.004999995], "cell": "0xA9B40013",
                        "contact": true, "onWalkable": true,
                        "interpreted": { "style": "0x8000003D", "forwardCommand": "0x45000005", "forwardSpeed": 1, "sidestepCommand": "0x00000000",
                                         "sidestepSpeed": 1, "turnCommand": "0x00000000", "turnSpeed": 1 } } ] }
        """;

    private static (ParitySet Set, string Dir) Read(string command, string world = "", string frameExtra = "")
    {
        string dir = Path.Combine(Path.GetTempPath(), "motion-parity-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        System.IO.File.WriteAllText(Path.Combine(dir, "table.json"), Table);
        using var doc = JsonDocument.Parse(File(command, world, frameExtra));
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

    [Fact]
    public void StopCompletely_IsReadAsTheInterpretersCall()
    {
        var (set, _) = Read("PhysicsObj.StopCompletely(false) -> None");
        Assert.Equal(MotionCallKind.StopCompletely, set.Motion!.Frames[0].Calls[0].Kind);
        Assert.Equal("None", set.Motion.Frames[0].Calls[0].Expected);
    }

    [Theory]
    // A world element the reader does not build is refused, never ignored; a misspelt one gets a did-you-mean.
    [InlineData(", \"box3\": \"x\"", "world.box3", "did you mean \"box2\"")]
    [InlineData(", \"platfrom\": \"x\"", "world.platfrom", "did you mean \"platform\"")]
    public void AnUnknownWorldElement_IsRefusedWithADidYouMean(string extra, string path, string hint)
    {
        var ex = Assert.Throws<SceneFormatException>(() => Read("DoMotion(0x45000005, speed 1, hold None) -> None", World(extra)));
        Assert.Equal(path, ex.JsonPath);
        Assert.Contains(hint, ex.Detail);
    }

    [Fact]
    public void AnUnknownFrameField_IsRefusedWithADidYouMean()
    {
        var ex = Assert.Throws<SceneFormatException>(() => Read("DoMotion(0x45000005, speed 1, hold None) -> None", frameExtra: " \"slidng\": false,"));
        Assert.Equal("frames[0].slidng", ex.JsonPath);
        Assert.Contains("did you mean \"sliding\"", ex.Detail);
    }

    [Fact]
    public void ADoorDescribedElsewhere_IsRefused()
    {
        // The reader builds the recorded door (the built-in slab at (100, 100, 0)); a file whose door stands elsewhere needs another world.
        var ex = Assert.Throws<SceneFormatException>(() => Read("DoMotion(0x45000005, speed 1, hold None) -> None",
            World(door: Door.Replace("(100,100,0)", "(101,100,0)", StringComparison.Ordinal))));
        Assert.Equal("world.door", ex.JsonPath);
    }

    [Fact]
    public void Box2_IsBuiltWhereItsSentenceSays()
    {
        var (without, _) = Read("DoMotion(0x45000005, speed 1, hold None) -> None");
        var (with, _) = Read("DoMotion(0x45000005, speed 1, hold None) -> None", World($", \"box2\": \"{Box2}\""));
        Assert.Equal(2, without.World.Objects.Count);
        Assert.Equal(3, with.World.Objects.Count);
        Assert.Equal(new System.Numerics.Vector3(60, 130, 0), with.World.Objects.PositionOf(0x70000F11).Frame.Origin);
    }
}
