using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// Moves refused before their first sub-step (a mover pushing into the wall it already slid against) and
/// the engine's memory of the last such refusal (not retail; neither changes a result): what a refusal
/// returns, which moves are not refused, and which changes to a request are not answered from memory.
/// The door's front face is at y = 100 − 0.009 = 99.991, so the retail player (r 0.48) stops with its
/// centre at y = 99.511 and a ball of radius 0.1 at y = 99.891.
/// </summary>
public class RefusedMoveTests
{
    private const float PlayerStopY = 100f - 0.009f - 0.48f;
    private const float BallStopY = 100f - 0.009f - 0.1f;
    private static readonly Vector3 HeadOn = new(0, 2f / 30f, 0);

    private static MoverDescription Ball() => new(0x5000_0002, [new Sphere(new Vector3(0, 0, 0.1f), 0.1f)], 0.2f, 0.04f);

    /// <summary>The player walked head-on into the door until it stands against it with a sliding normal.</summary>
    private static Mover PlayerAgainstTheDoor(PhysicsWorld world)
    {
        var player = TestScenes.Player(world, 100, PlayerStopY - 0.2f, MoverDescription.Player());
        player.Walk(HeadOn, 4);
        Assert.Equal(PlayerStopY, player.Origin.Y, 3e-3f);
        Assert.True(player.State.SlidingNormalValid, "the stop leaves a sliding normal");
        return player;
    }

    /// <summary>A player stopped against the door, and a second engine over the same world (no memory yet).</summary>
    private static (PhysicsEngine Engine, Mover Player) FreshEngineBesidePlayerAgainstTheDoor()
    {
        var world = TestScenes.Door();
        return (new PhysicsEngine(world), PlayerAgainstTheDoor(world));
    }

    private static Position Ahead(in MoverState state, Vector3 offset)
    {
        var target = state.Position;
        target.Frame.Origin += offset;
        return target;
    }

    [Fact]
    public void PushingIntoTheWallAlreadySlidAgainst_IsRefused_AndChangesNothing()
    {
        var (engine, player) = FreshEngineBesidePlayerAgainstTheDoor();
        var state = player.State;

        for (int frame = 0; frame < 3; frame++)
        {
            var result = engine.Resolve(player.Description, state, Ahead(state, HeadOn));
            Assert.False(result.Succeeded, $"frame {frame}: the push is refused");
            Assert.Equal(TransitionState.Collided, result.LastState);
            Assert.Equal(state.Position, result.Next.Position);
            Assert.Equal(state.SlidingNormal, result.Next.SlidingNormal);
            Assert.True(result.Next.SlidingNormalValid);
            Assert.False(result.CollisionNormalValid, $"frame {frame}: nothing was inserted, so nothing was hit");
            Assert.Equal(0, result.CollidedObjects.Length);
            Assert.False(result.VelocityKilled);
            state = result.Next;
        }
    }

    [Fact]
    public void SlidingAlongTheWall_AfterStoppingAgainstIt_IsNotRefused()
    {
        var world = TestScenes.Door();
        var player = PlayerAgainstTheDoor(world);
        float x = player.Origin.X;

        player.Walk(new Vector3(0.05f, 0.05f, 0), 3);

        Assert.All(player.Frames.TakeLast(3), f => Assert.True(f.Result.Succeeded));
        // Only the part along the face is kept: 0.05 m east per frame, none north.
        Assert.Equal(x + 0.15f, player.Origin.X, 2e-3f);
        Assert.Equal(PlayerStopY, player.Origin.Y, 3e-3f);
    }

    [Fact]
    public void TheSameRequestWithoutItsSlidingNormal_IsNotAnsweredFromTheLastRefusal()
    {
        var (engine, player) = FreshEngineBesidePlayerAgainstTheDoor();
        var state = player.State;
        Assert.False(engine.Resolve(player.Description, state, Ahead(state, HeadOn)).Succeeded);

        var withoutNormal = state;
        withoutNormal.SlidingNormalValid = false;
        withoutNormal.SlidingNormal = Vector3.Zero;
        var result = engine.Resolve(player.Description, withoutNormal, Ahead(withoutNormal, HeadOn));

        // Inserted this time: the door is hit and reported.
        Assert.Contains(TestScenes.DoorId, result.CollidedObjects.ToArray());
        Assert.True(result.Next.SlidingNormalValid, "the hit gives the sliding normal back");
    }

    [Fact]
    public void AnotherMoverWithTheSameRequest_IsNotAnsweredFromTheLastRefusal()
    {
        var (engine, player) = FreshEngineBesidePlayerAgainstTheDoor();
        var state = player.State;
        var target = Ahead(state, HeadOn);
        Assert.False(engine.Resolve(player.Description, state, target).Succeeded);

        // The camera's sphere is never refused before its first sub-step (retail returns early only for
        // movers that are not the viewer): its cancelled step is inserted where it stands, and succeeds.
        var viewer = new MoverDescription(0, [new Sphere(new Vector3(0, 0, 0.475f), 0.48f)], 0f, 0f,
            PhysicsState.None, ObjectInfoState.IsViewer);
        var result = engine.Resolve(viewer, state, target);
        Assert.True(result.Succeeded, "the viewer is inserted, not refused");
        Assert.Equal(state.Position.Origin, result.Next.Position.Origin);
    }

    [Fact]
    public void AChangedSubStepScale_IsNotAnsweredFromTheLastRefusal()
    {
        var world = TestGeometry.FlatWorld();
        var player = TestScenes.Player(world, 100, 100, MoverDescription.Player());
        var engine = new PhysicsEngine(world);
        var state = player.State;
        var target = Ahead(state, new Vector3(0, 0.5f, 0));

        // 0.5 m in steps of 0.48 × 0.0005 m is more than MaxSubSteps (1,000): refused at once, as retail.
        engine.SubStepScale = 0.0005f;
        Assert.False(engine.Resolve(player.Description, state, target).Succeeded);

        engine.SubStepScale = 1f;
        var result = engine.Resolve(player.Description, state, target);
        Assert.True(result.Succeeded, "with retail's sub-steps the same request moves");
        Assert.Equal(100.5f, result.Next.Position.Origin.Y, 1e-4f);
    }

    [Fact]
    public void AnotherTargetFromTheRefusedState_IsNotAnsweredFromTheLastRefusal()
    {
        // Refused head-on, then asked from the very same state for a step along the face: 0.05 m east is kept,
        // 0.05 m north is not (the wall), as in SlidingAlongTheWall_AfterStoppingAgainstIt_IsNotRefused.
        var (engine, player) = FreshEngineBesidePlayerAgainstTheDoor();
        var state = player.State;
        Assert.False(engine.Resolve(player.Description, state, Ahead(state, HeadOn)).Succeeded);

        var result = engine.Resolve(player.Description, state, Ahead(state, new Vector3(0.05f, 0.05f, 0)));

        Assert.True(result.Succeeded, "a step along the wall is not the refused push");
        Assert.Equal(state.Position.Origin.X + 0.05f, result.Next.Position.Origin.X, 2e-3f);
        Assert.Equal(PlayerStopY, result.Next.Position.Origin.Y, 3e-3f);
    }

    [Fact]
    public void TheSameRequestOutOfContact_IsNotAnsweredFromTheLastRefusal()
    {
        // Standing on flat ground (contact plane z = 0, foot sphere touching it: origin 0.005) and asked to go
        // 0.1 m straight down: in contact the step is projected onto the contact plane, nothing is left, and the
        // move is refused before its first sub-step. The same request out of contact (the walkable flag and the
        // plane unchanged) falls onto the ground and lands there: inserted, in contact, the origin at 0.005.
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var standing = MoverState.OnFloor(TestGeometry.At(100, 100, 0.005f), 0f);
        var down = Ahead(standing, new Vector3(0, 0, -0.1f));
        var refused = engine.Resolve(player, standing, down);
        Assert.False(refused.Succeeded, "straight down into the contact plane leaves nothing to move");

        var falling = standing;
        falling.Contact = false;
        var result = engine.Resolve(player, falling, down);

        Assert.True(result.Succeeded, "out of contact the step is not projected away");
        Assert.True(result.Next.Contact, "it lands on the ground");
        Assert.Equal(0.005f, result.Next.Position.Origin.Z, 3e-3f);
    }

    [Fact]
    public void ARefusedRequest_AfterItsLandblockIsUnloaded_IsCheckedAgain()
    {
        // The same push, refused once; then the landblock it stands in is unloaded. The request now names a
        // cell that is not in the world, which the input checks refuse, naming it (the remembered refusal
        // must not answer for a world that lost cells).
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var player = PlayerAgainstTheDoor(world);
        var state = player.State;
        var target = Ahead(state, HeadOn);
        Assert.False(engine.Resolve(player.Description, state, target).Succeeded);

        world.UnloadLandblock(state.Position.CellId >> 16);

        var error = Assert.Throws<ArgumentException>(() => engine.Resolve(player.Description, state, target));
        Assert.StartsWith("state.position.cell", error.Message);
    }

    [Fact]
    public void TwoMoversResolvedInTurnByOneEngine_EachStopAtTheirOwnDistance()
    {
        // The engine keeps the spheres of the position a move ended at for the next move; a different
        // mover at a different position must never be given them.
        var world = TestScenes.Door();
        var engine = new PhysicsEngine(world);
        var player = MoverDescription.Player();
        var ball = Ball();
        var playerState = MoverState.OnFloor(TestGeometry.At(100, PlayerStopY - 0.2f, 0), 0f);
        var ballState = MoverState.OnFloor(TestGeometry.At(100, BallStopY - 0.2f, 0), 0f);

        for (int frame = 0; frame < 8; frame++)
        {
            playerState = engine.Resolve(player, playerState, Ahead(playerState, HeadOn)).Next;
            ballState = engine.Resolve(ball, ballState, Ahead(ballState, HeadOn)).Next;
        }

        Assert.Equal(PlayerStopY, playerState.Position.Origin.Y, 3e-3f);
        Assert.Equal(BallStopY, ballState.Position.Origin.Y, 3e-3f);
    }
}
