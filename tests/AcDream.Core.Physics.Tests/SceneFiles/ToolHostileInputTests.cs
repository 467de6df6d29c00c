using System.IO;
using AcDream.Core.Physics.Validation;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The tool against hostile scene files: names are printed escaped, the total work is bounded, and an
/// error met while running names the file and the JSON path, on one line, with exit code 2.
/// </summary>
public class ToolHostileInputTests
{
    private static (int Code, string Out, string Err) RunScene(string json, string command = "run")
    {
        string file = Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}-hostile.json");
        File.WriteAllText(file, json);
        try
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            int code = ToolProgram.Run([command, file], stdout, stderr);
            return (code, stdout.ToString(), stderr.ToString().Replace(file, "FILE"));
        }
        finally
        {
            File.Delete(file);
        }
    }

    private static string Scene(string movers) => $$"""
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{{movers}}]
        }
        """;

    [Fact]
    public void MoverNamesWithControlCharacters_ArePrintedEscaped()
    {
        var (code, output, err) = RunScene(Scene("""{ "name": "evil\u001b[31m\nred\u202e", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [[0, 0.1, 0]] }"""));
        Assert.Equal("", err);
        Assert.Equal(0, code);
        Assert.DoesNotContain('\u001b', output);
        Assert.DoesNotContain('\u202e', output);
        Assert.Contains("evil\\u001B[31m\\u000Ared\\u202E", output);
        Assert.Equal(3, output.TrimEnd().Split('\n').Length); // header, one frame, summary: the name broke no line
    }

    [Fact]
    public void MoreFramesThanTheSceneLimit_AreRefused_NamingTheFileAndTheMover()
    {
        int perMover = 100_000; // SceneLoader.MaxFramesPerMover
        int movers = InputLimits.MaxSceneFrames / perMover + 1;
        var list = Enumerable.Range(0, movers).Select(i =>
            $$"""{ "name": "m{{i}}", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [{ "offset": [0, 0, 0], "count": {{perMover}} }] }""");
        var (code, output, err) = RunScene(Scene(string.Join(",", list)));
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.StartsWith($"acdream-physics: FILE: movers[{movers - 1}].motion: the scene's movers walk more than {InputLimits.MaxSceneFrames} frames", err);
    }

    [Theory]
    [InlineData("{ \"id\": \"0xFFFF\", \"height\": 0 }", "acdream-physics: FILE: landblocks[0].id: landblock 0xFFFF is outside the retail world")]
    [InlineData("{ \"id\": \"0xA9B4\", \"height\": 1e6 }", "acdream-physics: FILE: landblocks[0].height: must be finite and within ±100000 m, got 1000000.")]
    [InlineData("{ \"id\": \"0xA9B4\", \"heights\": [0, 0, 0, 0, 0, 1e6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0] }", "acdream-physics: FILE: landblocks[0].heights[5]: must be finite and within ±100000 m, got 1000000.")]
    public void ALandblockOutsideTheWorld_OrAHeightOutOfRange_IsReportedWithTheFileAndTheJsonPath(string landblock, string expected)
    {
        var (code, output, err) = RunScene($$"""
            { "version": 1, "landblocks": [{{landblock}}], "movers": [] }
            """);
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.StartsWith(expected, err);
    }

    [Fact]
    public void AStartStateFarFromItsCell_IsReportedWithTheFileAndTheMoversPath()
    {
        var (code, output, err) = RunScene(Scene("""{ "name": "far", "setup": "player", "cell": "0xA9B40001", "position": [10000, 5, 0], "floorZ": 0, "motion": [[0, 0.1, 0]] }"""));
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.StartsWith("acdream-physics: FILE: movers[0]: mover \"far\", frame 0: state.position.origin:", err);
    }

    [Fact]
    public void AMotionTheEngineRefuses_IsReportedWithTheFileAndTheMotionItemsPath()
    {
        var (code, _, err) = RunScene(Scene("""{ "name": "m", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [[0, 0.1, 0], { "offset": [0, 0.1, 0], "count": 3 }, [99999, 0, 0]] }"""));
        Assert.Equal(2, code);
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.StartsWith("acdream-physics: FILE: movers[0].motion[2]: mover \"m\", frame 4: target.origin:", err);
    }

    [Fact]
    public void Printable_EscapesControlAndFormatCharacters_Only()
    {
        Assert.Equal("plain name é", ToolProgram.Printable("plain name é"));
        Assert.Equal("a\\u0007b\\u0000c\\u200Bd", ToolProgram.Printable("a\u0007b\0c\u200Bd"));
    }
}
