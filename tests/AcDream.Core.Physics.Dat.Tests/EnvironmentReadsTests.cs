using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;
using DatFrame = DatReaderWriter.Types.Frame;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// A landblock's env cells sharing Environments (as one building's cells do): each Environment is read from the
/// portal DAT once per load however many of its structures the cells use, and each structure is converted once
/// and shared by the cells on it.
/// </summary>
public class EnvironmentReadsTests
{
    private const uint Landblock = 0x8040, Shared = 0x0D000005, Single = 0x0D000006;

    // Three structures of different sizes, so a cell given the wrong one shows.
    private static readonly BspTree Small = BspShapes.Box(new Vector3(-2, -2, 0), new Vector3(2, 2, 3));
    private static readonly BspTree Large = BspShapes.Box(new Vector3(-5, -4, 0), new Vector3(5, 4, 3));
    private static readonly BspTree Tall = BspShapes.Box(new Vector3(-3, -3, 0), new Vector3(3, 3, 6));

    private static CellStruct Structure(BspTree tree)
    {
        var vertices = DatObjects.NewVertexArray();
        var min = tree.Bounds.Center - new Vector3(tree.Bounds.Radius);
        var structure = new CellStruct { VertexArray = vertices, CellBSP = DatObjects.CellTree(BspShapes.CellBox(min, min + new Vector3(2 * tree.Bounds.Radius))) };
        structure.PhysicsBSP = DatObjects.PhysicsTree(tree, vertices, structure.PhysicsPolygons);
        return structure;
    }

    private static DatEnvCell Cell(uint index, uint environment, ushort structure, float x) => new()
    {
        Id = Landblock << 16 | index,
        EnvironmentId = (ushort)environment,
        CellStructure = structure,
        Position = new DatFrame { Origin = new Vector3(x, 100f, 40f), Orientation = Quaternion.Identity },
    };

    private static TempDats Dats()
    {
        var shared = new DatEnvironment { Id = Shared };
        shared.Cells.Add(0, Structure(Small));
        shared.Cells.Add(1, Structure(Large));
        var single = new DatEnvironment { Id = Single };
        single.Cells.Add(0, Structure(Tall));
        // Four cells: three on the shared Environment (structures 0, 1, 0), one on its own.
        return new TempDats([WorldWriter.Region(), shared, single],
        [
            WorldWriter.Land(Landblock, hasObjects: true), WorldWriter.Info(Landblock, 4),
            Cell(0x0100, Shared, 0, 20f), Cell(0x0101, Shared, 1, 50f), Cell(0x0102, Shared, 0, 80f), Cell(0x0103, Single, 0, 110f),
        ]);
    }

    [Fact]
    public void ALoad_ReadsEachEnvironmentOnce_AndTheCellsGetTheirOwnStructures()
    {
        using var dats = Dats();
        using var files = dats.Open();
        var reads = new List<uint>();
        files.Portal.Unpacking = reads.Add;

        var block = new DatWorld(files).LoadLandblock(Landblock);

        foreach (uint environment in new[] { Shared, Single })
        {
            int count = reads.Count(id => id == environment);
            Assert.True(count == 1, $"Environment 0x{environment:X8} was read {count} times in one load, expected once.");
        }
        var cells = block.EnvCells;
        Assert.Equal([0x80400100u, 0x80400101u, 0x80400102u, 0x80400103u], cells.Select(c => c.Id));
        TreeAssert.Same(Small, cells[0].PhysicsBsp!, "cell 0x0100 (structure 0)");
        TreeAssert.Same(Large, cells[1].PhysicsBsp!, "cell 0x0101 (structure 1)");
        TreeAssert.Same(Tall, cells[3].PhysicsBsp!, "cell 0x0103 (the other environment)");
        // Structure 0 is converted once: both cells on it hold the same trees.
        Assert.Same(cells[0].PhysicsBsp, cells[2].PhysicsBsp);
        Assert.Same(cells[0].CellBsp, cells[2].CellBsp);
    }

    [Fact]
    public void ALoadWithItsStructuresConverted_ReadsNoEnvironment()
    {
        using var dats = Dats();
        using var files = dats.Open();
        var first = new DatWorld(files).LoadLandblock(Landblock);
        var reads = new List<uint>();
        files.Portal.Unpacking = reads.Add;

        var second = new DatWorld(files).LoadLandblock(Landblock);

        Assert.True(!reads.Any(id => id >> 24 == 0x0D), $"a second load read Environments {string.Join(", ", reads.Select(id => $"0x{id:X8}"))}; the first load's structures are cached.");
        for (int i = 0; i < first.EnvCells.Count; i++)
            Assert.Same(first.EnvCells[i].PhysicsBsp, second.EnvCells[i].PhysicsBsp);
    }
}
