using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Diagnostics;

namespace AcDream.Core.Physics.Tests.Apparatus;

public class CellTransitTests
{
    [Fact]
    public void WalkingThroughTheDoorway_MovesTheMoverFromTheLandCellIntoTheEnvCell()
    {
        var world = Cottage.Build();
        var player = TestScenes.Player(world, 100, 107).WithLog();
        uint outdoor = player.State.Position.CellId;
        Assert.True(LandDefs.IsLandCell(outdoor));
        player.Walk(new Vector3(0, 0.1f, 0), 50); // to y = 112, two metres into the room

        Assert.Equal(Cottage.RoomId, player.State.Position.CellId);
        Assert.InRange(player.Origin.Y, 111.9f, 112.1f);
        Assert.InRange(player.Origin.Z, 0f, 0.01f);
        Assert.True(player.State.OnWalkable, "the room's floor holds the player");
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.CellChanged && e.ToCell == Cottage.RoomId);
        // The cell changes when sphere 0's centre crosses the room's south plane (y = 110), within the cell BSP's EPSILON.
        var firstInside = player.Frames.First(f => f.Cell == Cottage.RoomId);
        Assert.True(firstInside.After.Y >= 110f - PhysicsConstants.Epsilon && firstInside.Before.Y < 110f);
    }

    [Fact]
    public void WalkingBackOut_ReturnsToTheLandCell()
    {
        var world = Cottage.Build();
        var start = new Position(Cottage.RoomId, new Vector3(100, 112, 0));
        var player = new Mover(world, MoverDescription.Player(), MoverState.OnFloor(start, 0f));
        player.Walk(new Vector3(0, -0.1f, 0), 50);
        Assert.True(LandDefs.IsLandCell(player.State.Position.CellId));
        Assert.InRange(player.Origin.Y, 106.9f, 107.1f);
    }

    [Fact]
    public void TheShellBesideTheDoorway_BlocksFromOutside()
    {
        var world = Cottage.Build();
        var player = TestScenes.Player(world, 101.5f, 107);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y <= 110f - 0.2f - TestScenes.PlayerRadius + PhysicsConstants.Epsilon * 5, $"y = {player.Origin.Y}");
        Assert.True(LandDefs.IsLandCell(player.State.Position.CellId));
    }

    [Fact]
    public void TheRoomsNorthWall_BlocksFromInside()
    {
        var world = Cottage.Build();
        var start = new Position(Cottage.RoomId, new Vector3(100, 111, 0));
        var player = new Mover(world, MoverDescription.Player(), MoverState.OnFloor(start, 0f));
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y <= 114f - TestScenes.PlayerRadius + PhysicsConstants.Epsilon * 5, $"y = {player.Origin.Y}");
        Assert.Equal(Cottage.RoomId, player.State.Position.CellId);
    }
}
