using System.IO;
using AcDream.Core.Physics.Parity;
using AcDream.Core.Physics.Tests.Robustness;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// The two edge behaviours of <see cref="LedgeGrazeTests"/> on the real Holtburg cells they were found on
/// (the shared real-cells set, read when it is beside the repository; nothing to check without it). Each
/// mover runs from its recorded start state with its recorded offsets and must follow the reference.
/// </summary>
public class RealCellEdgeTests
{
    private static (ParityRun Run, MoveResult[] Results)? Run(string file, string moverName)
    {
        string? shared = StackDepthTests.SharedFolder();
        if (shared is null)
            return null;
        var set = ParityReader.ReadFile(Path.Combine(shared, "real-cells", file + ".json.gz"));
        var run = set.Runs.Single(r => r.Name == moverName);
        var engine = new PhysicsEngine(set.World);
        var state = run.Start;
        var results = new MoveResult[run.Frames.Length];
        for (int i = 0; i < results.Length; i++)
        {
            var target = state.Position;
            target.Frame.Origin += run.Frames[i].Offset;
            results[i] = engine.Resolve(run.Mover, state, target);
            state = results[i].Next;
            Assert.True(Vector3.Distance(run.Frames[i].Position, state.Position.Frame.Origin) <= 1e-4f,
                $"{moverName} frame {i}: expected {run.Frames[i].Position}, got {state.Position.Frame.Origin}");
            Assert.Equal(run.Frames[i].Accepted, results[i].Succeeded);
        }
        return (run, results);
    }

    /// <summary>Cottage B's cellar lip: the 4 m/s walker steps up in frame 56 and is refused from frame 58 to the end.</summary>
    [Fact]
    public void CottageB_SlowWalker_StopsForGoodAtTheCellarLip()
    {
        if (Run("cottageB-ramp", "ascent-x153.9-4mps") is not var (run, results))
            return; // the shared data is not on this machine
        Assert.True(results[57].Succeeded);
        Assert.All(results.Skip(58), r => Assert.False(r.Succeeded));
        var stuck = results[57].Next;
        Support.AssertVec.Near(new Vector3(0, -1, 0), stuck.SlidingNormal, 1e-6f);
        Assert.Equal(94.005f, stuck.Position.Frame.Origin.Z, 3);
        Assert.InRange(10.353f - stuck.Position.Frame.Origin.Y, 0.24f, 0.48f); // centre outside the floor's edge
        Assert.Equal(90, run.Frames.Length);
    }

    /// <summary>Cottage A's ramp top: with the 1.5 m step-down the mover ends 0.09–0.15 m past the top edge (y 5.802).</summary>
    [Fact]
    public void CottageA_LongStepDown_StandsOnTheRampPastItsTopEdge()
    {
        if (Run("cottageA-ramp", "issue98-harness-stepdown1.5") is not var (_, results))
            return; // the shared data is not on this machine
        var end = results[^1].Next;
        Assert.InRange(5.802f - end.Position.Frame.Origin.Y, 0.09f, 0.16f);
        Assert.True(end.Contact && end.OnWalkable);
        Assert.Equal(0.695f, end.ContactPlane.Normal.Z, 3);
        Assert.All(results.Skip(74), r => Assert.False(r.Succeeded));
    }
}
