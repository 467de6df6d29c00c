using System.IO;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Tests.Parity;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// The shared ACE managers folder (shared/ace-managers) through the MoveToManager: the files that follow retail match
/// frame by frame, the blocked move matches under the named progress-clock departure, and the position managers' files are
/// listed as not compared — no line says ok for what was not compared. Compiled only when the folder exists.
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
        Assert.Equal(210, report.Frames);
        Assert.Equal(report.Frames, report.BitIdentical);
        Assert.Equal(0, report.FlagMismatches);
    }

    [Theory]
    [InlineData("sticky.json.gz")]
    [InlineData("interpolate.json.gz")]
    [InlineData("interpolate-applied-offset.json.gz")]
    public void ThePositionManagersFiles_AreListedAsNotCompared(string file)
    {
        string line = Check(file).ToString();
        Assert.Contains("not compared here", line);
        Assert.DoesNotContain("ok", line);
    }
}
