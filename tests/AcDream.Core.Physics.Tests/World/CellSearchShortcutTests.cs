using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// The cell search's shortcut for spheres well inside a land cell without a building (CellGraph.AloneInSquare)
/// gives the very list, holder and interior flag of retail's full search, on positions chosen around the
/// cells' edges, the landblocks' edges and the cottage's building cell.
/// </summary>
public class CellSearchShortcutTests
{
    // The cottage's landblock with its eight neighbours loaded, so searches cross landblock edges.
    private static PhysicsWorld World()
    {
        var world = Cottage.Build();
        for (int dx = -1; dx <= 1; dx++)
            for (int dy = -1; dy <= 1; dy++)
                if (dx != 0 || dy != 0)
                    world.Cells.AddLandblock(Terrain.Flat((uint)(((0xA9 + dx) << 8) | (0xB4 + dy)), 0f));
        return world;
    }

    private static (uint[] Cells, uint Holder, bool Interior) Search(CellGraph graph, bool full, in Position position, Sphere[] spheres, bool findContaining)
    {
        graph.Shortcuts = full ? Shortcuts.None : Shortcuts.LandCellAlone;
        var cells = new CellArray();
        var holder = graph.FindCellList(position, spheres, cells, findContaining, out bool interior);
        return (Enumerable.Range(0, cells.Count).Select(i => cells[i].Id).ToArray(), holder?.Id ?? 0, interior);
    }

    // An offset into a cell's square: around its edges (radius-wise and by the float step), inside, or beyond.
    private static float Offset(Random random, float radius)
    {
        float edge = random.Next(4) switch { 0 => 0f, 1 => radius, 2 => 24f - radius, _ => 24f };
        return random.Next(6) switch
        {
            0 => edge,
            1 => MathF.BitIncrement(edge),
            2 => MathF.BitDecrement(edge),
            3 => edge + (float)(random.NextDouble() - 0.5) * 2e-3f,
            4 => (float)random.NextDouble() * 24f,
            _ => (float)random.NextDouble() * 30f - 3f,
        };
    }

    private static readonly float[] Radii = [0f, 1e-7f, 5e-4f, 1e-3f, 0.05f, 0.3f, 0.48f, 1.2f, 11.99f, 12f, 12.5f, -0.2f, float.NaN];

    [Fact]
    public void TheShortcut_GivesTheFullSearchsListHolderAndInteriorFlag()
    {
        var graph = World().Cells;
        var random = new Random(25);
        int shortcut = 0, full = 0;
        for (int n = 0; n < 60_000; n++)
        {
            // Start cells all over the landblock, the building's cell (0x25) often.
            uint index = random.Next(3) == 0 ? 0x25u : (uint)random.Next(1, 65);
            uint cellId = 0xA9B40000 | index;
            var corner = LandDefs.LandCellCorner(cellId);
            float radius = random.Next(3) == 0 ? (float)random.NextDouble() * 3f : Radii[random.Next(Radii.Length)];
            var centre = new Vector3(corner.X + Offset(random, radius), corner.Y + Offset(random, radius), 0.5f);
            var spheres = random.Next(3) switch
            {
                0 => new[] { new Sphere(centre, radius) },
                1 => [new Sphere(centre, radius), new Sphere(centre + new Vector3(0, 0, 1.2f), radius)],
                _ => [new Sphere(centre, radius), new Sphere(new Vector3(corner.X + Offset(random, radius), centre.Y, 1.7f), radius)],
            };
            var position = new Position(cellId, new Frame(centre));
            bool findContaining = random.Next(4) != 0;
            var expected = Search(graph, full: true, position, spheres, findContaining);
            var actual = Search(graph, full: false, position, spheres, findContaining);
            Assert.True(expected.Cells.SequenceEqual(actual.Cells),
                $"#{n} cell 0x{cellId:X8} spheres {string.Join(", ", spheres.Select(s => $"({s.Center.X:R}, {s.Center.Y:R}) r {s.Radius:R}"))}: full search [{string.Join(", ", expected.Cells.Select(c => c.ToString("X8")))}], shortcut [{string.Join(", ", actual.Cells.Select(c => c.ToString("X8")))}]");
            Assert.Equal(expected.Holder, actual.Holder);
            Assert.Equal(expected.Interior, actual.Interior);
            if (graph.Get(cellId) is LandCell { Building: null } land && CellGraph.AloneInSquare(land, spheres))
                shortcut++;
            else
                full++;
        }
        // Both ways are exercised often.
        Assert.True(shortcut > 3_000, $"only {shortcut} searches took the shortcut");
        Assert.True(full > 3_000, $"only {full} searches took the full search");
    }

    [Fact]
    public void TheShortcut_IsTakenWellInsideACell_NotWithinARadiusOfAnEdge()
    {
        var land = (LandCell)World().Cells.Get(0xA9B4000A)!; // index 10: column 1, row 1, the square x 24..48, y 24..48
        Assert.True(CellGraph.AloneInSquare(land, [new Sphere(new Vector3(30, 30, 0.5f), 0.48f)]));
        Assert.False(CellGraph.AloneInSquare(land, [new Sphere(new Vector3(47.6f, 30, 0.5f), 0.48f)]));
        Assert.False(CellGraph.AloneInSquare(land, [new Sphere(new Vector3(30, 30, 0.5f), 0.48f), new Sphere(new Vector3(30, 24.3f, 0.5f), 0.48f)]));
        Assert.False(CellGraph.AloneInSquare(land, []));
    }
}
