using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The built-in monster-approach scene: retail's MoveToManager has no path finding, so creatures whose straight line
/// only grazes the tree or the house corner slide round and arrive, and those meeting the tree or the wall head on
/// stop against it and give up through CheckProgressMade (then stand still): the scene opts in to the server's cancel
/// ("giveUp": true); without it the client's rule only counts and they keep running in place.
/// </summary>
public class MonsterApproachSceneTests
{
    private static readonly Trajectory Run = SceneRunner.Run(SceneLibrary.Load("monster-approach"));

    private static Vector3 At(string mover, int frame) => Mover(mover).Frames[frame].Position;

    private static MoverTrajectory Mover(string name) => Run.Movers.Single(m => m.Name == name);

    [Theory]
    [InlineData("grazes-the-tree", 100f, 110f)]
    [InlineData("grazes-the-corner", 132f, 112f)]
    public void AGrazingCreature_SlidesRound_AndArrives(string name, float x, float y)
    {
        // Arrived: the cylinder distance (radius 0.48 to the point) at most 0.6, so the centres within 1.08 m; then Ready.
        var end = At(name, 239);
        Assert.InRange(Vector2.Distance(new Vector2(end.X, end.Y), new Vector2(x, y)), 0f, 1.08f);
        Assert.Equal(MotionCommand.Ready, Mover(name).Frames[239].Motion!.Value.Interpreted.ForwardCommand);
    }

    [Theory]
    [InlineData("meets-the-tree")]
    [InlineData("meets-the-wall")]
    public void AHeadOnCreature_GivesUpWithinRetailsTime_AndStands(string name)
    {
        // It stops against the obstacle by frame 100 (a turn of up to 90° at 90°/s, then about 20 m at 9.5 m/s);
        // CheckProgressMade judges windows longer than 1 s (31 quanta): a check fails within two windows of the stop,
        // and the give-up rule waits one more window of failing checks: Ready by frame 100 + 3 × 31.
        var frames = Mover(name).Frames;
        Assert.Equal(At(name, 100), At(name, 239));
        Assert.Equal(MotionCommand.Ready, frames[193].Motion!.Value.Interpreted.ForwardCommand);
        Assert.True(At(name, 239).Y < 96f); // it never got past
    }

    [Fact]
    public void WithoutTheGiveUpOptIn_AHeadOnCreature_KeepsRunningInPlace()
    {
        // The client's rule (CountOnly, the default) never ends the move: still RunForward at the last frame, no further on.
        string original = SceneLibrary.ReadText("monster-approach");
        string text = original.Replace(", \"giveUp\": true }", " }");
        Assert.Equal(4, (original.Length - text.Length) / ", \"giveUp\": true".Length); // the four commands' opt-ins removed
        var run = SceneRunner.Run(SceneLoader.Load(text, "monster-approach"));
        var frames = run.Movers.Single(m => m.Name == "meets-the-wall").Frames;
        Assert.Equal(MotionCommand.RunForward, frames[239].Motion!.Value.Interpreted.ForwardCommand);
        Assert.True(frames[239].Position.Y < 96f);
        Assert.Equal(MotionCommand.Ready, Mover("meets-the-wall").Frames[239].Motion!.Value.Interpreted.ForwardCommand);
    }
}
