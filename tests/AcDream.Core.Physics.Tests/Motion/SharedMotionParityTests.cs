using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Parity;
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
        var built = MotionTables.Humanoid();
        Assert.Equal(built.Id, read.Id);
        Assert.Equal(built.DefaultStyle, read.DefaultStyle);
        Assert.Equal(built.StyleDefaults.OrderBy(p => p.Key), read.StyleDefaults.OrderBy(p => p.Key));
        SameMotions(built.Cycles, read.Cycles);
        SameMotions(built.Modifiers, read.Modifiers);
        Assert.Equal(built.LinkKeys.Order(), read.LinkKeys.Order());
        foreach (uint key in built.LinkKeys)
            SameMotions(built.LinksFrom(key)!, read.LinksFrom(key)!);
        Assert.Equal(built.Animations.Keys.Order(), read.Animations.Keys.Order());
        foreach (var (id, a) in built.Animations)
        {
            var b = read.Animations[id];
            Assert.Equal(a.FrameCount, b.FrameCount);
            Assert.Equal(a.RootFrames.ToArray(), b.RootFrames.ToArray());
        }
    }

    private static void SameMotions(IReadOnlyDictionary<uint, MotionData> a, IReadOnlyDictionary<uint, MotionData> b)
    {
        Assert.Equal(a.Keys.Order(), b.Keys.Order());
        foreach (var (key, x) in a)
        {
            var y = b[key];
            Assert.Equal(x.Bitfield, y.Bitfield);
            Assert.Equal(x.Flags, y.Flags);
            Assert.Equal(x.Anims.ToArray(), y.Anims.ToArray());
            Assert.Equal(x.Velocity, y.Velocity);
            Assert.Equal(x.Omega, y.Omega);
        }
    }
}
