using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// Every built-in scene's world (terrain, env cells, buildings, objects) written to DAT files and loaded by
/// <see cref="DatWorld"/>: its movers walk the same trajectory, to the bit, as through the scene's own world.
/// </summary>
public class DatWorldScenesTests
{
    public static TheoryData<string> BuiltInScenes()
    {
        var data = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void TheDatWorld_WalksBitIdenticalToTheScene(string name)
    {
        var scene = SceneLibrary.Load(name);
        var throughDat = DatWorldPath.Through(scene, SceneLibrary.ReadText(name));
        Assert.NotSame(scene.World, throughDat.World);
        Assert.Equal(scene.World.Cells.CellIds.Order(), throughDat.World.Cells.CellIds.Order());
        Assert.Equal(scene.World.Objects.Records.Select(r => r.Id).Order(), throughDat.World.Objects.Records.Select(r => r.Id).Order());
        var bits = TrajectoryReplay.Replay(throughDat, SceneRunner.Run(scene), tolerance: 0f);
        Assert.True(bits.Matches, $"{name} through DatWorld against the scene path: {bits.FirstDifference}");
        Assert.Equal(SceneRunner.Run(scene).ToJson(), SceneRunner.Run(throughDat).ToJson());
    }
}
