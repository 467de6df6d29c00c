using System.Globalization;
using AcDream.Core.Physics.Bench.Accuracy;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// <c>trace METHOD HEADING LATERAL SPEED HZ [back]</c>: prints one approach frame by frame (position,
/// collision normal, the reference's resolution of the same frame, penetration) to study a failure.
/// </summary>
public static class DoorTrace
{
    /// <summary>Runs the trace.</summary>
    public static int Run(string[] args)
    {
        if (args.Length < 5 || !Enum.TryParse<DoorMethod>(args[0], true, out var method))
        {
            Console.Error.WriteLine("usage: trace METHOD HEADING LATERAL SPEED HZ [back]   (METHOD: " + string.Join(", ", DoorMethods.All) + ")");
            return 2;
        }
        var inv = CultureInfo.InvariantCulture;
        var approach = new DoorApproach(int.Parse(args[1], inv), float.Parse(args[2], inv), float.Parse(args[3], inv), int.Parse(args[4], inv),
            args.Length > 5 && args[5] == "back");
        var scene = DoorScene.Create();
        var stepper = new DoorStepper(scene, method);
        var reference = new ReferenceSweep(scene.Reference);
        var state = DoorScene.Standing(approach.Start);
        Console.WriteLine($"{approach}: start {approach.Start}, step {approach.StepOffset}, {approach.Frames} frames, {DoorMethods.SubSteps(method, approach.StepOffset)} sub-steps");
        for (int k = 0; k < approach.Frames; k++)
        {
            var before = state.Position.Origin;
            var target = before + approach.StepOffset;
            var step = stepper.Step(state, target);
            var local = reference.Move(DoorScene.Player.Spheres, before, target);
            var after = step.Next.Position.Origin;
            Console.WriteLine(string.Format(inv, "{0,3} ({1:0.00000}, {2:0.00000}, {3:0.00000}) moved {4:0.00000} normal {5} ref ({6:0.00000}, {7:0.00000}) refNormal {8} pen {9:0.00000}",
                k, after.X, after.Y, after.Z, Vector3.Distance(before, after), step.NormalValid ? step.Normal.ToString("0.000", inv) : "-",
                local.Position.X, local.Position.Y, local.Collided ? local.FirstNormal.ToString("0.000", inv) : "-", DoorScene.SlabPenetration(after)));
            state = step.Next;
        }
        return 0;
    }
}
