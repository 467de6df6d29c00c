using System.Diagnostics;
using System.IO;
using System.IO.Compression;
using System.Text;
using System.Threading.Tasks;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;
using ToolProgram = AcDream.Core.Physics.Tool.Program;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The tool's readers cap what they read: a file over its size cap, a gzip that inflates past its cap, a
/// parity file with too many frames, and a FIFO or a device where a file should be are each refused on
/// one line naming the file and the cap, with exit code 2, without reading the file whole, crashing or
/// blocking. Oversized files are sparse (no disk is written).
/// </summary>
public sealed class ToolFileCapTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("acdream-caps-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private string Sparse(string name, long length)
    {
        string path = Path.Combine(_dir, name);
        using var file = File.Create(path);
        file.SetLength(length);
        return path;
    }

    /// <summary>Runs the tool on a worker thread; a run that has not finished after 60 s fails the test (a hang).</summary>
    private static (int Code, string Out, string Err) Tool(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var run = Task.Run(() => ToolProgram.Run(args, stdout, stderr));
        Assert.True(run.Wait(TimeSpan.FromSeconds(60)), $"the tool did not finish: {string.Join(' ', args)}");
        return (run.Result, stdout.ToString(), stderr.ToString());
    }

    private static void AssertOneLine(string err, params string[] parts)
    {
        Assert.Single(err.TrimEnd().Split('\n'));
        foreach (string part in parts)
            Assert.Contains(part, err);
    }

    [Fact]
    public void ASceneFileOverItsCap_IsRefusedBeforeItIsRead()
    {
        string big = Sparse("big.json", BoundedFile.MaxSceneBytes + 1);
        var (code, output, err) = Tool("run", big);
        Assert.Equal(2, code);
        Assert.Equal("", output);
        AssertOneLine(err, $"acdream-physics: {big}: is {BoundedFile.MaxSceneBytes + 1} bytes; a scene file may be at most {BoundedFile.MaxSceneBytes} bytes.");
    }

    [Fact]
    public void ATrajectoryFileOverItsCap_IsRefusedBeforeItIsRead()
    {
        string big = Sparse("big.trajectory.json", BoundedFile.MaxTrajectoryBytes + 1);
        var (code, _, err) = Tool("replay", "door", big);
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: {big}: is {BoundedFile.MaxTrajectoryBytes + 1} bytes; a trajectory file may be at most {BoundedFile.MaxTrajectoryBytes} bytes.");
    }

    [Fact]
    public void AParityFileOverItsCap_IsRefusedBeforeItIsRead()
    {
        Sparse("big.json.gz", BoundedFile.MaxParityBytes + 1);
        var (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: big.json.gz: (file): is {BoundedFile.MaxParityBytes + 1} bytes; a parity file may be at most {BoundedFile.MaxParityBytes} bytes.");
    }

    [Fact]
    public void AGzipThatInflatesPastItsCap_IsRefusedAtTheCap()
    {
        // A few hundred kilobytes of gzip inflating to one byte more than the cap (zeros compress ~1000:1).
        using (var file = File.Create(Path.Combine(_dir, "bomb.json.gz")))
        using (var gzip = new GZipStream(file, CompressionLevel.Fastest))
        {
            var zeros = new byte[1 << 20];
            for (long left = BoundedFile.MaxParityInflatedBytes + 1; left > 0; left -= zeros.Length)
                gzip.Write(zeros, 0, (int)Math.Min(left, zeros.Length));
        }
        Assert.True(new FileInfo(Path.Combine(_dir, "bomb.json.gz")).Length < BoundedFile.MaxParityBytes);
        var (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: bomb.json.gz: (file): holds more than {BoundedFile.MaxParityInflatedBytes} bytes; a parity file may inflate to at most that.");
    }

    [Fact]
    public void AParityFileWithMoreFramesThanItsCap_IsRefusedBeforeAnyRunIsRead()
    {
        // Eleven runs of 100 000 empty frames: 1.1 million in all; no frame is ever looked at.
        var json = new StringBuilder("""{"format": "ace-oracle-trajectories", "version": 1, "approaches": [""");
        for (int run = 0; run < 11; run++)
        {
            json.Append(run == 0 ? "{\"frames\": [" : ", {\"frames\": [");
            json.Insert(json.Length, "{},", 99_999).Append("{}]}");
        }
        json.Append("]}");
        using (var file = File.Create(Path.Combine(_dir, "many.json.gz")))
        using (var gzip = new GZipStream(file, CompressionLevel.Fastest))
            gzip.Write(Encoding.UTF8.GetBytes(json.ToString()));
        var (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: many.json.gz: approaches[10].frames: the file's runs hold more than {ParityReader.MaxFramesPerFile} frames in all.");
    }

    [Fact]
    public void AFifoGivenAsASceneOrAParityFile_IsRefusedWithoutBlocking()
    {
        if (!OperatingSystem.IsLinux())
            return; // mkfifo: Linux only (CI runs Linux)
        string fifo = Path.Combine(_dir, "scene.json");
        MakeFifo(fifo);
        MakeFifo(Path.Combine(_dir, "pipe.json.gz"));
        var (code, _, err) = Tool("run", fifo);
        Assert.Equal(2, code);
        AssertOneLine(err, $"acdream-physics: {fifo}: is empty or not a regular file (a FIFO, a socket or a device); not read.");
        (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: pipe.json.gz: (file): is empty or not a regular file");
    }

    [Fact]
    public void AScenesEntryLinkedToAnEndlessDevice_IsRefusedWithoutReadingIt()
    {
        if (!OperatingSystem.IsLinux())
            return; // /dev/zero: Linux only (CI runs Linux)
        Directory.CreateDirectory(Path.Combine(_dir, "scenes"));
        File.CreateSymbolicLink(Path.Combine(_dir, "scenes", "endless.json"), "/dev/zero");
        using (var file = File.Create(Path.Combine(_dir, "real.json.gz")))
        using (var gzip = new GZipStream(file, CompressionLevel.Fastest))
            gzip.Write(Encoding.UTF8.GetBytes("""{"format": "ace-parity-real", "version": 1, "scene": "endless.json"}"""));
        var (code, _, err) = Tool("parity", _dir);
        Assert.Equal(2, code);
        AssertOneLine(err, "acdream-physics: real.json.gz: scene: scenes/endless.json is empty or not a regular file (a FIFO, a socket or a device); not read.");
    }

    private static void MakeFifo(string path)
    {
        using var mkfifo = Process.Start("mkfifo", path);
        mkfifo.WaitForExit();
        Assert.Equal(0, mkfifo.ExitCode);
    }
}
