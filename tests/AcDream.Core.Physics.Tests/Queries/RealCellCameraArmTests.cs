using System.IO;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Parity;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// The camera arm's skip on real retail cells (the shared real-cells scenes: Holtburg cottages A and B, cells
/// turned 180°, convex cells joined by portals, a building shell, a ramp object): random arms from pivots in
/// every env cell answer bit for bit as the arm that walks every sub-step. Compiled only when the shared
/// folder exists (see the test project).
/// </summary>
public class RealCellCameraArmTests
{
    [Theory]
    [InlineData("cottageA-ramp.json")]
    [InlineData("cottageB-ramp.json")]
    public void RandomArmsFromEveryEnvCell_AnswerAsWalkingEverySubStep_BitForBit(string scene)
    {
        string dir = SharedFolders.Find("real-cells")!;
        var world = SceneLoader.Load(File.ReadAllText(Path.Combine(dir, "scenes", scene))).World;
        var cells = world.Cells.EnvCellsOf(0xA9B4).ToArray();
        Assert.NotEmpty(cells);
        var skipped = new Support.ShortcutCounter();
        var skipping = new WorldQuery(world, Shortcuts.All, skipped);
        var walking = new WorldQuery(world, Shortcuts.None);
        var random = new Random(77);
        int arms = 0, passed = 0;
        while (arms < 2000)
        {
            // A pivot in a random cell: a random point of its bounding sphere that the cell holds.
            var cell = cells[random.Next(cells.Length)];
            var offset = new Vector3((float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1);
            var pivot = cell.Bounds.Center + offset * cell.Bounds.Radius;
            if (!cell.ContainsPoint(pivot))
                continue;
            arms++;
            var direction = Vector3.Normalize(new Vector3((float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1, (float)random.NextDouble() - 0.3f));
            var desired = pivot + direction * (float)(random.NextDouble() * 8);
            var from = new Position(cell.Id, pivot);
            skipped.Clear();
            var a = skipping.CameraArm(from, desired);
            int steps = skipped.ViewerSubSteps;
            var b = walking.CameraArm(from, desired);
            var (oa, ob) = (a.Camera.Origin, b.Camera.Origin);
            bool same = a.Camera.CellId == b.Camera.CellId && a.Placement == b.Placement && a.Blocked == b.Blocked
                && Bits(oa.X) == Bits(ob.X) && Bits(oa.Y) == Bits(ob.Y) && Bits(oa.Z) == Bits(ob.Z)
                && Bits(a.Normal.X) == Bits(b.Normal.X) && Bits(a.Normal.Y) == Bits(b.Normal.Y) && Bits(a.Normal.Z) == Bits(b.Normal.Z);
            Assert.True(same, $"{scene} arm {arms}: {from} -> {desired}: passing over {steps} sub-steps gave {a.Camera} {a.Normal}, walking gave {b.Camera} {b.Normal}");
            passed += steps > 0 ? 1 : 0;
        }
        Assert.True(passed > arms / 10, $"only {passed} of {arms} arms passed over sub-steps");
    }

    private static uint Bits(float f) => (uint)BitConverter.SingleToInt32Bits(f);
}
