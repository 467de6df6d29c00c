using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// ContactTracker: retail's collision records (CPhysicsObj::track_object_collision / report_collision_end /
/// report_environment_collision) as start and end events per mover.
/// </summary>
public class ContactTrackerTests
{
    // 1/16 s frames: the clock is exact in binary, so 16 frames are exactly the 1 s timeout.
    private const double Dt = 1.0 / 16;
    private const uint Post = 0x7100_0001;

    private static PhysicsWorld PostWorld(PhysicsState state)
    {
        var world = TestGeometry.FlatWorld();
        var post = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.5f, 2f)] };
        world.Objects.Register(Post, post, TestGeometry.At(100, 103, 0), 1f, state, ShadowFlags.IsCreature);
        return world;
    }

    private sealed record Frame(int Index, ContactEvent[] Events, bool Touched);

    /// <summary>A runner heading north past the post's west side (it grazes it and slides by), then on.</summary>
    private static List<Frame> RunPast(PhysicsWorld world, int frames, Vector3 desired, float startX = 99.6f)
    {
        var engine = new PhysicsEngine(world);
        var tracker = new ContactTracker(world);
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(startX, 100, 0), 0f);
        var body = BodyState.Creature();
        var log = new List<Frame>();
        for (int i = 1; i <= frames; i++)
        {
            var r = engine.Step(mover, state, body, Dt, desired);
            tracker.Track(r, state, i * Dt);
            state = r.Next;
            body = r.Body;
            log.Add(new Frame(i, tracker.Events.ToArray(), r.Move.CollidedObjects.Span.Contains(Post)));
        }
        return log;
    }

    [Fact]
    public void AnObjectContact_StartsOnceWhenFirstHit_AndEndsMoreThanOneSecondAfterTheLastTouch()
    {
        var log = RunPast(PostWorld(PhysicsState.None), 60, new Vector3(0, 4, 0));
        int first = log.First(f => f.Touched).Index;
        int last = log.Last(f => f.Touched).Index;
        var starts = log.Where(f => f.Events.Any(e => e.Kind == ContactEventKind.ObjectStart)).ToList();
        var ends = log.Where(f => f.Events.Any(e => e.Kind == ContactEventKind.ObjectEnd)).ToList();
        Assert.Single(starts);
        Assert.Equal(first, starts[0].Index);
        Assert.Equal(Post, starts[0].Events.Single(e => e.Kind == ContactEventKind.ObjectStart).ObjectId);
        // 16 frames after the last touch are exactly 1 s, which is not more than the timeout: the 17th ends it.
        Assert.Single(ends);
        Assert.Equal(last + 17, ends[0].Index);
        Assert.Equal(Post, ends[0].Events.Single().ObjectId);
    }

    [Fact]
    public void AnEtherealObject_EndsAtTheFirstTrackedStepWithoutATouch()
    {
        var log = RunPast(PostWorld(PhysicsState.Ethereal), 60, new Vector3(0, 4, 0), startX: 100f);
        int last = log.Last(f => f.Touched).Index;
        Assert.Contains(log, f => f.Events.Any(e => e.Kind == ContactEventKind.ObjectStart));
        var end = log.Single(f => f.Events.Any(e => e.Kind == ContactEventKind.ObjectEnd));
        Assert.Equal(last + 1, end.Index);
    }

    [Fact]
    public void ALanding_StartsAnEnvironmentContact_AndTheNextTransitionWithoutOne_EndsIt()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var tracker = new ContactTracker(world);
        var mover = MoverDescription.Player();
        var state = MoverState.Airborne(TestGeometry.At(100, 100, 1));
        var body = BodyState.Creature();
        var events = new List<(int Frame, ContactEventKind Kind, bool Walkable)>();
        for (int i = 1; i <= 40; i++)
        {
            var r = engine.Step(mover, state, body, Dt, new Vector3(0, 2, 0));
            tracker.Track(r, state, i * Dt);
            foreach (var e in tracker.Events)
                events.Add((i, e.Kind, r.Next.OnWalkable));
            state = r.Next;
            body = r.Body;
        }
        Assert.NotEmpty(events);
        Assert.Equal(ContactEventKind.EnvironmentStart, events[0].Kind);
        Assert.True(events[0].Walkable);
        // Starts and ends alternate, beginning with the landing.
        for (int i = 1; i < events.Count; i++)
            Assert.NotEqual(events[i - 1].Kind, events[i].Kind);
        Assert.Equal(ContactEventKind.EnvironmentEnd, events[1].Kind);
    }

    [Fact]
    public void ARefusedMove_ChangesNothing_AndEndAllEndsEveryRecord()
    {
        var world = PostWorld(PhysicsState.None);
        var engine = new PhysicsEngine(world);
        var tracker = new ContactTracker(world);
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(100, 101.5f, 0), 0f);
        // Push straight into the post until a move is refused.
        MoveResult r = default;
        double now = 0;
        for (int i = 0; i < 20; i++)
        {
            var target = state.Position;
            target.Frame.Origin += new Vector3(0, 0.3f, 0);
            r = engine.Resolve(mover, state, target);
            tracker.Track(r, state, now += 0.5);
            if (!r.Succeeded) break;
            state = r.Next;
        }
        Assert.False(r.Succeeded);
        Assert.Empty(tracker.Events.ToArray());
        Assert.True(tracker.IsTouching(Post));
        // Refused moves for 3 s: retail runs no handle_all_collisions, so the record stays.
        for (int i = 0; i < 6; i++)
            tracker.Track(r, state, now += 0.5);
        Assert.True(tracker.IsTouching(Post));
        tracker.EndAll(now);
        Assert.Equal([new ContactEvent(ContactEventKind.ObjectEnd, Post).ToString()], tracker.Events.ToArray().Select(e => e.ToString()));
        Assert.Equal(0, tracker.ObjectCount);
        var ex = Assert.Throws<ArgumentException>(() => tracker.EndAll(now - 1));
        Assert.StartsWith("now", ex.Message);
    }

    [Fact]
    public void Tracking_AllocatesNothing_OnceWarm()
    {
        var world = PostWorld(PhysicsState.None);
        var engine = new PhysicsEngine(world);
        var tracker = new ContactTracker(world);
        var mover = MoverDescription.Player();
        var body = BodyState.Creature();
        double now = 0;
        void Walk()
        {
            var state = MoverState.OnFloor(TestGeometry.At(99.6f, 100, 0), 0f);
            var b = body;
            for (int i = 0; i < 60; i++)
            {
                var r = engine.Step(mover, state, b, Dt, new Vector3(0, 4, 0));
                tracker.Track(r, state, now += Dt);
                state = r.Next;
                b = r.Body;
            }
        }
        Assert.Equal(0, Allocations.PerRound(Walk, Walk));
    }
}
