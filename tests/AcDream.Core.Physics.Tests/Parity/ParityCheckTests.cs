using System.Globalization;
using System.IO;
using System.IO.Compression;
using System.Text;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.Parity;

/// <summary>
/// The parity check on small files written here: both formats, the thresholds, the messages that name
/// the file, the mover or approach and the frame, and the exit codes. The expected frames are ACE's
/// results (the first four frames of the first approach of ACE's door file: a walk on flat ground at
/// z 0, which ACE resolves to z 0.004999995).
/// </summary>
public sealed class ParityCheckTests : IDisposable
{
    private readonly string _dir = Path.Combine(Path.GetTempPath(), $"acdream-parity-{Guid.NewGuid():N}");

    public ParityCheckTests() => Directory.CreateDirectory(_dir);

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private const string Approach = "front heading -85 lateral -0.7 speed 1 30 Hz";

    // ACE's first four frames of its door file's first approach.
    private static readonly string[] AceFrames =
    [
        """{"pos":[101.259186,99.33959,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""",
        """{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""",
        """{"pos":[101.19278,99.345406,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""",
        """{"pos":[101.15958,99.34831,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""",
    ];

    private static string AceFile(params string[] frames) =>
        $$"""
        {
          "format": "ace-oracle-trajectories", "version": 1,
          "scene": "door", "landblock": "0xA9B4",
          "objects": [{"id": "0x70000001", "position": [100,100,0], "state": "0x10008"}],
          "player": {"id": "0x50000001", "spheres": [[0,0,0.475,0.48],[0,0,1.35,0.48]], "stepUp": 0.6, "stepDown": 0.04, "state": "Gravity|EdgeSlide", "isPlayer": true},
          "approaches": [
            {"side": "front", "heading": -85, "lateral": -0.7, "speed": 1, "hz": 30, "start": [101.29239,99.336685,0], "offset": [-0.033206493,0.0029051937,0], "frames": [
              {{string.Join(",\n      ", frames)}}
            ]}
          ]
        }
        """;

    private string Write(string name, string json)
    {
        string path = Path.Combine(_dir, name);
        using var file = File.Create(path);
        using var gzip = new GZipStream(file, CompressionLevel.Fastest);
        gzip.Write(Encoding.UTF8.GetBytes(json));
        return path;
    }

    private static string[] With(int index, string frame)
    {
        var frames = (string[])AceFrames.Clone();
        frames[index] = frame;
        return frames;
    }

    private static string NextFloatUp(float value) =>
        BitConverter.UInt32BitsToSingle(BitConverter.SingleToUInt32Bits(value) + 1).ToString("R", CultureInfo.InvariantCulture);

    [Fact]
    public void AceDoorFile_MatchingEveryFrame_PassesBitIdentical()
    {
        var report = ParityCheck.CheckFile(Write("door.json.gz", AceFile(AceFrames)));

        Assert.True(report.Passed, report.ToString());
        Assert.True(report.RequireBitIdentical);
        Assert.Equal(1, report.Runs);
        Assert.Equal(4, report.Frames);
        Assert.Equal(4, report.BitIdentical);
        Assert.Equal(0, report.MaxDifference);
        Assert.Equal("door.json.gz: ok (bit-identical) 1 run, 4 frames, 100.00 % within 1e-4 m, 4 bit-identical, max difference 0 m, 0 flag mismatches", report.ToString());
    }

    [Fact]
    public void AWrongPosition_FailsNamingTheFileTheApproachAndTheFrame()
    {
        var frames = With(2, """{"pos":[101.19278,99.355406,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""");

        var report = ParityCheck.CheckFile(Write("trunk.json.gz", AceFile(frames)));

        Assert.False(report.Passed);
        Assert.Equal(3, report.WithinTolerance);
        Assert.StartsWith($"trunk.json.gz: '{Approach}', frame 2: position: expected (101.19278, 99.35541, 0.004999995), actual (101.19278, 99.345406, 0.004999995)", report.FirstFailure);
        Assert.Contains("FAIL", report.ToString());
    }

    [Fact]
    public void OneFloatStepOff_FailsTheDoorFile_AndPassesAnyOther()
    {
        var frames = With(1, $$"""{"pos":[{{NextFloatUp(101.22598f)}},99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""");

        var door = ParityCheck.CheckFile(Write("door.json.gz", AceFile(frames)));
        var other = ParityCheck.CheckFile(Write("door-moved.json.gz", AceFile(frames)));

        Assert.False(door.Passed);
        Assert.Contains($"'{Approach}', frame 1: position", door.FirstFailure);
        Assert.True(other.Passed, other.ToString());
        Assert.Equal(3, other.BitIdentical);
        Assert.Equal(4, other.WithinTolerance);
    }

    [Theory]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":0,"ok":1}""", "walkable: expected False, actual True")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":0,"w":1,"ok":1}""", "contact: expected False, actual True")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40026","c":1,"w":1,"ok":1}""", "cell: expected 0xA9B40026, actual 0xA9B40025")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"sl":[1,0,0],"ok":1}""", "sliding: expected True, actual False")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":0}""", "accepted: expected False, actual True")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"hit":["0x70000001"],"ok":1}""", "hits: expected [0x70000001], actual []")]
    public void AFlagThatDiffers_Fails_AndIsCounted(string frame, string message)
    {
        var report = ParityCheck.CheckFile(Write("boulder.json.gz", AceFile(With(1, frame))));

        Assert.False(report.Passed);
        Assert.Equal(1, report.FlagMismatches);
        Assert.Equal($"boulder.json.gz: '{Approach}', frame 1: {message}", report.FirstFailure);
    }

    // A flat scene with the retail player as a scene mover, for the real-cell format.
    private const string FlatScene =
        """
        {
          "version": 1, "name": "flat",
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{
            "name": "walker", "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }, { "center": [0, 0, 1.35], "radius": 0.48 }],
            "stepUpHeight": 0.6, "stepDownHeight": 0.04, "state": ["Gravity", "EdgeSlide"], "objectInfo": ["IsPlayer"],
            "position": [101.29239, 99.336685, 0], "floorZ": 0, "motion": [[-0.033206493, 0.0029051937, 0]]
          }]
        }
        """;

    private string RealFile(string cpCell = "0xA9B40025", string sceneSha = "") =>
        $$"""
        {
          "format": "ace-parity-real", "version": 1, "scene": "flat.json"{{sceneSha}},
          "movers": [
            {"name": "walker", "start": {"position": [101.29239,99.336685,0], "cell": "0xA9B40025", "rotation": [1,0,0,0], "contact": 1, "walkable": 1,
              "contactPlane": [0,0,1,0], "contactPlaneCell": "0xA9B40025", "water": 0, "sliding": null},
             "frames": [
              {"offset":[-0.033206493,0.0029051937,0],"pos":[101.259186,99.33959,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"cp":[0,0,1,0],"cpCell":"{{cpCell}}","ok":1},
              {"offset":[-0.033206493,0.0029051937,0],"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"cp":[0,0,1,0],"cpCell":"0xA9B40025","ok":1}
            ]},
            {"name": "walker-excluded", "excluded": "walks off the only loaded landblock", "frames": []}
          ]
        }
        """;

    private void WriteScene()
    {
        Directory.CreateDirectory(Path.Combine(_dir, "scenes"));
        File.WriteAllText(Path.Combine(_dir, "scenes", "flat.json"), FlatScene);
    }

    [Fact]
    public void RealCellFile_FromTheRecordedStartState_Passes_AndSkipsExcludedMovers()
    {
        WriteScene();
        string sha = $", \"sceneSha256\": \"{SceneLoader.Sha256Of(FlatScene)}\"";

        var report = ParityCheck.CheckFile(Write("flat.json.gz", RealFile(sceneSha: sha)));

        Assert.True(report.Passed, report.ToString());
        Assert.False(report.RequireBitIdentical);
        Assert.Equal(1, report.Runs);
        Assert.Equal(2, report.Frames);
    }

    [Fact]
    public void RealCellFile_AContactPlaneCellThatDiffers_Fails()
    {
        WriteScene();

        var report = ParityCheck.CheckFile(Write("flat.json.gz", RealFile(cpCell: "0xA9B40026")));

        Assert.Equal("flat.json.gz: 'walker', frame 0: contact plane cell: expected 0xA9B40026, actual 0xA9B40025", report.FirstFailure);
    }

    [Fact]
    public void RealCellFile_AChangedScene_IsRefusedNamingTheHash()
    {
        WriteScene();
        var ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(Write("flat.json.gz", RealFile(sceneSha: ", \"sceneSha256\": \"00\""))));
        Assert.Equal("sceneSha256", ex.JsonPath);
    }

    [Theory]
    [InlineData("""{"cell":"0xA9B40025","c":1,"w":1,"ok":1}""", "approaches[0].frames[1].pos", "is required.")]
    [InlineData("""{"pos":[1,2],"cell":"0xA9B40025","c":1,"w":1,"ok":1}""", "approaches[0].frames[1].pos", "a vector [x, y, z] needs 3 numbers, got 2.")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"0xA9B40025","c":2,"w":1,"ok":1}""", "approaches[0].frames[1].c", "expected 0 or 1, got the number 2.")]
    [InlineData("""{"pos":[101.22598,99.3425,0.004999995],"cell":"nope","c":1,"w":1,"ok":1}""", "approaches[0].frames[1].cell", "expected an id (a hex string such as \"0x7000_0001\" or an integer), got the string \"nope\".")]
    public void AMalformedFrame_IsRefusedNamingItsJsonPath(string frame, string path, string detail)
    {
        string file = Write("bad.json.gz", AceFile(With(1, frame)));

        var ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(file));

        Assert.Equal(path, ex.JsonPath);
        Assert.Equal(detail, ex.Detail);
    }

    [Fact]
    public void AMalformedHeader_IsRefusedNamingItsJsonPath()
    {
        var ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(Write("bad.json.gz", AceFile(AceFrames).Replace("\"door\"", "\"gate\""))));
        Assert.Equal("scene", ex.JsonPath);
        ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(Write("bad.json.gz", AceFile(AceFrames).Replace("0x70000001", "0x70000009"))));
        Assert.Equal("objects[0].id", ex.JsonPath);
        ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(Write("bad.json.gz", "{ not json")));
        Assert.Equal("", ex.JsonPath);
    }

    // A field the reader neither builds nor names is refused, never ignored (a misspelt one gets a did-you-mean).
    [Theory]
    [InlineData("\"landblock\": \"0xA9B4\",", "\"landblock\": \"0xA9B4\", \"landblok\": 1,", "landblok")]
    [InlineData("\"isPlayer\": true}", "\"isPlayer\": true, \"stepUpp\": 1}", "player.stepUpp")]
    [InlineData("\"state\": \"0x10008\"}", "\"state\": \"0x10008\", \"scale\": 2}", "objects[0].scale")]
    [InlineData("\"hz\": 30,", "\"hz\": 30, \"rate\": 30,", "approaches[0].rate")]
    public void AnUnknownFieldInAnAceFile_IsRefusedNamingIt(string find, string replace, string path)
    {
        string text = AceFile(AceFrames);
        Assert.Contains(find, text);
        var ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(Write("bad.json.gz", text.Replace(find, replace))));
        Assert.Equal(path, ex.JsonPath);
        Assert.StartsWith("unknown field", ex.Detail);
    }

    private static (int Code, string Out, string Err) Tool(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = ToolProgram.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void Tool_Parity_PrintsOneShortLinePerFile_AndEveryDetailWithV()
    {
        Write("door.json.gz", AceFile(AceFrames));
        var (code, output, _) = Tool("parity", _dir);
        Assert.Equal(0, code);
        Assert.Equal("door.json.gz: ok (bit-identical); 1 run, 4 frames, 4 within, 4 bit-identical, max 0 m, 0 flag mismatches", output.TrimEnd());
        (code, output, _) = Tool("parity", _dir, "-v");
        Assert.Equal(0, code);
        Assert.Equal("door.json.gz: ok (bit-identical) 1 run, 4 frames, 100.00 % within 1e-4 m, 4 bit-identical, max difference 0 m, 0 flag mismatches", output.TrimEnd());
    }

    [Fact]
    public void Tool_ExitCodes_ZeroOneAndTwo()
    {
        Write("door.json.gz", AceFile(AceFrames));
        var (code, output, err) = Tool("parity", _dir);
        Assert.Equal(0, code);
        Assert.StartsWith("door.json.gz: ok", output);
        Assert.Equal("", err);

        Write("trunk.json.gz", AceFile(With(3, """{"pos":[101.15958,99.34831,0.004999995],"cell":"0xA9B40025","c":1,"w":1,"ok":0}""")));
        (code, output, _) = Tool("parity", _dir);
        Assert.Equal(1, code);
        var lines = output.TrimEnd().Split('\n');
        Assert.Equal(2, lines.Length);
        Assert.Contains($"trunk.json.gz: FAIL", lines[1]);
        Assert.EndsWith($"first: trunk.json.gz: '{Approach}', frame 3: accepted: expected False, actual True", lines[1].TrimEnd());

        Write("bad.json.gz", AceFile(With(1, """{"cell":"0xA9B40025","c":1,"w":1,"ok":1}""")));
        (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        Assert.Equal("acdream-physics: bad.json.gz: approaches[0].frames[1].pos: is required.", err.TrimEnd());
    }

    [Fact]
    public void Tool_AnEmptyOrMissingDirectory_IsAUsageError()
    {
        Assert.Equal(2, Tool("parity", _dir).Code);
        Assert.Equal(2, Tool("parity", Path.Combine(_dir, "missing")).Code);
        Assert.Equal(2, Tool("parity").Code);
    }
}
