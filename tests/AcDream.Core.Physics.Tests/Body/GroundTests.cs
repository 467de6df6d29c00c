using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// MoverState.Ground / GroundObjectId say what set the contact plane (terrain, an env cell's floor, a
/// building, an object and its id), and GroundState sums up Contact and OnWalkable.
/// </summary>
public class GroundTests
{
    private static BodyDriver Drop(PhysicsWorld world, Position from)
    {
        var driver = new BodyDriver(world, MoverDescription.Player(), MoverState.Airborne(from), BodyState.Creature());
        driver.RunUntil(1.0 / 30, Vector3.Zero, s => s.Contact && s.OnWalkable, maxSeconds: 5);
        // A few more frames: the landing hop settles.
        for (int i = 0; i < 30; i++) driver.Step(1.0 / 30, Vector3.Zero);
        return driver;
    }

    [Fact]
    public void OnTerrain_TheGroundIsTheTerrainOfTheLandCell()
    {
        var d = Drop(TestGeometry.FlatWorld(), TestGeometry.At(100, 100, 3));
        Assert.Equal(GroundKind.Terrain, d.State.Ground);
        Assert.Equal(0u, d.State.GroundObjectId);
        Assert.Equal(LandDefs.LandCellAt(TestGeometry.Landblock, new Vector3(100, 100, 0)), d.State.ContactPlaneCellId);
        Assert.Equal(GroundState.WalkableGround, d.State.GroundState);
    }

    [Fact]
    public void OnACrate_TheGroundIsTheObjectAndItsId()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0042, new Vector3(98, 98, 0), new Vector3(102, 102, 1));
        var d = Drop(world, TestGeometry.At(100, 100, 3));
        Assert.Equal(GroundKind.Object, d.State.Ground);
        Assert.Equal(0x7000_0042u, d.State.GroundObjectId);
        Assert.InRange(d.Origin.Z, 1f, 1.01f);
    }

    [Fact]
    public void OnACylinder_TheGroundIsTheObject()
    {
        var world = TestGeometry.FlatWorld();
        var post = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 1.5f, 1f)] };
        world.Objects.Register(0x7000_0043, post, TestGeometry.At(100, 100, 0), 1f, PhysicsState.Static);
        var d = Drop(world, TestGeometry.At(100, 100, 3));
        Assert.Equal(GroundKind.Object, d.State.Ground);
        Assert.Equal(0x7000_0043u, d.State.GroundObjectId);
    }

    [Fact]
    public void OnABuildingsRoof_TheGroundIsTheBuilding()
    {
        var world = TestGeometry.FlatWorld();
        var shell = new PhysicsModel(BspShapes.Box(new Vector3(-4, -4, 0), new Vector3(4, 4, 2)), name: "platform");
        var at = new Vector3(100, 100, 0);
        world.Cells.AddBuilding(new Building(shell, new Position(LandDefs.LandCellAt(TestGeometry.Landblock, at), new Frame(at)), []));
        var d = Drop(world, TestGeometry.At(100, 100, 4));
        Assert.Equal(GroundKind.Building, d.State.Ground);
        Assert.InRange(d.Origin.Z, 2f, 2.01f);
    }

    [Fact]
    public void InARoom_TheGroundIsTheEnvCellsFloor()
    {
        var world = Cottage.Build();
        var from = new Position(Cottage.RoomId, new Frame(Cottage.RoomOrigin + new Vector3(0, 2, 1)));
        var d = Drop(world, from);
        Assert.Equal(GroundKind.EnvCell, d.State.Ground);
        Assert.Equal(Cottage.RoomId, d.State.ContactPlaneCellId);
    }

    [Fact]
    public void MoverState_GrowsByTheObjectIdOnly()
    {
        // 72 bytes before: the kind sits in the padding after OnWalkable, the id adds 4 (a hot-path copy).
        Assert.Equal(76, System.Runtime.CompilerServices.Unsafe.SizeOf<MoverState>());
    }

    [Fact]
    public void GroundState_IsRetailsContactAndOnWalkable()
    {
        var s = new MoverState();
        Assert.Equal(GroundState.Airborne, s.GroundState);
        s.OnWalkable = true; // ON_WALKABLE without CONTACT: retail reads CONTACT first
        Assert.Equal(GroundState.Airborne, s.GroundState);
        s.Contact = true;
        Assert.Equal(GroundState.WalkableGround, s.GroundState);
        s.OnWalkable = false;
        Assert.Equal(GroundState.SteepSurface, s.GroundState);
    }

    [Fact]
    public void AJump_LeavesTheGround_AndTheGroundIsKeptWithTheLastPlane()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0044, new Vector3(98, 98, 0), new Vector3(102, 102, 1));
        var d = Drop(world, TestGeometry.At(100, 100, 3));
        d.Step(1.0 / 30, Vector3.Zero, jump: 5f);
        d.Step(1.0 / 30, Vector3.Zero);
        Assert.Equal(GroundState.Airborne, d.State.GroundState);
        // The plane the mover left is still carried (retail's last known contact plane), and so is what set it.
        Assert.Equal(GroundKind.Object, d.State.Ground);
    }
}
