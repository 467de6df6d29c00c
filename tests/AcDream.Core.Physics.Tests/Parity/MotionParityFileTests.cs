using System.Diagnostics;
using System.IO;
using System.IO.Compression;
using System.Text;
using System.Threading.Tasks;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.Parity;

/// <summary>
/// The motion and manager parity files through the tool: the table file they name is read through the bounded
/// reader (a link to an endless device or a FIFO is refused unopened, on one line, exit 2), and a call the library
/// refuses while a file runs, or a garbled call, is one line naming the file, the JSON path and the field.
/// </summary>
public sealed class MotionParityFileTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("acdream-motion-parity-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private const string Table = """
        { "format": "ace-motion-table", "version": 1, "id": "0x09000001", "defaultStyle": "0x8000003D",
          "styleDefaults": { "0x8000003D": "0x41000003" },
          "cycles": { "0x003D0003": { "anims": [{ "animId": "0x03000001", "framerate": 30 }] },
                      "0x003D0005": { "flags": 1, "velocity": [0, 3.12, 0], "anims": [{ "animId": "0x03000001", "framerate": 30 }] } },
          "modifiers": {}, "links": {},
          "animations": { "0x03000001": { "numFrames": 4 } } }
        """;

    private static string MotionFile(string command) => $$"""
        { "format": "ace-motion-parity", "version": 1, "table": "table.json", "rateHz": 30,
          "mover": { "setup": "retail player: spheres", "stepUpHeight": 0.6, "stepDownHeight": 0.04, "stateBits": 1024,
                     "motionTable": "0x09000001", "scale": 1, "elasticity": 0.05, "friction": 0.95 },
          "skills": { "run": 200, "jump": 200, "burden": 0, "runRate": 2.375 },
          "start": { "cell": "0xA9B40013", "origin": [60, 60, 0], "orientation": [1, 0, 0, 0] },
          "world": { "landblock": "0xA9B4, flat terrain at z 0 (all 81 heights index 0)",
                     "door": "door slab box x -0.5..0.5, y -0.009..0.252, z 0..2.2 (object frame) at landblock-local (100,100,0), identity orientation, static",
                     "platform": "box x -4..4, y -4..4, z 0..2 (object frame) at landblock-local (60,150,0), identity orientation, static" },
          "frames": [ { "commands": ["RawState.CurrentHoldKey = Run", "{{command}}"], "quantumRan": true, "origin": [60, 60, 0], "cell": "0xA9B40013",
                        "interpreted": { "style": "0x8000003D", "forwardCommand": "0x41000003", "forwardSpeed": 1, "sidestepCommand": "0x00000000",
                                         "sidestepSpeed": 1, "turnCommand": "0x00000000", "turnSpeed": 1 } } ] }
        """;

    private static string ManagerFile(string command) => $$"""
        { "format": "ace-manager-parity", "version": 1, "table": "table.json", "rateHz": 30,
          "mover": { "setup": "retail player", "motionTable": "0x09000001", "runSkill": 200 },
          "start": { "cell": "0xA9B40013", "origin": [60, 60, 0], "orientation": [1, 0, 0, 0] },
          "frames": [ { "commands": ["@MoveToPosition (70,75)", "{{command}}"], "origin": [60, 60, 0], "cell": "0xA9B40013", "aceHeading": 0,
                        "interpreted": { "forwardCommand": "0x41000003", "forwardSpeed": 1, "turnCommand": "0x00000000", "turnSpeed": 1 } } ] }
        """;

    private void WriteGzip(string name, string json)
    {
        using var file = File.Create(Path.Combine(_dir, name));
        using var gzip = new GZipStream(file, CompressionLevel.Fastest);
        gzip.Write(Encoding.UTF8.GetBytes(json));
    }

    /// <summary>Runs the tool's parity check on the folder on a worker thread; a run that has not finished after 60 s fails (a hang).</summary>
    private (int Code, string Err) Parity()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var run = Task.Run(() => ToolProgram.Run(["parity", _dir], stdout, stderr));
        Assert.True(run.Wait(TimeSpan.FromSeconds(60)), "the tool did not finish: it blocked or ran away on the folder");
        return (run.Result, stderr.ToString());
    }

    private static void AssertOneLine(string err, string expected)
    {
        Assert.Single(err.TrimEnd().Split('\n'));
        Assert.StartsWith(expected, err);
    }

    [Theory]
    [InlineData("motion")]
    [InlineData("manager")]
    public void ATableLinkedToAnEndlessDevice_IsRefusedWithoutReadingIt(string kind)
    {
        if (!OperatingSystem.IsLinux())
            return; // /dev/zero: Linux only (CI runs Linux)
        File.CreateSymbolicLink(Path.Combine(_dir, "table.json"), "/dev/zero");
        WriteGzip("f.json.gz", kind == "motion" ? MotionFile("StopMotion(0x45000005, hold None) -> None") : ManagerFile("PhysicsObj.TurnToHeading(DesiredHeading 90) -> x"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: f.json.gz: table: table.json is empty or not a regular file (a FIFO, a socket or a device); not read.");
    }

    [Theory]
    [InlineData("motion")]
    [InlineData("manager")]
    public void ATableThatIsAFifo_IsRefusedWithoutBlocking(string kind)
    {
        if (!OperatingSystem.IsLinux())
            return; // mkfifo: Linux only (CI runs Linux)
        using (var mkfifo = Process.Start("mkfifo", Path.Combine(_dir, "table.json")))
        {
            mkfifo.WaitForExit();
            Assert.Equal(0, mkfifo.ExitCode);
        }
        WriteGzip("f.json.gz", kind == "motion" ? MotionFile("StopMotion(0x45000005, hold None) -> None") : ManagerFile("PhysicsObj.TurnToHeading(DesiredHeading 90) -> x"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: f.json.gz: table: table.json is empty or not a regular file (a FIFO, a socket or a device); not read.");
    }

    [Fact]
    public void ATableOverItsCap_IsRefusedBeforeItIsRead()
    {
        using (var file = File.Create(Path.Combine(_dir, "table.json")))
            file.SetLength(Physics.Parity.MotionParityReader.MaxTableBytes + 1L);
        WriteGzip("f.json.gz", MotionFile("StopMotion(0x45000005, hold None) -> None"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: f.json.gz: table: table.json is {Physics.Parity.MotionParityReader.MaxTableBytes + 1L} bytes; a motion table file may be at most");
    }

    [Fact]
    public void ACallTheLibraryRefusesInAMotionFile_NamesTheFileTheCommandAndTheField()
    {
        File.WriteAllText(Path.Combine(_dir, "table.json"), Table);
        // A motion the table has nothing for: the interpreter refuses it naming "motion".
        WriteGzip("m.json.gz", MotionFile("DoMotion(0x45000099, speed 1, hold None) -> None"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: m.json.gz: frames[0].commands[1]: the call was refused: motion:");
    }

    [Theory]
    [InlineData("NaN, 75, 0")]
    [InlineData("1E+30, 75, 0")]
    public void AMoveToTargetNotFinite_IsNamedAsTheTargetsOrigin_WithTheFileAndTheCommand(string xyz)
    {
        File.WriteAllText(Path.Combine(_dir, "table.json"), Table);
        WriteGzip("p.json.gz", ManagerFile($"PhysicsObj.MoveToPosition(({xyz}), MovementParameters{{CanRun, Speed 1}}) -> x"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: p.json.gz: frames[0].commands[1]: the call was refused: target.origin: must be finite and within");
        Assert.DoesNotContain("0x00000000", err);
    }

    // A manager file's reader builds or names every field it is given: an unknown one is refused, never ignored.
    [Theory]
    [InlineData("p.json.gz", "\"aceHeading\": 0,", "\"aceHeading\": 0, \"orign\": [60, 60, 0],", "frames[0].orign: unknown field \"orign\" (did you mean \"origin\"?")]
    [InlineData("sticky.json.gz", "\"aceHeading\": 0,", "\"aceHeading\": 0, \"stickey\": 1,", "frames[0].stickey: unknown field \"stickey\" (did you mean \"sticky\"?")]
    [InlineData("p.json.gz", "\"runSkill\": 200", "\"runSkill\": 200, \"runSkil\": 200", "mover.runSkil: unknown field \"runSkil\" (did you mean \"runSkill\"?")]
    public void AnUnknownFieldInAManagerFile_IsRefusedWithADidYouMean(string name, string find, string replace, string expected)
    {
        File.WriteAllText(Path.Combine(_dir, "table.json"), Table);
        string text = ManagerFile("PhysicsObj.TurnToHeading(DesiredHeading 90) -> x");
        Assert.Contains(find, text);
        WriteGzip(name, text.Replace(find, replace));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: {name}: {expected}");
    }

    [Fact]
    public void AGarbledMoveToCall_IsUnreadable_NotARawDotNetError()
    {
        File.WriteAllText(Path.Combine(_dir, "table.json"), Table);
        WriteGzip("g.json.gz", ManagerFile("PhysicsObj.MoveToPosition((70, 75"));
        var (code, err) = Parity();
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: g.json.gz: frames[0].commands[1]: unreadable position in \"PhysicsObj.MoveToPosition((70, 75\".");
        Assert.DoesNotContain("length", err);
    }
}
