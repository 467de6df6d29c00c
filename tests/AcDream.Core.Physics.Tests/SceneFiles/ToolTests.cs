using System.IO;
using ToolProgram = AcDream.Core.Physics.Tool.Program;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>The acdream-physics command-line tool: exit codes, outputs and error messages.</summary>
public class ToolTests
{
    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = ToolProgram.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    private static string Temp(string name) => Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}-{name}");

    [Fact]
    public void List_PrintsTheBuiltInScenes()
    {
        var (code, output, _) = Run("list");
        Assert.Equal(0, code);
        foreach (string name in SceneLibrary.Names)
            Assert.Contains(name, output);
    }

    [Fact]
    public void List_StartsEveryDescriptionInOneColumn_PastTheLongestName()
    {
        var (_, output, _) = Run("list");
        int longest = 0;
        foreach (string name in SceneLibrary.Names)
            longest = Math.Max(longest, name.Length);
        var lines = output.TrimEnd().Split('\n');
        Assert.Equal(SceneLibrary.Names.Count, lines.Length);
        foreach (string line in lines)
        {
            string name = line[..line.IndexOf(' ')];
            Assert.Equal(SceneLibrary.Load(name).Description, line[(longest + 2)..].TrimEnd('\r'));
        }
    }

    [Fact]
    public void Run_PrintsATableAndASummary()
    {
        var (code, output, err) = Run("run", "boulder");
        Assert.Equal(0, code);
        Assert.Equal("", err);
        var lines = output.TrimEnd().Split('\n');
        Assert.StartsWith("mover", lines[0]);
        Assert.StartsWith("boulder: 4 movers, 160 frames", lines[^1]);
        Assert.Equal(1 + 160 + 1, lines.Length);
    }

    [Fact]
    public void Run_OfAMotionScene_PrintsTheHeadingAndTheCommandInEffect()
    {
        // run-turn: the Run key from frame 0 (RunForward at Run 200's rate, (200/400 × 11 + 4)/4 = 2.375), TurnRight
        // with the Run key from 1 s (× 1.5) to 2 s, the stop at 3 s (frame 90 at 30 Hz).
        var (code, output, err) = Run("run", "run-turn");
        Assert.Equal(0, code);
        Assert.Equal("", err);
        var lines = output.TrimEnd().Split('\n');
        string Line(string mover, int frame) => lines.Single(l => l.StartsWith(mover + " ", StringComparison.Ordinal)
            && l.Split(' ', StringSplitOptions.RemoveEmptyEntries)[1] == frame.ToString(System.Globalization.CultureInfo.InvariantCulture));
        Assert.EndsWith(" hdg    0.0 RunForwardx2.375 - -", Line("north", 0));
        Assert.EndsWith(" hdg   90.0 RunForwardx2.375 - -", Line("east", 0)); // rotated −90° about z: facing +X
        Assert.EndsWith(" RunForwardx2.375 - TurnRightx1.5", Line("north", 45));
        Assert.EndsWith(" Readyx1 - -", Line("north", 90));
        Assert.DoesNotContain(" hdg ", Run("run", "boulder").Out); // offset movers print no motion columns
    }

    [Fact]
    public void Record_ThenReplay_Matches_AndAnEditedFileFails()
    {
        string traj = Temp("door.json");
        try
        {
            Assert.Equal(0, Run("record", "door", "--out", traj).Code);
            var (code, output, _) = Run("replay", "door", traj);
            Assert.Equal(0, code);
            Assert.Contains("replay matches", output);

            File.WriteAllText(traj, File.ReadAllText(traj).Replace("\"position\":[100,98.1,", "\"position\":[100,98.2,"));
            (code, output, _) = Run("replay", "door", traj);
            Assert.Equal(1, code);
            Assert.Contains("mover 'front-centre', frame 0, field position.y: expected 98.2, actual 98.1", output);
        }
        finally
        {
            File.Delete(traj);
        }
    }

    [Fact]
    public void SceneFromAFile_Works()
    {
        string scene = Temp("trunk.json");
        try
        {
            File.WriteAllText(scene, SceneLibrary.ReadText("trunk"));
            Assert.Equal(0, Run("run", scene).Code);
        }
        finally
        {
            File.Delete(scene);
        }
    }

    private const string OneMoverScene = """
        {
          "version": 1, "name": "one",
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{ "name": "m", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [[0, 0.1, 0]] }]
        }
        """;

    /// <summary>Counts of one read in the singular: "1 mover, 1 frame", not "1 movers, 1 frames".</summary>
    [Fact]
    public void OneMoverOneFrame_IsCountedInTheSingular()
    {
        string scene = Temp("one.json");
        string traj = Temp("one.trajectory.json");
        try
        {
            File.WriteAllText(scene, OneMoverScene);
            var (code, output, _) = Run("record", scene, "--out", traj);
            Assert.Equal(0, code);
            Assert.StartsWith("one: 1 mover, 1 frame, 0 with a collision, 0 airborne, 0 refused; trajectory written", output);
            (code, output, _) = Run("replay", scene, traj);
            Assert.Equal(0, code);
            Assert.StartsWith("one: replay matches (1 frame, 1 mover, tolerance", output);
        }
        finally
        {
            File.Delete(scene);
            File.Delete(traj);
        }
    }

    /// <summary>The typo rule through the tool: one line naming the file, the misspelt field's path and the field meant.</summary>
    [Fact]
    public void AMisspeltField_ExitsTwo_NamingTheTypo()
    {
        string scene = Temp("typo.json");
        try
        {
            File.WriteAllText(scene, OneMoverScene.Replace("\"position\"", "\"postion\""));
            var (code, output, err) = Run("run", scene);
            Assert.Equal(2, code);
            Assert.Equal("", output);
            Assert.EndsWith($"{scene}: movers[0].postion: unknown field \"postion\"; did you mean \"position\"?", err.TrimEnd());
        }
        finally
        {
            File.Delete(scene);
        }
    }

    [Fact]
    public void Diag_PrintsTheEvents()
    {
        var (code, output, _) = Run("run", "door", "--diag");
        Assert.Equal(0, code);
        Assert.Contains("skipped 0x70000001 Cylinder[0]: BspOnlyDispatch", output);
    }

    [Theory]
    [InlineData("")]
    [InlineData("frobnicate")]
    [InlineData("run")]
    [InlineData("run no-such-scene")]
    [InlineData("record door")]
    [InlineData("replay door")]
    [InlineData("run door --bogus")]
    [InlineData("run door extra")]
    [InlineData("replay door /no/such/file.json")]
    [InlineData("replay door --tolerance -1 x.json")]
    public void UsageErrors_ExitTwo_WithAMessageAndNoStackTrace(string commandLine)
    {
        var (code, _, err) = Run(commandLine.Split(' ', StringSplitOptions.RemoveEmptyEntries));
        Assert.Equal(2, code);
        Assert.False(string.IsNullOrWhiteSpace(err));
        Assert.DoesNotContain("   at ", err);
    }

    [Fact]
    public void ABadSceneFile_ExitsTwo_WithOneLineNamingTheFileAndThePath()
    {
        string scene = Temp("bad.json");
        try
        {
            File.WriteAllText(scene, SceneLibrary.ReadText("trunk").Replace("\"radius\": 0.6,", "\"radius\": -0.6,"));
            var (code, output, err) = Run("run", scene);
            Assert.Equal(2, code);
            Assert.Equal("", output);
            Assert.Single(err.TrimEnd().Split('\n'));
            Assert.Contains($"{scene}: setups.trunk.cylSpheres[0].radius: must be", err);
        }
        finally
        {
            File.Delete(scene);
        }
    }
}
