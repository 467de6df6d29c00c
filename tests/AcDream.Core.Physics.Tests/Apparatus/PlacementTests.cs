using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

public class PlacementTests
{
    [Fact]
    public void PlacingInFreeSpaceJustAboveTheFloor_SettlesOntoIt()
    {
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var result = engine.Place(MoverDescription.Player(), TestGeometry.At(90, 90, 0.02f));
        Assert.True(result.Succeeded);
        AssertVec.Near(new Vector3(90, 90, 0.005f), result.Position.Origin, 1e-4f);
        Assert.True(result.Next.Contact);
        Assert.True(result.Next.OnWalkable);
    }

    [Fact]
    public void PlacingOnTopOfTheDoor_FindsTheNearestFreeSpot()
    {
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var request = TestGeometry.At(TestScenes.DoorOrigin.X, TestScenes.DoorOrigin.Y, 0.005f);
        var result = engine.Place(MoverDescription.Player(), request);
        Assert.True(result.Succeeded);
        Assert.True(TestScenes.SlabPenetration(result.Position.Origin) <= PhysicsConstants.Epsilon, $"placed into the slab at {result.Position.Origin}");
        float moved = Vector3.Distance(request.Origin, result.Position.Origin);
        Assert.InRange(moved, 0.1f, 4.01f);
    }

    [Fact]
    public void PlacingWithAnUnknownCell_Throws()
    {
        var engine = new PhysicsEngine(TestScenes.Door());
        var ex = Assert.Throws<ArgumentException>(() => engine.Place(MoverDescription.Player(), new Position(0x01020001, Vector3.One)));
        Assert.Contains("0x01020001", ex.Message);
    }
}
