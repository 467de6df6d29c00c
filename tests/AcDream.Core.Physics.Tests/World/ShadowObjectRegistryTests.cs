using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

public class ShadowObjectRegistryTests
{
    private static PhysicsSetup Ball(float radius) => new() { Spheres = [new Sphere(Vector3.Zero, radius)] };

    private static HashSet<uint> EntitiesIn(ShadowObjectRegistry registry, uint cell)
    {
        var ids = new HashSet<uint>();
        foreach (var row in registry.RowsInCell(cell))
            ids.Add(row.EntityId);
        return ids;
    }

    [Fact]
    public void Register_Door_HasOneRowPerShape_AndTheBspBitFromItsParts()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(0x7000_0001, TestGeometry.DoorSetup(), TestGeometry.At(12, 12, 0), 1f, PhysicsState.ReportCollisions);
        var rows = world.Objects.RowsInCell(TestGeometry.At(12, 12, 0).CellId).ToArray();
        Assert.Equal(3, rows.Length);
        Assert.All(rows, r => Assert.Equal(PhysicsState.ReportCollisions | PhysicsState.HasPhysicsBsp, r.State));
        Assert.All(rows, r => Assert.Equal(1, r.CylSphereCount));
    }

    [Fact]
    public void Register_CallerStateBitIsKept_WhenThePartsHaveNoBsp()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(1, Ball(0.5f), TestGeometry.At(12, 12, 0), 1f, PhysicsState.HasPhysicsBsp);
        Assert.Equal(PhysicsState.HasPhysicsBsp, world.Objects.RowsInCell(TestGeometry.At(12, 12, 0).CellId)[0].State);
    }

    [Fact]
    public void ObjectOnACellBorder_IsInBothCells_Once()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(1, Ball(0.5f), TestGeometry.At(23.8f, 12, 0), 1f, PhysicsState.Static);
        uint west = LandDefs.LandCellAt(TestGeometry.Landblock, new Vector3(1, 12, 0));
        uint east = LandDefs.LandCellAt(TestGeometry.Landblock, new Vector3(25, 12, 0));
        Assert.Equal(1, world.Objects.RowsInCell(west).Length);
        Assert.Equal(1, world.Objects.RowsInCell(east).Length);
        Assert.Equal(2, world.Objects.CellsOf(1).Count);
    }

    [Fact]
    public void ObjectNearACorner_IsInAllFourCells()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(1, Ball(0.5f), TestGeometry.At(23.8f, 23.8f, 0), 1f, PhysicsState.Static);
        Assert.Equal(4, world.Objects.CellsOf(1).Count);
    }

    [Fact]
    public void Move_MigratesRows_AndUnregisterRemovesThem()
    {
        var world = TestGeometry.FlatWorld();
        var reg = world.Objects;
        reg.Register(1, Ball(0.5f), TestGeometry.At(12, 12, 0), 1f, PhysicsState.None);
        uint first = TestGeometry.At(12, 12, 0).CellId, second = TestGeometry.At(60, 12, 0).CellId;
        reg.Move(1, TestGeometry.At(60, 12, 0));
        Assert.Empty(EntitiesIn(reg, first));
        Assert.Equal(new HashSet<uint> { 1 }, EntitiesIn(reg, second));
        Assert.True(reg.Unregister(1));
        Assert.Empty(EntitiesIn(reg, second));
        Assert.False(reg.Unregister(1));
    }

    [Fact]
    public void BadInput_Throws_AndLeavesTheRegistryUnchanged()
    {
        var world = TestGeometry.FlatWorld();
        var reg = world.Objects;
        reg.Register(1, Ball(0.5f), TestGeometry.At(12, 12, 0), 1f, PhysicsState.None);
        uint cell = TestGeometry.At(12, 12, 0).CellId;

        var dup = Assert.Throws<ArgumentException>(() => reg.Register(1, Ball(0.5f), TestGeometry.At(30, 12, 0), 1f, PhysicsState.None));
        Assert.Contains("already registered", dup.Message);
        var unknownCell = Assert.Throws<ArgumentException>(() => reg.Move(1, new Position(0x12340001, new Vector3(1, 1, 0))));
        Assert.Contains("unknown cell 0x12340001", unknownCell.Message);
        var unregistered = Assert.Throws<ArgumentException>(() => reg.Move(2, TestGeometry.At(30, 12, 0)));
        Assert.Contains("not registered", unregistered.Message);
        var nan = Assert.Throws<ArgumentException>(() => reg.Move(1, new Position(cell, new Vector3(float.NaN, 1, 0))));
        Assert.Contains("position.origin", nan.Message);
        var zeroQ = Assert.Throws<ArgumentException>(() => reg.Register(3, Ball(0.5f), new Position(cell, new Frame(new Vector3(12, 12, 0), default)), 1f, PhysicsState.None));
        Assert.Contains("zero length", zeroQ.Message);

        Assert.Equal(1, reg.Count);
        Assert.Equal(new HashSet<uint> { 1 }, EntitiesIn(reg, cell));
        Assert.Equal(new Vector3(12, 12, 0), reg.PositionOf(1).Origin);
    }

    /// <summary>
    /// An independent model of retail's outdoor cell rule: an object is in every land cell whose square,
    /// grown by the object's radius on each side, holds the object's centre.
    /// </summary>
    private static HashSet<uint> ModelCells(Vector3 center, float radius)
    {
        var cells = new HashSet<uint>();
        for (int x = 0; x < 8; x++)
            for (int y = 0; y < 8; y++)
            {
                float x0 = x * 24 - radius, x1 = (x + 1) * 24 + radius, y0 = y * 24 - radius, y1 = (y + 1) * 24 + radius;
                if (center.X > x0 && center.X < x1 && center.Y > y0 && center.Y < y1)
                    cells.Add((TestGeometry.Landblock << 16) | (uint)(x * 8 + y + 1));
            }
        return cells;
    }

    [Fact]
    public void RandomRegisterMoveUnregister_MatchesABruteForceModel()
    {
        var rng = new Random(20261123);
        var world = TestGeometry.FlatWorld();
        var reg = world.Objects;
        var model = new Dictionary<uint, (Vector3 Center, float Radius)>();
        for (int op = 0; op < 400; op++)
        {
            uint id = (uint)rng.Next(1, 25);
            var center = new Vector3((float)rng.NextDouble() * 180 + 6, (float)rng.NextDouble() * 180 + 6, 0);
            float radius = 0.2f + (float)rng.NextDouble() * 3f;
            int kind = rng.Next(3);
            var pos = TestGeometry.At(center.X, center.Y, 0);
            if (kind == 0 && !model.ContainsKey(id))
            {
                reg.Register(id, Ball(radius), pos, 1f, PhysicsState.None);
                model[id] = (center, radius);
            }
            else if (kind == 1 && model.TryGetValue(id, out var m))
            {
                reg.Move(id, pos);
                model[id] = (center, m.Radius);
            }
            else if (kind == 2)
            {
                Assert.Equal(model.Remove(id), reg.Unregister(id));
            }

            if (op % 20 != 0)
                continue;
            for (uint c = 1; c <= 64; c++)
            {
                uint cell = (TestGeometry.Landblock << 16) | c;
                var expected = model.Where(kv => ModelCells(kv.Value.Center, kv.Value.Radius).Contains(cell)).Select(kv => kv.Key).ToHashSet();
                var rows = reg.RowsInCell(cell).ToArray();
                Assert.Equal(expected, rows.Select(r => r.EntityId).ToHashSet());
                Assert.Equal(expected.Count, rows.Length); // each object once per cell (one shape each)
            }
        }
        Assert.Equal(model.Count, reg.Count);
    }

    [Fact]
    public void Unregister_MovesTheCellsLastObjectIntoTheHole_AsRetailDoes()
    {
        var world = TestGeometry.FlatWorld();
        var reg = world.Objects;
        var twoShapes = new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.3f), new Sphere(new Vector3(0, 0, 1), 0.3f)] };
        for (uint id = 1; id <= 4; id++)
            reg.Register(id, id == 4 ? twoShapes : Ball(0.3f), TestGeometry.At(10 + id, 12, 0), 1f, PhysicsState.None);
        uint cell = TestGeometry.At(12, 12, 0).CellId;
        reg.Unregister(2);
        Assert.Equal(new uint[] { 1, 4, 4, 3 }, reg.RowsInCell(cell).ToArray().Select(r => r.EntityId).ToArray());
        reg.Unregister(4);
        Assert.Equal(new uint[] { 1, 3 }, reg.RowsInCell(cell).ToArray().Select(r => r.EntityId).ToArray());
        reg.Unregister(3);
        Assert.Equal(new uint[] { 1 }, reg.RowsInCell(cell).ToArray().Select(r => r.EntityId).ToArray());
    }

    [Fact]
    public void ALongBspWall_IsListedInEveryLandCellUnderItsBox()
    {
        var world = TestGeometry.FlatWorld();
        var wall = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-30, -0.2f, 0), new Vector3(30, 0.2f, 3)), name: "wall");
        world.Objects.Register(9, new PhysicsSetup { Parts = [new SetupPart(wall, Frame.Identity)] }, TestGeometry.At(100, 108, 0), 1f, PhysicsState.Static);
        // The wall's bounding sphere (r ≈ 30.1) spans x 69.9..130.1: land-cell columns 2 to 5.
        var columns = world.Objects.CellsOf(9).Select(c => ((c & 0xFFFF) - 1) / 8).Distinct().OrderBy(x => x).ToArray();
        Assert.Equal(new uint[] { 2, 3, 4, 5 }, columns);
    }

    /// <summary>
    /// Retail lists a cylsphere object by a sphere at each cylsphere's low point with its radius, unscaled
    /// (CObjCell::find_cell_list for cylspheres): a tall trunk near a border, even scaled up, stays in its cell.
    /// </summary>
    [Theory]
    [InlineData(1f)]
    [InlineData(3f)]
    public void ACylinderObject_IsListedByItsUnscaledFoot(float scale)
    {
        var world = TestGeometry.FlatWorld();
        var trunk = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.3f, 20f)] };
        world.Objects.Register(9, trunk, TestGeometry.At(23.5f, 12, 0), scale, PhysicsState.Static);
        Assert.Equal(new[] { TestGeometry.At(23.5f, 12, 0).CellId }, world.Objects.CellsOf(9).ToArray());
        world.Objects.Move(9, TestGeometry.At(23.8f, 12, 0));
        Assert.Equal(2, world.Objects.CellsOf(9).Count);
    }
}
