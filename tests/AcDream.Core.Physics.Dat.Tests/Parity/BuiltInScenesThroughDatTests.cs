using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests.Parity;

/// <summary>
/// Every built-in scene's world written as DAT objects (GfxObj, Setup, Environment, EnvCell, LandBlock,
/// LandBlockInfo, Region) into DAT files and loaded by <see cref="DatWorld"/> holds the scene's cells and objects
/// and walks its movers exactly as the scene path does: the whole trajectory is the same text (every float to the bit) as
/// the scene path's, and the committed replay matches bit for bit (tolerance 0, as on the scene path).
/// </summary>
public class BuiltInScenesThroughDatTests
{
    private static readonly string ReplayDirectory = Path.Combine(AppContext.BaseDirectory, "Replays");

    public static TheoryData<string> BuiltInScenes()
    {
        var data = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void TheDatPath_WalksBitIdenticalToTheScenePath(string name)
    {
        var scene = SceneLibrary.Load(name);
        var throughDat = DatPath.Through(scene, SceneLibrary.ReadText(name));
        var committed = Trajectory.LoadFile(Path.Combine(ReplayDirectory, name + ".trajectory.json"));
        Assert.NotSame(scene.World, throughDat.World);
        Assert.Equal(scene.World.Cells.CellIds.Order(), throughDat.World.Cells.CellIds.Order());
        Assert.Equal(scene.World.Objects.Records.Select(r => r.Id).Order(), throughDat.World.Objects.Records.Select(r => r.Id).Order());

        var bits = TrajectoryReplay.Replay(throughDat, SceneRunner.Run(scene), tolerance: 0f);
        var result = TrajectoryReplay.Replay(throughDat, committed, tolerance: 0f);

        Assert.True(bits.Matches, $"{name} through DAT files against the scene path: {bits.FirstDifference}");
        Assert.Equal(SceneRunner.Run(scene).ToJson(), SceneRunner.Run(throughDat).ToJson());
        Assert.True(result.Matches, $"{name} through DAT files: {result.FirstDifference}");
        Assert.Equal(committed.FrameCount, result.FramesCompared);
    }
}
