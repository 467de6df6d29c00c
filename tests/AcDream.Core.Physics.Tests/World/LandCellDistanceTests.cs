using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

public class LandCellDistanceTests
{
    // Cell index 10 of landblock 0xA9B4 is x 1, y 1: the square 24..48 m on both axes, landblock-local.
    private static readonly LandCell Cell = (LandCell)WorldWithOneBlock().Cells.Get(0xA9B4000A)!;

    private static PhysicsWorld WorldWithOneBlock()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(0xA9B4, 0f));
        return world;
    }

    [Theory]
    [InlineData(30f, 40f, 0f)]   // inside
    [InlineData(48f, 30f, 0f)]   // on the east edge
    [InlineData(24f, 24f, 0f)]   // on the south-west corner
    [InlineData(51f, 30f, 3f)]   // east
    [InlineData(22f, 30f, 2f)]   // west
    [InlineData(30f, 23f, 1f)]   // south
    [InlineData(30f, 50f, 2f)]   // north
    [InlineData(51f, 52f, 5f)]   // north-east: 3 and 4 m
    public void TheDistance_IsHorizontal_FromTheCellsSquare(float x, float y, float expected)
    {
        Assert.Equal(expected, Cell.DistanceOutside(new Vector3(x, y, 123f)), 1e-5f);
    }
}
