using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests.Parity;

/// <summary>
/// The shared parity sets (ACE's door, trunk and boulder in shared/ace-parity; the real Holtburg cells in
/// shared/real-cells) with their worlds written to DAT files and loaded by <see cref="DatWorld"/>: every frame of
/// every run resolves to the same bits as through the scene path (position, cell, contact, planes, normals,
/// objects hit), the parity report is the scene path's, and the file meets its threshold (the door bit-identical
/// with ACE). Compiled only when a shared folder is present.
/// </summary>
public class SharedParityThroughDatTests
{
    public static TheoryData<string, string> Files() => SharedFolders.CollisionParityFiles();

    [Theory]
    [MemberData(nameof(Files))]
    public void EveryFrame_IsBitIdenticalThroughTheDatPath(string folder, string file)
    {
        var set = ParityReader.ReadFile(Path.Combine(SharedFolders.Find(folder)!, file));
        var datSet = set with { World = DatPath.Through(set.World) };
        // The DAT holds each landblock's env cells 0x0100 up without gaps (the cells the scene lacks as fillers).
        var envIds = datSet.World.Cells.CellIds.Where(id => (id & 0xFFFF) >= 0x0100).ToList();
        Assert.Subset(envIds.ToHashSet(), set.World.Cells.CellIds.Where(id => (id & 0xFFFF) >= 0x0100).ToHashSet());
        foreach (var block in envIds.GroupBy(id => id >> 16))
            Assert.Equal(Enumerable.Range(0x0100, block.Count()).Select(i => block.Key << 16 | (uint)i), block.Order());
        var sceneEngine = new PhysicsEngine(set.World);
        var datEngine = new PhysicsEngine(datSet.World);
        int frames = 0;
        foreach (var run in set.Runs)
        {
            MoverState a = run.Start, b = run.Start;
            foreach (var frame in run.Frames)
            {
                var ta = a.Position;
                ta.Frame.Origin += frame.Offset;
                var tb = b.Position;
                tb.Frame.Origin += frame.Offset;
                var ra = sceneEngine.Resolve(run.Mover, a, ta);
                var rb = datEngine.Resolve(run.Mover, b, tb);
                var difference = TrajectoryReplay.Compare(run.Name, frames, TrajectoryFrame.From(ta, ra), TrajectoryFrame.From(tb, rb), 0f);
                Assert.True(difference is null, $"{file} through DAT files: {difference}");
                a = ra.Next;
                b = rb.Next;
                frames++;
            }
        }
        Assert.True(frames > 0);
        var report = ParityCheck.Check(datSet);
        Assert.True(report.Passed, report.ToString());
        var sceneReport = ParityCheck.Check(set);
        Assert.Equal(sceneReport.ToString(), report.ToString());
        Assert.Equal(sceneReport.BitIdentical, report.BitIdentical);
        if (folder == "ace-parity" && file == "door.json.gz")
            Assert.Equal(report.Frames, report.BitIdentical);
    }
}
