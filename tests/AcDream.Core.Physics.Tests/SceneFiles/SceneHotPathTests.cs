using System.Text.Json.Nodes;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>Scene loading stays off the hot path: resolving the frames of a loaded scene allocates nothing once warm.</summary>
public class SceneHotPathTests
{
    [Theory]
    [MemberData(nameof(ReplayTests.BuiltInScenes), MemberType = typeof(ReplayTests))]
    public void ResolvingALoadedScenesFrames_AllocatesNothing(string name)
    {
        var scene = SceneLibrary.Load(name);
        var engine = new PhysicsEngine(scene.World);
        var inputs = new List<(MoverDescription Mover, MoverState State, Position Target)>();
        var steps = new List<(MoverDescription Mover, MoverState State, Core.Physics.BodyState Body, SceneStep Step)>();
        foreach (var mover in scene.Movers)
        {
            var state = mover.Start;
            var body = mover.StartBody;
            if (mover.IsMotion)
                continue; // its frames depend on its motion layer's state: MotionSceneTests.SteppingAMotionMover_AllocatesNothingOnceWarm
            for (int f = 0; f < mover.FrameCount; f++)
            {
                if (mover.IsBody)
                {
                    var step = mover.Steps[f];
                    steps.Add((mover.Description, state, body, step));
                    var r = engine.Step(mover.Description, state, body, step.Elapsed, step.DesiredVelocity, step.JumpVelocity);
                    (state, body) = (r.Next, r.Body);
                    continue;
                }
                var target = state.Position;
                target.Frame.Origin += mover.Motion[f];
                inputs.Add((mover.Description, state, target));
                state = engine.Resolve(mover.Description, state, target).Next;
            }
        }
        var array = inputs.ToArray();
        var stepArray = steps.ToArray();
        void RunAll()
        {
            for (int i = 0; i < array.Length; i++)
                engine.Resolve(array[i].Mover, array[i].State, array[i].Target);
            for (int i = 0; i < stepArray.Length; i++)
                engine.Step(stepArray[i].Mover, stepArray[i].State, stepArray[i].Body, stepArray[i].Step.Elapsed, stepArray[i].Step.DesiredVelocity, stepArray[i].Step.JumpVelocity);
        }
        Assert.Equal(0, Allocations.PerRound(RunAll, RunAll));
    }
}
