using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// The object cull (not retail; it changes no result): objects beyond reach of the check spheres are not
/// tested, are reported as skipped, and an object moved into the path between frames is seen at once.
/// </summary>
public class ObjectCullTests
{
    private const uint BarrelId = 0x7200_0001;

    private static readonly PhysicsSetup Barrel = new()
    {
        CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 1.0f)],
        Height = 1f,
        Radius = 0.4f,
    };

    /// <summary>The door world with a barrel in the door's 24 m cell, 8 m to the side of the door.</summary>
    private static PhysicsWorld DoorAndFarBarrel()
    {
        var world = TestScenes.Door();
        world.Objects.Register(BarrelId, Barrel, TestGeometry.At(108f, 100f, 0f), 1f, PhysicsState.ReportCollisions);
        return world;
    }

    [Fact]
    public void AnObjectBeyondReach_IsReportedSkippedOutOfReach_AndNeverTested()
    {
        var player = TestScenes.Player(DoorAndFarBarrel(), 100, 98.5f).With(Shortcuts.All).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 12);

        var events = player.Log!.Events;
        Assert.Contains(events, e => e.Kind == TransitionEventKind.ShapeSkipped && e.EntityId == BarrelId && e.Reason == SkipReason.OutOfReach);
        Assert.DoesNotContain(events, e => e.Kind == TransitionEventKind.ShapeTested && e.EntityId == BarrelId);
        // The door on the path is still tested, and stops the player.
        Assert.Contains(events, e => e.Kind == TransitionEventKind.ShapeTested && e.EntityId == TestScenes.DoorId);
        Assert.Contains(player.Frames, f => f.Collided.Contains(TestScenes.DoorId));
    }

    [Fact]
    public void AnObjectWithinReach_IsTested()
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(BarrelId, Barrel, TestGeometry.At(100f, 101.5f, 0f), 1f, PhysicsState.ReportCollisions);
        var player = TestScenes.Player(world, 100, 100).WithLog();
        player.Walk(new Vector3(0, 0.1f, 0), 10);

        Assert.Contains(player.Log!.Events, e => e.Kind == TransitionEventKind.ShapeTested && e.EntityId == BarrelId);
        Assert.Contains(player.Frames, f => f.Collided.Contains(BarrelId));
        // Stopped at the barrel: centres 0.4 + 0.48 apart at most, less the slide tolerance.
        Assert.True(player.Origin.Y < 101.5f - 0.85f, $"the player stops at the barrel, got y = {player.Origin.Y}");
    }

    [Fact]
    public void AnObjectMovedIntoThePathBetweenFrames_IsHitOnTheNextFrame()
    {
        // The barrel starts in the player's 24 m cell (72..96 on both axes), far from its path.
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(BarrelId, Barrel, TestGeometry.At(75f, 75f, 0f), 1f, PhysicsState.ReportCollisions);
        var player = TestScenes.Player(world, 90, 90);
        player.Walk(new Vector3(0, 0.1f, 0), 3);
        Assert.DoesNotContain(player.Frames, f => f.Collided.Length > 0);

        // Right in front of the player: 0.8 m ahead, within one frame's reach of its spheres.
        world.Objects.Move(BarrelId, TestGeometry.At(player.Origin.X, player.Origin.Y + 0.9f, 0f));
        player.Walk(new Vector3(0, 0.1f, 0), 1);

        Assert.Contains(BarrelId, player.Frames[^1].Collided);
    }

    [Fact]
    public void AnObjectReplacedBetweenFrames_TheNewOneIsHit_NotTheRowsOfTheOld()
    {
        // A barrel beside the path, within the cull's reach (listed as a candidate with its rows) but never
        // touched; the walk keeps the same region and lists from frame to frame.
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(BarrelId, Barrel, TestGeometry.At(91.5f, 90.5f, 0f), 1f, PhysicsState.ReportCollisions);
        var player = TestScenes.Player(world, 90, 90);
        player.Walk(new Vector3(0, 0.1f, 0), 2);
        Assert.DoesNotContain(player.Frames, f => f.Collided.Length > 0);

        // Another object takes the barrel's place in the cell's list, right in front of the player: the
        // cull's kept lists (indices and rows) must be made again, or the old barrel's rows are tested.
        const uint other = BarrelId + 1;
        Assert.True(world.Objects.Unregister(BarrelId));
        world.Objects.Register(other, Barrel, TestGeometry.At(player.Origin.X, player.Origin.Y + 0.9f, 0f), 1f, PhysicsState.ReportCollisions);
        player.Walk(new Vector3(0, 0.1f, 0), 1);

        Assert.Contains(other, player.Frames[^1].Collided);
    }

    [Fact]
    public void AnObjectAcrossALandblockSeam_IsHit()
    {
        // A 0.5 m ball 1 m east of the seam between landblocks 0xA9B4 and 0xAAB4 (global x 193 from
        // 0xA9B4's corner), centre 0.5 m up; the player walks east at it from x 190 in 0xA9B4. Its lower
        // sphere (0.48 m at 0.475 m) must stop touching the ball: centres at least 0.98 m apart.
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Physics.Terrain.Flat(0xA9B4, 0f));
        world.Cells.AddLandblock(Physics.Terrain.Flat(0xAAB4, 0f));
        var ballAt = Position.Outdoor(0xAAB4, new Vector3(1, 100, 0.5f));
        world.Objects.Register(7, new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.5f)] }, ballAt);
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var state = MoverState.OnFloor(Position.Outdoor(0xA9B4, new Vector3(190, 100, 0)), 0f);
        bool hit = false;
        for (int frame = 0; frame < 12; frame++)
        {
            var target = state.Position;
            target.Frame.Origin.X += 0.3f;
            var result = engine.Resolve(player, state, target);
            state = result.Next;
            hit |= result.CollidedObjects.Span.Contains(7u);
            var lower = state.Position.ToGlobal() + new Vector3(0, 0, 0.475f);
            float apart = Vector3.Distance(lower, ballAt.ToGlobal());
            Assert.True(apart >= 0.98f - 1e-3f, $"frame {frame}: the player's sphere is {0.98f - apart} m inside the ball at {state.Position}");
        }
        Assert.True(hit, "the player never touched the ball across the seam");
    }

    [Fact]
    public void AJumpIntoABallFarAboveTheStart_IsStoppedByIt()
    {
        // The player jumps straight up at 10 m/s from the floor; a 0.5 m ball hangs right above it, centre
        // 5.5 m up. The first object region is made on the jump's first quantum, around spheres whose top is
        // under 2.2 m (head sphere 0.48 m at 1.35 m, risen 0.33 m), reaching 2 m higher (step-down 1.5 + 0.5,
        // the move's rest is 0): the ball, from 5.0 m up, lies above it. Free, the head's top would rise to
        // 1.83 + 10² / (2 × 9.8) = 6.93 m, through the ball; it must stop where the head sphere touches it:
        // head centre at most 5.5 − 0.98 = 4.52 m, origin at most 4.52 − 1.35 = 3.17 m. The spheres leave the
        // region through its top, so a new region must be made there.
        var world = TestGeometry.FlatWorld();
        var ballAt = TestGeometry.At(100f, 100f, 5.5f);
        world.Objects.Register(BarrelId, new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.5f)] }, ballAt);
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(100f, 100f, 0f), 0f);
        var body = AcDream.Core.Physics.BodyState.Creature();
        bool hit = false;
        float top = 0f;
        for (int frame = 0; frame < 30; frame++)
        {
            var step = engine.Step(player, state, body, 1.0 / 30, Vector3.Zero, frame == 0 ? 10f : 0f);
            state = step.Next;
            body = step.Body;
            hit |= step.Move.CollidedObjects.Span.Contains(BarrelId);
            top = MathF.Max(top, state.Position.Origin.Z);
            Assert.True(state.Position.Origin.Z <= 3.17f + 1e-3f, $"frame {frame}: the player rose to {state.Position.Origin.Z} m, into the ball");
        }
        Assert.True(hit, $"the player never touched the ball (highest origin {top} m)");
    }

    [Fact]
    public void AColumnsTop_HoldsAPlayerWalkingOnIt()
    {
        // A column (cylinder, radius 1.5 m, 6 m tall, foot at z = 0) and the player without EdgeSlide standing on
        // its top, walking 0.1 m a frame across it (8 frames, never nearer the rim than 0.7 m). The object region
        // reaches about 3 m below the spheres (step-down 1.5 + 0.5 + 1), far above the column's foot: only the
        // column's height puts its reach box there. On the cap the foot sphere (radius 0.48, centre 0.475 above
        // the origin) touches z = 6, so the origin stays at 6.005, in contact with walkable ground every frame.
        var world = TestGeometry.FlatWorld();
        var column = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 1.5f, 6f)], Height = 6f, Radius = 1.5f };
        world.Objects.Register(BarrelId, column, TestGeometry.At(100f, 100f, 0f), 1f, PhysicsState.Static);
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player().With(physicsState: PhysicsState.Gravity);
        var state = MoverState.OnFloor(TestGeometry.At(100f, 100f, 6.005f), 6f);
        for (int frame = 0; frame < 8; frame++)
        {
            var target = state.Position;
            target.Frame.Origin.X += 0.1f;
            state = engine.Resolve(player, state, target).Next;
            Assert.True(state.Contact && state.OnWalkable, $"frame {frame}: the player lost the column's top at {state.Position}");
            Assert.InRange(state.Position.Origin.Z, 6f, 6.01f);
        }
        Assert.Equal(100.8f, state.Position.Origin.X, 3);
    }
}
