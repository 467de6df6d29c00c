using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Parity;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// Every file of the shared ACE motion-layer folders (shared/ace-motion, and shared/ace-motion-2: the same motion
/// layer under contact, a slide along the door slab and a step off a box) meets its threshold through the motion
/// layer and the body step: positions within 1e-4 m, flags and the interpreted state equal on every frame.
/// Compiled only when one of the folders exists (see the test project); a folder that is absent adds no case.
/// </summary>
public class SharedMotionParityTests
{
    public static TheoryData<string, string> Files()
    {
        var data = new TheoryData<string, string>();
        foreach (string folder in new[] { "ace-motion", "ace-motion-2" })
            if (SharedFolders.Find(folder) is { } dir)
                foreach (string file in Directory.GetFiles(dir, "*.json.gz").OrderBy(f => f, StringComparer.Ordinal))
                    data.Add(folder, Path.GetFileName(file));
        return data;
    }

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryMotionFile_MeetsItsThreshold(string folder, string file)
    {
        var report = ParityCheck.CheckFile(Path.Combine(SharedFolders.Find(folder)!, file));
        Assert.True(report.Passed, report.ToString());
        Assert.True(report.Frames > 0, report.ToString());
    }

    [Fact]
    public void TheSharedTable_IsTheBuiltInHumanoid_ToTheBit()
    {
        // The humanoid is written in code from the reference data's description; read from its table.json it must be
        // the same table: every key, bitfield, flag, animation, frame range, framerate, vector and root frame.
        var read = MotionTableReader.Parse(File.ReadAllText(Path.Combine((SharedFolders.Find("ace-motion") ?? SharedFolders.Find("ace-motion-2"))!, "table.json")));
        MotionTableAssert.Same(MotionTables.Humanoid(), read);
    }

}
