using System.IO;
using System.IO.Compression;
using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Tests.Parity;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// The shared ACE managers folder (shared/ace-managers) through the MoveToManager: the files that follow retail match
/// frame by frame, the blocked move matches under the named progress-clock departure, the position managers' files compared where ACE
/// follows retail and their departures named — no line says ok for what was not compared. Compiled only when the folder exists.
/// </summary>
public class SharedManagerParityTests
{
    private static ParityReport Check(string file) => ParityCheck.CheckFile(Path.Combine(SharedFolders.Find("ace-managers")!, file));

    [Theory]
    [InlineData("moveto-position.json.gz")]
    [InlineData("moveto-walk-run-threshold-retail15.json.gz")]
    [InlineData("moveto-walk-run-threshold.json.gz")]
    [InlineData("moveto-object.json.gz")]
    [InlineData("turnto-heading.json.gz")]
    public void TheRetailFollowingFiles_MatchEveryFrame(string file)
    {
        var report = Check(file);
        Assert.True(report.Passed, report.ToString());
        Assert.Equal(report.Frames, report.WithinTolerance);
        Assert.Equal(0, report.FlagMismatches);
        Assert.StartsWith($"{file}: ok", report.ToString());
    }

    [Fact]
    public void TheBlockedMove_MatchesEveryFrame_UnderTheProgressClockDeparture()
    {
        // The default rule is the client's (count only), as ACE's manager: positions bit for bit through the end; the
        // fail counts differ only by the named progress-clock offset (ours first fails at frame 89, ACE's at 92).
        var report = Check("moveto-blocked.json.gz");
        string line = report.ToString();
        Assert.True(report.Passed, line);
        Assert.StartsWith("moveto-blocked.json.gz: ok", line);
        Assert.Contains("under departure progress-clock", line);
        Assert.Contains("ours from frame 89, ACE's from frame 92", line);
        // The tool's short line keeps the verdict, the departure's name and the counts; the detail is the -v line's.
        Assert.Equal("moveto-blocked.json.gz: ok (within 1e-4 m, headings within 1e-3 deg) under departure progress-clock; 1 run, 210 frames, 210 within, 210 bit-identical, max 0 m, 0 flag mismatches (more with -v)",
            report.Summary());
        Assert.Equal(210, report.Frames);
        Assert.Equal(report.Frames, report.BitIdentical);
        Assert.Equal(0, report.FlagMismatches);
    }

    [Fact]
    public void Sticky_MatchesUntilOurStickEnds_UnderTheQuantumClockDeparture()
    {
        // Ours ends the stick in frame 32 (30 float quanta exceed 1 s), ACE's in frame 33 (README of the data: timer
        // adds a double 1/30); frames 0-32 compared, the rest named as not compared.
        var report = Check("sticky.json.gz");
        string line = report.ToString();
        Assert.True(report.Passed, line);
        Assert.StartsWith("sticky.json.gz: ok (within 1e-3 m", line);
        Assert.Contains("frames 0-32 under departure quantum-clock", line);
        Assert.Contains("frames 33-59 not compared", line);
        Assert.Equal(33, report.Frames);
        Assert.Equal(report.Frames, report.WithinTolerance);
        Assert.Equal(0, report.FlagMismatches);
    }

    [Fact]
    public void InterpolateAppliedOffset_MatchesAce_AndTheFailedNodeWhereAceThrows()
    {
        // ACE throws from frame 104 to 119 (the update behind the door failed); retail blips there: those 16 frames are
        // compared with the failed node (100, 101.5), the other 164 with ACE.
        var report = Check("interpolate-applied-offset.json.gz");
        string line = report.ToString();
        Assert.True(report.Passed, line);
        Assert.StartsWith("interpolate-applied-offset.json.gz: ok (within 1e-3 m", line);
        Assert.Contains("frames 0-103 and 120-179 under departure blip-failed-node", line);
        Assert.Contains("(16 of 16 there)", line);
        Assert.Equal(164, report.Frames);
        Assert.Equal(report.Frames, report.WithinTolerance);
    }

    [Fact]
    public void Interpolate_AsShipped_DepartsAndComparesNothing()
    {
        // ACE as shipped jumps onto the reported points (frames 6, 18, ..., 90) and throws from frame 120; ours smooths,
        // stops at the door (y 99.43), blips behind it at 104 and to the 150 m update at 120.
        var report = Check("interpolate.json.gz");
        string line = report.ToString();
        Assert.StartsWith("interpolate.json.gz: departs (nothing compared)", line);
        Assert.DoesNotContain(": ok", line);
        Assert.Equal(0, report.Frames);
        Assert.Contains("jumps onto a reported point 8 times", line);
        Assert.Contains("stops at the door at y 99.43", line);
        Assert.Contains("blips 2 times (frames 104 and 120", line);
        Assert.Contains("ends at 0xA9B50023 (100, 59.5)", line);
    }

    [Theory]
    [InlineData("sticky", "objects", "role")]
    [InlineData("interpolate", "frames[0].commands[0]", "unreadable position")]
    [InlineData("moveto-object", "objects[2].role", "did you mean \"door\"")]
    [InlineData("sticky", "objects[4].role", "did you mean \"tree\"")]
    public void APositionManagersFileWithBadInput_IsAClearErrorNamingThePath(string name, string path, string message)
    {
        // A copy of the recording in a scratch folder (beside its table), broken in one place: the sticky target's
        // object left out, the first InterpolateTo's position made unreadable, or an object the world does not build
        // (a misspelt role: refused, never ignored).
        string shared = SharedFolders.Find("ace-managers")!;
        string dir = Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}");
        Directory.CreateDirectory(dir);
        try
        {
            File.Copy(Path.Combine(shared, "table.json"), Path.Combine(dir, "table.json"));
            JsonNode root;
            using (var gz = new GZipStream(File.OpenRead(Path.Combine(shared, name + ".json.gz")), CompressionMode.Decompress))
                root = JsonNode.Parse(gz)!;
            if (path.EndsWith(".role", StringComparison.Ordinal))
            {
                int index = path[8] - '0';
                root["objects"]![index]!["role"] = path == "objects[2].role" ? "dor" : "trees";
            }
            else if (name == "sticky")
                root["objects"] = new JsonArray();
            else
                root["frames"]![0]!["commands"]![0] = "@InterpolateTo(99.9, north, 0) heading 0";
            string file = Path.Combine(dir, name + ".json.gz");
            using (var gz = new GZipStream(File.Create(file), CompressionLevel.Fastest))
                gz.Write(System.Text.Encoding.UTF8.GetBytes(root.ToJsonString()));
            var ex = Assert.Throws<SceneFormatException>(() => ParityCheck.CheckFile(file));
            Assert.Contains(path, ex.Message);
            Assert.Contains(message, ex.Message);
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }
}
