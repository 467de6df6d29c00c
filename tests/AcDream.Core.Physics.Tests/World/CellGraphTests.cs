using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

public class CellGraphTests
{
    private static uint Land(float x, float y) => LandDefs.LandCellAt(TestGeometry.Landblock, new Vector3(x, y, 0));

    private static (HashSet<uint> Cells, Cell? Holder) Find(PhysicsWorld world, Position position, float radius, float z = 0.5f)
    {
        var cells = new CellArray();
        ReadOnlySpan<Sphere> spheres = [new Sphere(position.Origin + new Vector3(0, 0, z), radius)];
        var holder = world.Cells.FindCellList(position, spheres, cells, findContaining: true, out _);
        return (Enumerable.Range(0, cells.Count).Select(i => cells[i].Id).ToHashSet(), holder);
    }

    [Fact]
    public void SphereInsideACell_ListsOnlyThatCell()
    {
        var world = TestGeometry.FlatWorld();
        var (cells, holder) = Find(world, TestGeometry.At(12, 12, 0), 0.48f);
        Assert.Equal(new HashSet<uint> { Land(12, 12) }, cells);
        Assert.Equal(Land(12, 12), holder!.Id);
    }

    [Fact]
    public void SphereAcrossABorder_ListsBothCells_AndTheHolderIsWhereTheCentreIs()
    {
        var world = TestGeometry.FlatWorld();
        var (cells, holder) = Find(world, TestGeometry.At(24.2f, 12, 0), 0.48f);
        Assert.Equal(new HashSet<uint> { Land(12, 12), Land(30, 12) }, cells);
        Assert.Equal(Land(30, 12), holder!.Id);
        var (_, west) = Find(world, new Position(Land(23.8f, 12), new Vector3(23.8f, 12, 0)), 0.48f);
        Assert.Equal(Land(12, 12), west!.Id);
    }

    [Fact]
    public void SphereAtACorner_ListsFourCells()
    {
        var world = TestGeometry.FlatWorld();
        var (cells, _) = Find(world, TestGeometry.At(47.9f, 47.9f, 0), 0.48f);
        Assert.Equal(4, cells.Count);
    }

    [Fact]
    public void SphereAtTheLandblockEdge_ListsOnlyKnownCells()
    {
        var world = TestGeometry.FlatWorld();
        var (cells, holder) = Find(world, TestGeometry.At(0.2f, 100, 0), 0.48f);
        Assert.Equal(new HashSet<uint> { Land(0.2f, 100) }, cells); // the western neighbour landblock is not loaded
        Assert.NotNull(holder);
    }

    [Fact]
    public void FromOutside_NearTheDoorway_TheRoomIsListed_ButTheHolderStaysOutdoors()
    {
        var world = Cottage.Build();
        var (cells, holder) = Find(world, TestGeometry.At(100, 109.7f, 0), 0.48f);
        Assert.Contains(Cottage.RoomId, cells);
        Assert.True(LandDefs.IsLandCell(holder!.Id));
    }

    [Fact]
    public void FromInside_NearTheDoorway_TheOutsideIsListedThroughThePortal_AndTheHolderIsTheRoom()
    {
        var world = Cottage.Build();
        var (cells, holder) = Find(world, new Position(Cottage.RoomId, new Vector3(100, 110.3f, 0)), 0.48f);
        Assert.Contains(Land(100, 110), cells);
        Assert.Equal(Cottage.RoomId, holder!.Id);
    }

    [Fact]
    public void FromInside_FarFromTheDoorway_OnlyTheRoomIsListed()
    {
        var world = Cottage.Build();
        var (cells, holder) = Find(world, new Position(Cottage.RoomId, new Vector3(100, 113, 0)), 0.48f);
        Assert.Equal(new HashSet<uint> { Cottage.RoomId }, cells);
        Assert.Equal(Cottage.RoomId, holder!.Id);
    }

    [Fact]
    public void UnknownCells_AreRefusedWithTheirId()
    {
        var world = Cottage.Build();
        var ex = Assert.Throws<ArgumentException>(() => world.Cells.GetRequired(0xA9B40105, "cell"));
        Assert.Contains("0xA9B40105", ex.Message);
        Assert.Throws<ArgumentException>(() => world.Cells.AddLandblock(Terrain.Flat(TestGeometry.Landblock, 0)));
    }

    [Fact]
    public void LandCells_AreFoundByIdInTheirOwnLandblockOnly()
    {
        var world = TestGeometry.FlatWorld();
        world.Cells.AddLandblock(Terrain.Flat(0x0102, 0));
        for (uint index = 1; index <= 64; index++)
        {
            Assert.Equal(0xA9B40000 | index, world.Cells.Get(0xA9B40000 | index)!.Id);
            Assert.Equal(0x01020000 | index, world.Cells.Get(0x01020000 | index)!.Id);
        }
        // Neighbouring landblocks not added, cell index 0 and indices past 64 (not land cells).
        Assert.Null(world.Cells.Get(0xA9B50001));
        Assert.Null(world.Cells.Get(0xAAB40001));
        Assert.Null(world.Cells.Get(0x01030001));
        Assert.Null(world.Cells.Get(0xA9B40000));
        Assert.Null(world.Cells.Get(0xA9B40041));
        Assert.Null(world.Cells.Get(0xA9B40100));
    }
}
