using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// An object far longer than a land cell is listed in every land cell under it, along both axes. Our rule
/// for an outdoor BSP object (docs/open-questions.md, cell membership): every cell under the horizontal
/// box around each part's bounding sphere, plus the cells the sphere search finds (the centre cell and its
/// eight neighbours).
/// </summary>
public class LongObjectCellTests
{
    private const uint Id = 0x7000_0050;

    // A slab 100 m × 0.4 m × 2 m (half 50, 0.2, 1) with a bounding sphere of radius 50 given explicitly,
    // lying along X or along Y. Centre (cx, cy): the box is cx ± 50, cy ± 50, so the cells are
    // gx = ⌊(cx − 50) / 24⌋ .. ⌊(cx + 50) / 24⌋ and likewise for y.
    // At (100, 115): x 50..150 → gx 2..6 (50 / 24 = 2.08, 150 / 24 = 6.25); y 65..165 → gy 2..6
    // (65 / 24 = 2.71, 165 / 24 = 6.88): 25 cells. The sphere search alone reaches only gx 3..5 × gy 3..5.
    // At (115, 60): x 65..165 → gx 2..6; y 10..110 → gy 0..4: 25 cells.

    [Theory]
    [InlineData(true, 100f, 115f, 2, 6, 2, 6)]
    [InlineData(false, 100f, 115f, 2, 6, 2, 6)]
    [InlineData(true, 115f, 60f, 2, 6, 0, 4)]
    [InlineData(false, 115f, 60f, 2, 6, 0, 4)]
    public void ALongSlab_IsListedInEveryCellUnderIt(bool alongX, float cx, float cy, int gx0, int gx1, int gy0, int gy1)
    {
        var world = TestGeometry.FlatWorld();
        var half = alongX ? new Vector3(50, 0.2f, 1) : new Vector3(0.2f, 50, 1);
        var model = new PhysicsModel(BspShapes.Box(-half, half), new Sphere(Vector3.Zero, 50f), "long slab");
        world.Objects.Register(Id, new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] }, TestGeometry.At(cx, cy, 1), 1f, PhysicsState.Static);

        var expected = new SortedSet<uint>();
        for (int gx = gx0; gx <= gx1; gx++)
            for (int gy = gy0; gy <= gy1; gy++)
                expected.Add((TestGeometry.Landblock << 16) | (uint)(gx * 8 + gy + 1));
        var actual = new SortedSet<uint>(world.Objects.CellsOf(Id));
        Assert.True(expected.SetEquals(actual),
            $"missing [{string.Join(", ", expected.Except(actual).Select(c => $"0x{c:X8}"))}], extra [{string.Join(", ", actual.Except(expected).Select(c => $"0x{c:X8}"))}]");
        foreach (uint cell in expected)
            Assert.Contains(world.Objects.RowsInCell(cell).ToArray(), row => row.EntityId == Id);
    }
}
