using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Parity;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// The shared parity sets (shared/ace-parity, shared/real-cells) with their worlds loaded by <see cref="DatWorld"/>
/// from DAT files: the same report as through the scene path, every file meeting its threshold (the door
/// bit-identical with ACE). Compiled only when a shared folder is present.
/// </summary>
public class SharedParityThroughDatWorldTests
{
    public static TheoryData<string, string> Files() => SharedFolders.CollisionParityFiles();

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryFile_GivesTheSameReportThroughTheDatWorld(string folder, string file)
    {
        var set = ParityReader.ReadFile(Path.Combine(SharedFolders.Find(folder)!, file));
        var datSet = set with { World = DatWorldPath.Through(set.World) };
        var report = ParityCheck.Check(datSet);
        Assert.True(report.Passed, report.ToString());
        Assert.True(report.Frames > 0);
        Assert.Equal(ParityCheck.Check(set).ToString(), report.ToString());
        Assert.Equal(ParityCheck.Check(set).BitIdentical, report.BitIdentical);
        if (folder == "ace-parity" && file == "door.json.gz")
            Assert.Equal(report.Frames, report.BitIdentical);
    }
}
