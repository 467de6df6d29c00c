using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// Retail body motion through <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>: falls, jumps, landings, friction, bounces and
/// the quantum rules, each pinned to a number worked out by hand in its comment (g = 9.8 m/s²).
/// </summary>
public class BodyMotionTests
{
    private const double Hz30 = 1.0 / 30.0;
    private const float G = 9.8f;

    /// <summary>A flat floor at z = 0 with a static box of the given height spanning x 98..102, y 102..106.</summary>
    private static PhysicsWorld Block(float height)
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0030, new Vector3(98, 102, 0), new Vector3(102, 106, height));
        return world;
    }

    /// <summary>
    /// Running at 4 m/s off a 2 m ledge (the runner has no EdgeSlide and steps down 1.5 m, less than the drop).
    /// Leaving the ground sets the velocity to the run (CMotionInterp::LeaveGround), so the fall is ballistic:
    /// from rest vertically, t = √(2h/g) = √(4 / 9.8) = 0.6389 s, and it covers 4 × 0.6389 = 2.556 m forward.
    /// Quanta end on whole frames, so both may be late by one quantum (1/30 s, 0.133 m).
    /// </summary>
    [Fact]
    public void WalkingOffA2mLedge_LandsAfterTheFallTime_AtTheBallisticDistance()
    {
        var (leave, land) = RunOffLedge(30);
        double fall = Math.Sqrt(2 * 2.0 / G); // 0.6389 s
        Assert.InRange(land.Time - leave.Time, fall - 1e-6, fall + Hz30 + 1e-6);
        float ahead = land.Origin.Y - leave.Origin.Y;
        Assert.InRange(ahead, 4f * (float)fall - 1e-3f, 4f * (float)(fall + Hz30) + 1e-3f);
        Assert.InRange(land.Origin.Z, 0f, 0.01f); // standing on the floor: the sphere's foot (0.475 − 0.48) touches z = 0
        Assert.True(land.OnWalkable);
        Assert.Equal(2.005f, leave.Origin.Z, 3); // still at the ledge's height on the frame it loses contact
    }

    /// <summary>
    /// The same run off the ledge at 10, 30, 60 and 144 frames a second. Retail ticks no faster than 30 Hz
    /// (CPhysics::UseTime) and steps a 10 Hz frame whole, so the quanta are 0.1, 1/30, 1/30 and 5/144 s; the
    /// landing spots may differ by the run's travel in the longest quantum, 4 m/s × 0.1 s = 0.4 m, and the
    /// landing times by 0.1 s.
    /// </summary>
    [Fact]
    public void FrameRateIndependence_LandingsAt10_30_60_144Hz_AgreeWithinOneQuantum()
    {
        var landings = new[] { 10, 30, 60, 144 }.Select(hz => (Hz: hz, Land: RunOffLedge(hz).Land)).ToArray();
        foreach (var a in landings)
            foreach (var b in landings)
            {
                Assert.True(MathF.Abs(a.Land.Origin.Y - b.Land.Origin.Y) <= 0.4f + 1e-3f,
                    $"{a.Hz} Hz lands at y = {a.Land.Origin.Y}, {b.Hz} Hz at y = {b.Land.Origin.Y}");
                Assert.True(Math.Abs(a.Land.Time - b.Land.Time) <= 0.1 + 1e-6,
                    $"{a.Hz} Hz lands at t = {a.Land.Time}, {b.Hz} Hz at t = {b.Land.Time}");
                Assert.InRange(a.Land.Origin.Z, 0f, 0.01f);
            }
    }

    private static (BodyDriver.Sample Leave, BodyDriver.Sample Land) RunOffLedge(int hz)
    {
        var world = Block(2f);
        var start = MoverState.OnFloor(TestGeometry.At(100, 104, 2f), 2f);
        var body = new BodyDriver(world, BodyDriver.Runner(1.5f), start, BodyState.Creature());
        var run = new Vector3(0, 4, 0);
        var leave = body.RunUntil(1.0 / hz, run, s => !s.Contact);
        var land = body.RunUntil(1.0 / hz, run, s => s.Contact);
        return (leave, land);
    }

    /// <summary>
    /// A standing jump forward onto a 0.5 m block and a jump off its far side. The runner starts 1 m short of
    /// the block at 2 m/s and jumps at 4 m/s: its foot (origin − 0.005) is over the block's top (0.5 m) from
    /// 4t − 4.9t² = 0.505, t = (4 − √(16 − 9.898)) / 9.8 = 0.158 s, long before its sphere reaches the block's
    /// face at t = (1 − 0.48) / 2 = 0.26 s; it comes down onto the top at 4t − 4.9t² = 0.505 on the way down,
    /// t = (4 + 2.4702) / 9.8 = 0.6602 s, 2 × 0.66 = 1.32 m on (y = 102.32, on the block). Jumping again from
    /// the top it lands on the floor when 4t − 4.9t² = −0.5, t = (4 + √(16 + 9.8)) / 9.8 = 0.9265 s, having
    /// covered exactly 2 m/s × its flight (the jump sets the velocity; CMotionInterp::LeaveGround).
    /// Landings are late by at most one quantum (1/30 s).
    /// </summary>
    [Fact]
    public void JumpOntoAndOffA0_5mBlock_LandsAtTheBallisticTimes()
    {
        var world = Block(0.5f);
        var start = MoverState.OnFloor(TestGeometry.At(100, 101, 0), 0f);
        var body = new BodyDriver(world, BodyDriver.Runner(0.04f), start, BodyState.Creature());
        var run = new Vector3(0, 2, 0);

        var takeOff = body.Step(Hz30, run, jump: 4f);
        Assert.True(takeOff.Jumped);
        var onTop = body.RunUntil(Hz30, run, s => s.Contact);
        double up = (4 + Math.Sqrt(16 - 2 * G * 0.505)) / G; // 0.6602 s
        Assert.InRange(onTop.Time - Hz30, up - Hz30 - 1e-6, up + 1e-6); // the jump's frame counts from its start
        Assert.InRange(onTop.Origin.Z, 0.5f, 0.51f);
        Assert.InRange(onTop.Origin.Y, 102.0f, 102.5f);
        Assert.True(onTop.OnWalkable);

        // Walk on to 105 m (on the block), then jump off the far side.
        body.RunUntil(Hz30, run, s => s.Origin.Y >= 105f);
        Assert.True(body.State.Contact && body.State.OnWalkable);
        double jumpTime = body.Time;
        float jumpY = body.Origin.Y;
        Assert.True(body.Step(Hz30, run, jump: 4f).Jumped);
        var down = body.RunUntil(Hz30, run, s => s.Contact);
        double flight = (4 + Math.Sqrt(16 + 2 * G * 0.5)) / G; // 0.9265 s
        Assert.InRange(down.Time - jumpTime, flight - 1e-6, flight + Hz30 + 1e-6);
        Assert.InRange(down.Origin.Z, 0f, 0.01f);
        Assert.Equal(2f * (float)(down.Time - jumpTime), down.Origin.Y - jumpY, 2);
    }

    /// <summary>
    /// A player let go at rest 2 m above the floor in front of the door, over its foot cylinder (door space
    /// (0, 0.12), radius 0.5, top at 0.2 m). The door has a physics BSP, so retail never tests that cylinder:
    /// the player falls past it to the floor. Retail integrates no offset while the velocity is zero, so the
    /// fall starts one quantum late: after n quanta it has fallen ½·g·q²·(n² − 1); the foot (origin − 0.005)
    /// reaches the floor when that passes 1.995 m, n² − 1 ≥ 1.995 × 2 × 900 / 9.8 = 366.4, n = 20:
    /// 0.667 s, within one quantum of √(2h/g) = 0.638 s.
    /// </summary>
    [Fact]
    public void FallOntoTheDoorsFoot_PassesTheFootCylinder_AndLandsOnTheFloor()
    {
        var world = TestScenes.Door();
        var start = MoverState.Airborne(TestGeometry.At(100, 99.45f, 2f));
        var body = new BodyDriver(world, MoverDescription.Player(), start, BodyState.Creature());
        var land = body.RunUntil(Hz30, Vector3.Zero, s => s.Contact);
        Assert.Equal(20, body.Samples.Count);
        Assert.InRange(land.Time - Math.Sqrt(2 * 1.995 / G), 0, Hz30);
        Assert.InRange(land.Origin.Z, 0f, 0.01f); // the floor, not the cylinder's top at 0.2 m
        Assert.Equal(99.45f, land.Origin.Y, 4);
        Assert.All(body.Samples, s => Assert.Empty(s.Collided));
    }

    /// <summary>
    /// A body sliding at 5 m/s on flat ground with retail's friction 0.95 and no motion of its own: each 1/30 s
    /// quantum scales the speed by 0.05^(1/30) = 0.904963 (calc_friction: (1 − friction)^quantum) and moves
    /// the body by the new speed × 1/30. After 30 quanta (1 s) the speed is 5 × 0.05 = 0.25 m/s; the 31st
    /// quantum finds |v|² − 0.25² below EPSILON and stops it dead. The distance is
    /// 5/30 × Σ(k = 1..30) r^k = 5/30 × r(1 − r³⁰)/(1 − r) = 5/30 × 0.859715 / 0.095037 = 1.5077 m.
    /// </summary>
    [Fact]
    public void SlidingOnFlatGround_FrictionStopsItAfterOneSecond_At1_508m()
    {
        var world = TestGeometry.FlatWorld();
        var start = MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f);
        var body = new BodyDriver(world, MoverDescription.Player(), start, BodyState.Object(new Vector3(5, 0, 0)));
        for (int i = 0; i < 30; i++)
            body.Step(Hz30, Vector3.Zero);
        Assert.Equal(0.25f, body.Body.Velocity.X, 4);
        body.Step(Hz30, Vector3.Zero);
        Assert.Equal(Vector3.Zero, body.Body.Velocity);
        Assert.Equal(101.5077f, body.Origin.X, 3);
        body.Step(Hz30, Vector3.Zero);
        Assert.Equal(101.5077f, body.Origin.X, 3);
        Assert.All(body.Samples, s => Assert.True(s.Contact && s.OnWalkable));
    }

    /// <summary>
    /// A weightless body (no Gravity) flying at (1, 4, 0) m/s into a wall whose face is the plane y = 102,
    /// with elasticity 0.5 (above retail's setter cap of 0.1, written directly): handle_all_collisions adds
    /// −(v·n)(1 + e)·n = 4 × 1.5 × (0, −1, 0) to the velocity, leaving (1, −2, 0): half the speed into the wall,
    /// reflected, and the speed along it kept.
    /// </summary>
    [Fact]
    public void BounceOffAWall_WithElasticityHalf_KeepsHalfTheNormalSpeed()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0031, new Vector3(90, 102, 0), new Vector3(110, 103, 5));
        var mover = new MoverDescription(0x50000006, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.None);
        var state = BodyState.Object(new Vector3(1, 4, 0));
        state.Elasticity = 0.5f;
        var body = new BodyDriver(world, mover, MoverState.Airborne(TestGeometry.At(100, 100, 1)), state);
        var hit = body.RunUntil(Hz30, Vector3.Zero, s => s.Result.Move.CollisionNormalValid);
        Assert.Equal(new Vector3(0, -1, 0), hit.Result.Move.CollisionNormal);
        Assert.Equal(1f, hit.Velocity.X, 5);
        Assert.Equal(-2f, hit.Velocity.Y, 5);
        Assert.Equal(0f, hit.Velocity.Z, 5);
        // Stopped at its last free position short of the face (a blocked transition keeps the last good sub-step).
        Assert.InRange(hit.Origin.Y, 102f - 0.48f - 4f / 30f, 102f - 0.48f + PhysicsConstants.Epsilon);
        body.Step(Hz30, Vector3.Zero);
        Assert.Equal(hit.Origin.Y - 2f / 30f, body.Origin.Y, 4); // flying back at 2 m/s
    }

    /// <summary>Retail's setter (CPhysicsObj::set_elasticity) caps elasticity at 0.1 and floors it at 0.</summary>
    [Theory]
    [InlineData(0.5f, 0.1f)]
    [InlineData(0.07f, 0.07f)]
    [InlineData(-1f, 0f)]
    public void SetElasticity_ClampsAsRetail(float given, float stored)
    {
        var body = BodyState.Creature();
        body.SetElasticity(given);
        Assert.Equal(stored, body.Elasticity);
    }

    /// <summary>
    /// A weightless body at 80 m/s: UpdatePhysicsInternal rescales the velocity to 50 m/s before moving, so a
    /// 1/30 s quantum moves it 50/30 = 1.6667 m, not 2.667 m, and its velocity stays (0, 50, 0).
    /// </summary>
    [Fact]
    public void MaximumSpeed_IsClampedTo50()
    {
        var world = TestGeometry.FlatWorld();
        var mover = new MoverDescription(0x50000006, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.None);
        var body = new BodyDriver(world, mover, MoverState.Airborne(TestGeometry.At(100, 100, 5)), BodyState.Object(new Vector3(0, 80, 0)));
        body.Step(Hz30, Vector3.Zero);
        Assert.Equal(100f + 50f / 30f, body.Origin.Y, 4);
        Assert.Equal(50f, body.Body.Velocity.Y, 4);
    }

    /// <summary>update_object drops an elapsed time over the huge quantum (2 s): nothing moves, nothing is carried.</summary>
    [Fact]
    public void AFrameLongerThanTheHugeQuantum_DoesNothing()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var state = MoverState.Airborne(TestGeometry.At(100, 100, 5));
        var body = BodyState.Object(new Vector3(0, 3, 0));
        var r = engine.Step(MoverDescription.Player(), state, body, 2.5, Vector3.Zero);
        Assert.Equal(0, r.Quanta);
        Assert.Equal(state.Position.Origin, r.Next.Position.Origin);
        Assert.Equal(body.Velocity, r.Body.Velocity);
        Assert.Equal(0.0, r.Body.PendingTime);
        // Exactly 2 s is not dropped: ten max quanta of 0.2 s.
        Assert.Equal(10, engine.Step(MoverDescription.Player(), state, body, 2.0, Vector3.Zero).Quanta);
    }

    /// <summary>
    /// The quantum rules: under 1/30 s gathered nothing runs (CPhysics::UseTime) and the time is carried; up to
    /// 0.2 s runs as one quantum; longer runs 0.2 s quanta, then the rest if it is over 1/30 s, else carries it.
    /// A body moving at 3 m/s with no gravity shows each quantum's length in its travel.
    /// </summary>
    [Theory]
    [InlineData(0.02, 0, 0.02, 0.0)]      // gathered
    [InlineData(0.05, 1, 0.0, 0.15)]      // one quantum of 0.05 s
    [InlineData(0.2, 1, 0.0, 0.6)]        // one max quantum
    [InlineData(0.5, 3, 0.0, 1.5)]        // 0.2 + 0.2 + 0.1
    [InlineData(0.42, 2, 0.02, 1.2)]      // 0.2 + 0.2, 0.02 carried
    public void ElapsedTime_IsCutIntoRetailQuanta(double elapsed, int quanta, double carried, double travel)
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var mover = new MoverDescription(0x50000006, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.None);
        var state = MoverState.Airborne(TestGeometry.At(100, 100, 5));
        var r = engine.Step(mover, state, BodyState.Object(new Vector3(3, 0, 0)), elapsed, Vector3.Zero);
        Assert.Equal(quanta, r.Quanta);
        Assert.Equal(carried, r.Body.PendingTime, 6);
        Assert.Equal(100f + (float)travel, r.Next.Position.Origin.X, 4);
    }

    /// <summary>
    /// Retail quirk (UpdatePhysicsInternal integrates the offset only when |v|² &gt; 0): a body released at rest
    /// does not move in its first quantum; it only gains g × q = 9.8/30 = 0.3267 m/s downwards.
    /// </summary>
    [Fact]
    public void ABodyReleasedAtRest_DoesNotMoveInItsFirstQuantum()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var state = MoverState.Airborne(TestGeometry.At(100, 100, 5));
        var r = engine.Step(MoverDescription.Player(), state, BodyState.Creature(), Hz30, Vector3.Zero);
        Assert.Equal(1, r.Quanta);
        Assert.Equal(5f, r.Next.Position.Origin.Z);
        Assert.Equal(-9.8f / 30f, r.Body.Velocity.Z, 5);
        Assert.Equal(new Vector3(0, 0, PhysicsConstants.Gravity), r.Body.Acceleration);
    }

    /// <summary>A jump needs walkable ground under a gravity body (CMotionInterp::jump_is_allowed); in the air it is refused.</summary>
    [Fact]
    public void AJumpInTheAir_IsRefused()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var state = MoverState.Airborne(TestGeometry.At(100, 100, 5));
        var r = engine.Step(MoverDescription.Player(), state, BodyState.Creature(), Hz30, Vector3.Zero, 4f);
        Assert.False(r.Jumped);
        Assert.Equal(-9.8f / 30f, r.Body.Velocity.Z, 5);
    }

    /// <summary>A body standing still on the floor: no acceleration, no motion, no transition, and its state is unchanged.</summary>
    [Fact]
    public void ABodyAtRestOnTheFloor_StaysPut()
    {
        var world = TestGeometry.FlatWorld();
        var engine = new PhysicsEngine(world);
        var state = MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f);
        var r = engine.Step(MoverDescription.Player(), state, BodyState.Creature(), Hz30, Vector3.Zero);
        Assert.Equal(1, r.Quanta);
        Assert.Equal(state.Position.Origin, r.Next.Position.Origin);
        Assert.True(r.Next.Contact && r.Next.OnWalkable);
        Assert.Equal(Vector3.Zero, r.Body.Velocity);
        Assert.Equal(Vector3.Zero, r.Body.Acceleration);
    }

    [Fact]
    public void LeaveGroundVelocity_IsCappedAt50MetresASecond_KeepingItsDirection()
    {
        // get_leave_ground_velocity then set_velocity (CMotionInterp.c:530): (40, 0, 30) is 50 m/s exactly; (80, 0, 60) caps to it.
        var v = BodyMotion.LeaveGroundVelocity(Vector3.Zero, new Vector3(80f, 0f, 0f), 60f);
        Assert.Equal(40f, v.X, 4);
        Assert.Equal(30f, v.Z, 4);
    }

    [Fact]
    public void ABodyLandingOnWalkableGroundFromTheAir_Bounces()
    {
        // handle_all_collisions (CPhysicsObj.c:6227): not on walkable ground before, so the bounce applies on landing:
        // -10 m/s into a floor with elasticity 0.5 leaves +5 m/s.
        var v = new Vector3(0f, 0f, -10f);
        BodyMotion.HandleCollisions(ref v, PhysicsState.Gravity, 0.5f, prevOnWalkable: false, onWalkable: true,
            collisionNormalValid: true, Vector3.UnitZ, framesStationaryFall: 0, carried: 0);
        Assert.Equal(5f, v.Z, 4);
    }
}
