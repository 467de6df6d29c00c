using System.IO;
using AcDream.Core.Physics.Parity;

namespace AcDream.Core.Physics.Tests.Parity;

/// <summary>
/// Every parity file of the shared folders (shared/ace-parity and shared/real-cells, in a folder "shared"
/// beside the repository or one of its parents) meets its threshold: ACE's door file bit-identical,
/// every other file within 1e-4 m on every frame with every flag equal. This file is compiled only
/// when one of the folders exists (see the test project), so without them the test does not exist
/// instead of passing without a check; CI also runs `acdream-physics parity` on both folders.
/// </summary>
public class SharedParityFolderTests
{
    internal static string? FindShared(string name) => SharedFolders.Find(name);

    public static TheoryData<string, string> Files()
    {
        var data = new TheoryData<string, string>();
        foreach (string folder in new[] { "ace-parity", "real-cells" })
            if (FindShared(folder) is { } dir)
                foreach (string file in Directory.GetFiles(dir, "*.json.gz").OrderBy(f => f, StringComparer.Ordinal))
                    data.Add(folder, Path.GetFileName(file));
        return data;
    }

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryFile_MeetsItsThreshold(string folder, string file)
    {
        var report = ParityCheck.CheckFile(Path.Combine(FindShared(folder)!, file));
        Assert.True(report.Passed, report.ToString());
        Assert.True(report.Frames > 0, report.ToString());
        if (folder == "ace-parity" && file == "door.json.gz")
            Assert.Equal(report.Frames, report.BitIdentical);
    }
}
