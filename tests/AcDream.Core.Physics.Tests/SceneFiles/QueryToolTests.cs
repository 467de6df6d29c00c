using System.IO;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>The tool's query and plot commands: one line per query, hand-computed answers, exit codes.</summary>
public class QueryToolTests
{
    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = ToolProgram.Run(args, stdout, stderr);
        return (code, stdout.ToString().TrimEnd(), stderr.ToString().TrimEnd());
    }

    [Theory]
    [InlineData("door floor 100 98 5", "floor z=0 normal=(0, 0, 1) terrain cell 0xA9B40025")]
    [InlineData("door floor 100 100.1 5", "floor z=2.2 normal=(0, 0, 1) object 0x70000001 cell 0xA9B40025")]
    [InlineData("door floor 100 98 5 2", "floor none within 2 m")]
    [InlineData("cottage floor 100 102 2", "floor z=0 normal=(0, 0, 1) envcell cell 0xA9B40100")]
    [InlineData("cellar floor 101.25 103 1", "floor z=-1.2 normal=(0, 0, 1) envcell cell 0xA9B40101")]
    [InlineData("cottage cell 100 102 1", "cell 0xA9B40100 (indoor) at (100, 102, 1)")]
    [InlineData("cottage cell 100 98 1", "cell 0xA9B40025 (outdoor) at (100, 98, 1)")]
    [InlineData("cottage cell -5 98 1", "cell none (no loaded cell holds the point)")]
    [InlineData("door near 100 99.7 1 0.3", "near 1 object: 0x70000001 Bsp[0]")]
    [InlineData("door near 90 90 1 2", "near none")]
    [InlineData("door cast 100 98 1 100 102 1 0.3", "cast hit fraction=0.4228 centre=(100, 99.691, 1) point=(100, 99.991, 1) normal=(0, -1, 0) object 0x70000001 cell 0xA9B40025")]
    [InlineData("door cast 90 98 1 90 102 1 0", "cast clear")]
    public void Query_PrintsOneLine(string args, string expected)
    {
        var (code, output, err) = Run(["query", .. args.Split(' ')]);
        Assert.Equal("", err);
        Assert.Equal(0, code);
        Assert.Equal(expected, output);
    }

    [Theory]
    [InlineData("query door", "query needs SCENE and floor, cell, near or cast")]
    [InlineData("query door sideways 1 2 3", "unknown query 'sideways'")]
    [InlineData("query door floor 1 2", "query floor needs X Y Z [DROP]")]
    [InlineData("query door cast 1 2 3 4 5 6 nan", "R 'nan' is not a number")]
    [InlineData("query door near 1 2 3 -1", "radius: must be a finite number of zero or more")]
    [InlineData("plot door", "plot needs --out FILE.png")]
    public void BadQueries_ExitWithTwo_AndSayWhy(string args, string message)
    {
        var (code, output, err) = Run(args.Split(' '));
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Contains(message, err);
        Assert.DoesNotContain('\n', err);
    }

    [Fact]
    public void Plot_OfAMotionScene_DrawsAHeadingTickEveryFifthFrame()
    {
        // run-turn: 120, 120 and 240 frames, a tick on frames 0, 5, 10…: 24 + 24 + 48.
        string png = Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}-run-turn.png");
        try
        {
            var (code, output, err) = Run("plot", "run-turn", "--out", png);
            Assert.Equal("", err);
            Assert.Equal(0, code);
            Assert.Contains("; 96 heading ticks; plot written to", output);
            Assert.DoesNotContain("heading ticks", Run("plot", "jump", "--out", png).Out); // body movers without a motion table have none
            Assert.DoesNotContain("reported position", output); // no interpolateTo commands
            // remote-smoothing's 37 interpolateTo commands (17 + 10 + 10 in the scene file) are drawn beside the paths.
            Assert.Contains("; 37 reported positions; plot written to", Run("plot", "remote-smoothing", "--out", png).Out);
        }
        finally
        {
            File.Delete(png);
        }
    }

    [Fact]
    public void Plot_WritesAPng_AndCountsTheCellarStairsSteps()
    {
        string png = Path.Combine(Path.GetTempPath(), $"acdream-{Guid.NewGuid():N}-cellar.png");
        try
        {
            var (code, output, err) = Run("plot", "cellar", "--out", png);
            Assert.Equal("", err);
            Assert.Equal(0, code);
            // Five treads and the cellar floor: six steps down for one climber, six up for the other.
            Assert.Contains("12 stepped", output);
            Assert.Contains("0 airborne", output);
            // The movers are numbered on the plot and named in its legend, which is printed too, in scene order.
            Assert.EndsWith("\n  1: climber-down-the-stair\n  2: climber-up-the-stair\n  3: player-at-the-top-step\n" +
                "  4: climber-diagonal-into-the-stairwell", output.Replace("\r\n", "\n"));
            var bytes = File.ReadAllBytes(png);
            Assert.True(bytes.Length > 10_000, $"the PNG has only {bytes.Length} bytes");
            Assert.Equal(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G' }, bytes[..4]);
        }
        finally
        {
            File.Delete(png);
        }
    }
}
