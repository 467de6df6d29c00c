using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>Objects without a BSP collide through their cylinders or, lacking those, their spheres.</summary>
public class ObjectRungTests
{
    private const uint ObjectId = 0x7000_0010;

    private static PhysicsWorld WorldWith(PhysicsSetup setup, Vector3 at, PhysicsState state = PhysicsState.Static, ShadowFlags flags = ShadowFlags.None)
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(ObjectId, setup, TestGeometry.At(at.X, at.Y, at.Z), 1f, state, flags);
        return world;
    }

    [Fact]
    public void TreeTrunk_CylinderOnly_BlocksWithARadialNormal()
    {
        var trunk = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 5f)] };
        var world = WorldWith(trunk, new Vector3(100, 104, 0));
        var player = TestScenes.Player(world, 100, 101).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        float stop = 104 - 0.4f - TestScenes.PlayerRadius;
        Assert.InRange(player.Origin.Y, stop - 0.1f, stop + PhysicsConstants.Epsilon * 5);
        var normal = player.Log!.Events.Last(e => e.Kind == TransitionEventKind.ObjectNormal);
        Assert.Equal(ShadowShapeKind.Cylinder, normal.ShapeKind);
        AssertVec.Near(new Vector3(0, -1, 0), normal.Vector, 1e-3f);
    }

    [Fact]
    public void Boulder_SphereOnly_BlocksWithoutPenetration()
    {
        var centre = new Vector3(100, 104, 1f);
        var boulder = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, 1f), 1f)] };
        var world = WorldWith(boulder, new Vector3(100, 104, 0));
        var player = TestScenes.Player(world, 100, 101).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y < 103f, $"the boulder should stop the player, y = {player.Origin.Y}");
        foreach (var f in player.Frames)
            foreach (float z in new[] { 0.475f, 1.35f })
                Assert.True(Vector3.Distance(f.After + new Vector3(0, 0, z), centre) >= 1f + TestScenes.PlayerRadius - PhysicsConstants.Epsilon * 5);
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Sphere);
    }

    [Fact]
    public void CylinderAndSphere_OnlyTheCylinderIsTested()
    {
        var both = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 5f)], Spheres = [new Sphere(new Vector3(0, 0, 1), 1.5f)] };
        var world = WorldWith(both, new Vector3(100, 104, 0));
        var player = TestScenes.Player(world, 100, 101).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.DoesNotContain(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.ShapeKind == ShadowShapeKind.Sphere);
        Assert.True(player.Origin.Y > 102.5f, "the big sphere is never tested, so the player reaches the trunk");
    }

    [Fact]
    public void TwoPlayers_PassThroughEachOther_ThePvpExemptionTestsNothing()
    {
        var otherPlayer = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.35f, 1.8f)] };
        var world = WorldWith(otherPlayer, new Vector3(100, 104, 0), PhysicsState.None, ShadowFlags.IsPlayer | ShadowFlags.IsCreature | ShadowFlags.HasWeenie);
        var player = TestScenes.Player(world, 100, 101).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 60);
        Assert.True(player.Origin.Y > 105f);
        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeSkipped && e.Reason == SkipReason.Exempt);
    }

    [Fact]
    public void TwoPkPlayers_Collide_ThroughTheCylinderRung()
    {
        var otherPlayer = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.35f, 1.8f)] };
        var world = WorldWith(otherPlayer, new Vector3(100, 104, 0), PhysicsState.None, ShadowFlags.IsPlayer | ShadowFlags.IsCreature | ShadowFlags.IsPK | ShadowFlags.HasWeenie);
        var pk = new MoverDescription(0x50000002, MoverDescription.Player().Spheres, 0.6f, 0.04f,
            PhysicsState.Gravity | PhysicsState.EdgeSlide, ObjectInfoState.IsPlayer | ObjectInfoState.IsPK);
        var player = TestScenes.Player(world, 100, 101, pk);
        player.Walk(new Vector3(0, 0.1f, 0), 60);
        Assert.True(player.Origin.Y < 104f - 0.35f - TestScenes.PlayerRadius + PhysicsConstants.Epsilon * 5);
        Assert.Contains(player.Frames, f => f.Collided.Contains(ObjectId));
    }

    [Fact]
    public void MissileMover_IgnoresACreatureThatIsNotItsTarget_ButHitsTheDoorSlab()
    {
        var creature = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.5f, 2f)] };
        var world = WorldWith(creature, new Vector3(100, 102, 0), PhysicsState.None, ShadowFlags.IsCreature | ShadowFlags.HasWeenie);
        world.Objects.Register(TestScenes.DoorId, TestGeometry.DoorSetup(), TestGeometry.At(100, 106, 0), 1f, PhysicsState.ReportCollisions);
        var arrow = new MoverDescription(0x80000001, [new Sphere(new Vector3(0, 0, 1f), 0.05f)], 0f, 0f,
            PhysicsState.Missile, ObjectInfoState.None, targetId: 0x12345678);
        var mover = new Mover(world, arrow, MoverState.Airborne(TestGeometry.At(100, 100, 0)));
        mover.Walk(new Vector3(0, 0.5f, 0), 20);
        Assert.True(mover.Origin.Y > 103f, "the arrow flies through the creature it is not aimed at");
        Assert.True(mover.Origin.Y < 106f - 0.009f - 0.05f + PhysicsConstants.Epsilon * 5, $"the slab stops the arrow, y = {mover.Origin.Y}");
    }
}
