using System.IO;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Tests.Parity;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// Every file of the shared ACE motion-layer folder (shared/ace-motion) meets its threshold through the motion
/// layer and the body step: positions within 1e-4 m, flags and the interpreted state equal on every frame.
/// Compiled only when the folder exists (see the test project).
/// </summary>
public class SharedMotionParityTests
{
    public static TheoryData<string> Files()
    {
        var data = new TheoryData<string>();
        if (SharedFolders.Find("ace-motion") is { } dir)
            foreach (string file in Directory.GetFiles(dir, "*.json.gz").OrderBy(f => f, StringComparer.Ordinal))
                data.Add(Path.GetFileName(file));
        return data;
    }

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryMotionFile_MeetsItsThreshold(string file)
    {
        var report = ParityCheck.CheckFile(Path.Combine(SharedFolders.Find("ace-motion")!, file));
        Assert.True(report.Passed, report.ToString());
        Assert.True(report.Frames > 0, report.ToString());
    }
}
