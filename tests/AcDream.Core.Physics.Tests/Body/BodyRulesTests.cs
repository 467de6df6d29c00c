using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>Smaller retail body rules: sledding friction, kill_velocity, and spin.</summary>
public class BodyRulesTests
{
    private static MoverState OnPlane(Vector3 normal) => new()
    {
        Position = TestGeometry.At(100, 100, 0),
        Contact = true,
        OnWalkable = true,
        ContactPlane = new Plane(normal, 0f),
        ContactPlaneCellId = TestGeometry.At(100, 100, 0).CellId,
    };

    /// <summary>
    /// calc_friction for a sledding body (CPhysicsObj.c:560-575), one 0.5 s quantum, body friction 0.95,
    /// velocity along the plane: below 1.25 m/s friction is 1 (stops dead); from 2.5 m/s on a slope steeper
    /// than 10° (normal z 0.9 &lt; cos 10° = 0.985) it is 0.2, keeping 0.8^0.5 = 0.894427; on level ground the
    /// body's 0.95 applies, keeping 0.05^0.5 = 0.223607; between 1.25 and 2.5 m/s too.
    /// </summary>
    [Theory]
    [InlineData(1.0f, 1.0f, 0f)]
    [InlineData(3.0f, 0.9f, 0.894427f)]
    [InlineData(3.0f, 1.0f, 0.223607f)]
    [InlineData(2.0f, 0.9f, 0.223607f)]
    public void SleddingFriction_FollowsTheDecompile(float speed, float normalZ, float kept)
    {
        var normal = new Vector3(MathF.Sqrt(1 - normalZ * normalZ), 0, normalZ);
        var along = Vector3.Normalize(new Vector3(-normal.Z, 0, normal.X)) * speed; // in the plane
        var v = along;
        BodyMotion.ApplyFriction(ref v, 0.5f, v.LengthSquared(), OnPlane(normal), PhysicsState.Gravity | PhysicsState.Sledding, 0.95f);
        Assert.Equal(speed * kept, v.Length(), 4);
    }

    /// <summary>
    /// A grounded body pushed at 3 m/s (no friction) into the door's slab: the blocked transition falls back
    /// on its last known contact plane and retail kills the velocity (OBJECTINFO::kill_velocity); on walkable
    /// ground before and after there is no bounce, so the velocity is exactly zero from that frame on.
    /// </summary>
    [Fact]
    public void ABodyBlockedOnTheGround_HasItsVelocityKilled()
    {
        var world = TestScenes.Door();
        var body = BodyState.Object(new Vector3(0, 3, 0));
        body.Friction = 0f;
        var driver = new BodyDriver(world, TestScenes.SeedPlayer(), MoverState.OnFloor(TestGeometry.At(100, 99, 0), 0f), body);
        var killed = driver.RunUntil(1.0 / 30, Vector3.Zero, s => s.Result.Move.VelocityKilled, maxSeconds: 2);
        Assert.Equal(Vector3.Zero, killed.Velocity);
        Assert.True(driver.Samples.Take(driver.Samples.Count - 1).All(s => s.Velocity == new Vector3(0, 3, 0)));
        Assert.True(killed.Origin.Y <= TestScenes.DoorOrigin.Y + TestScenes.SlabFront - TestScenes.PlayerRadius + PhysicsConstants.Epsilon);
    }

    /// <summary>
    /// Omega turns the body by omega × quantum each quantum (Frame::grotate): π/2 rad/s about Z for 1 s of
    /// 1/30 s frames in the air turns a body facing north a quarter turn (quaternion (0, 0, sin 45°, cos 45°));
    /// standing on walkable ground, calc_acceleration zeroes the spin after its first quantum.
    /// </summary>
    [Fact]
    public void Omega_TurnsAnAirborneBody_AndStopsOnTheGround()
    {
        var world = TestGeometry.FlatWorld();
        var mover = new MoverDescription(0x50000006, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.None);
        var body = BodyState.Object(Vector3.Zero);
        body.Omega = new Vector3(0, 0, MathF.PI / 2);
        var air = new BodyDriver(world, mover, MoverState.Airborne(TestGeometry.At(100, 100, 5)), body);
        for (int i = 0; i < 30; i++)
            air.Step(1.0 / 30, Vector3.Zero);
        var q = air.State.Position.Frame.Orientation;
        Assert.Equal(MathF.Sin(MathF.PI / 4), q.Z, 3);
        Assert.Equal(MathF.Cos(MathF.PI / 4), q.W, 3);

        var ground = new BodyDriver(world, MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f), body);
        ground.Step(1.0 / 30, new Vector3(1, 0, 0));
        Assert.Equal(Vector3.Zero, ground.Body.Omega);
    }

    /// <summary>
    /// handle_all_collisions (CPhysicsObj.c:6227): a transition that counted two stationary-fall frames stops the
    /// body whatever its velocity, and the counter (1 or 2) is carried; at 1 frame an airborne body hitting a
    /// floor (normal +z) with elasticity 0.5 bounces: v_z = -4 + 4 × 1.5 = +2 m/s.
    /// </summary>
    [Fact]
    public void StationaryFall_TwoFramesStopTheBody_OneFrameBounces()
    {
        var v = new Vector3(1f, 0f, -4f);
        int carried = BodyMotion.HandleCollisions(ref v, PhysicsState.Gravity, 0.5f, false, false, true, Vector3.UnitZ, 2, 0);
        Assert.Equal(Vector3.Zero, v);
        Assert.Equal(2, carried);

        v = new Vector3(1f, 0f, -4f);
        carried = BodyMotion.HandleCollisions(ref v, PhysicsState.Gravity, 0.5f, false, false, true, Vector3.UnitZ, 1, 0);
        Assert.Equal(new Vector3(1f, 0f, 2f), v);
        Assert.Equal(1, carried);
    }

    /// <summary>
    /// get_leave_ground_velocity (CMotionInterp.c:530): with no desired motion and no jump (all below EPSILON) the
    /// body keeps its velocity (walking off a ledge while sliding keeps the slide); otherwise the desired motion
    /// with the jump speed replaces it.
    /// </summary>
    [Fact]
    public void LeaveGroundVelocity_WithoutMotion_KeepsTheCurrentVelocity()
    {
        var current = new Vector3(0.7f, -0.3f, 0.1f);
        Assert.Equal(current, BodyMotion.LeaveGroundVelocity(current, Vector3.Zero, 0f));
        Assert.Equal(new Vector3(2f, 0f, 3f), BodyMotion.LeaveGroundVelocity(current, new Vector3(2f, 0f, 0f), 3f));
    }

    /// <summary>
    /// Leaving the ground into a wall within one quantum (CPhysicsObj::SetPositionInternal): set_on_walkable(0)
    /// calls LeaveGround first, which sets the velocity to the run, and handle_all_collisions then reflects that
    /// velocity off the wall. The runner (no EdgeSlide, step-down 1.5 m) stands at rest on a 2 m block whose edge
    /// is at y = 106, with a 4 m wall 1.5 m beyond it (face at y = 107.5), and runs at 7.5 m/s for one 0.2 s
    /// quantum (MaxQuantum, stepped whole): the target, 1.5 m on at y = 107.1, lies past the edge and 0.08 m into
    /// the wall (its spheres, radius 0.48, touch the face at y = 107.02). The runner's sphere still rests on the
    /// edge while its centre is less than its radius beyond it (y &lt; 106.48), so it leaves the ground between
    /// 106.48 and the wall. The quantum starts at rest on walkable ground, so no acceleration or friction enters:
    /// the velocity is the run (0, 7.5, 0) reflected off the wall's normal (0, −1, 0) keeping the elasticity 0.05:
    /// v_y = 7.5 − 7.5 × 1.05 = −0.375 m/s, v_x = v_z = 0. Setting the run after the reflection would leave
    /// (0, 7.5, 0), pressing into the wall.
    /// </summary>
    [Fact]
    public void LeavingTheGroundIntoAWall_ReflectsTheRunVelocity()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0030, new Vector3(98, 102, 0), new Vector3(102, 106, 2));
        BodyDriver.AddBox(world, 0x7000_0031, new Vector3(98, 107.5f, 0), new Vector3(102, 108.5f, 4));
        var driver = new BodyDriver(world, BodyDriver.Runner(1.5f), MoverState.OnFloor(TestGeometry.At(100, 105.6f, 2f), 2f),
            BodyState.Creature());

        var step = driver.Step(0.2, new Vector3(0, 7.5f, 0));

        Assert.Equal(1, step.Quanta);
        Assert.False(driver.State.OnWalkable, $"the runner should have left the ground, at {driver.Origin}");
        Assert.True(step.Move.CollisionNormalValid, "the runner should have met the wall");
        Assert.Equal(-1f, step.Move.CollisionNormal.Y, 5);
        Assert.InRange(driver.Origin.Y, 106.48f, 107.02f + PhysicsConstants.Epsilon);
        Assert.Equal(0f, driver.Body.Velocity.X);
        Assert.Equal(-0.375f, driver.Body.Velocity.Y, 5);
        Assert.Equal(0f, driver.Body.Velocity.Z);
    }

    /// <summary>
    /// handle_all_collisions (CPhysicsObj.c:6227): an Inelastic body that hits something stops dead. A ball (one
    /// sphere, radius 0.3 m) flying at 3 m/s north, 1.5 m up, its front 0.05 m short of a wall's face (y = 101):
    /// within the first 1/30 s quantum (0.1 m) it hits the wall, and its whole velocity, gravity's −9.8/30 m/s
    /// included, is zeroed. An elastic body would keep (0, 3 − 3 × 1.05, −0.3267) = (0, −0.15, −0.3267).
    /// </summary>
    [Fact]
    public void AnInelasticBody_StopsDeadOnAWall()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0031, new Vector3(90, 101, 0), new Vector3(110, 102, 3));
        var ball = new MoverDescription(0x50000007, [new AcDream.Core.Physics.Sphere(Vector3.Zero, 0.3f)], 0f, 0f, PhysicsState.Gravity | PhysicsState.Inelastic);
        var driver = new BodyDriver(world, ball, MoverState.Airborne(TestGeometry.At(100, 100.65f, 1.5f)), BodyState.Object(new Vector3(0, 3, 0)));

        var step = driver.Step(1.0 / 30, Vector3.Zero);

        Assert.True(step.Move.CollisionNormalValid, "the ball should have hit the wall");
        Assert.Equal(-1f, step.Move.CollisionNormal.Y, 5);
        Assert.Equal(Vector3.Zero, driver.Body.Velocity);
    }

    /// <summary>
    /// handle_all_collisions bounces a body that stays on walkable ground only when it is sledding. A sledding
    /// body (the player's spheres, no friction) on flat ground slides at (2, 2, 0) m/s at a wall whose face is
    /// 0.05 m ahead (y = 101): in one 1/30 s quantum it meets the wall and slides along it. Friction 0 keeps the
    /// velocity; a sledding body on the ground is not held by calc_acceleration, so gravity adds −9.8/30 =
    /// −0.32667 m/s; the wall's normal (0, −1, 0) then reflects the 2 m/s into it keeping 0.05:
    /// v = (2, 2 − 2 × 1.05, −0.32667) = (2, −0.1, −0.32667).
    /// </summary>
    [Fact]
    public void ASleddingBodyOnTheGround_BouncesOffAWall()
    {
        var world = TestGeometry.FlatWorld();
        BodyDriver.AddBox(world, 0x7000_0031, new Vector3(90, 101, 0), new Vector3(110, 102, 3));
        var sled = new MoverDescription(0x50000008, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.Gravity | PhysicsState.Sledding);
        var body = BodyState.Object(new Vector3(2, 2, 0));
        body.Friction = 0f;
        var driver = new BodyDriver(world, sled, MoverState.OnFloor(TestGeometry.At(100, 100.47f, 0), 0f), body);

        var step = driver.Step(1.0 / 30, Vector3.Zero);

        Assert.True(driver.State.OnWalkable, "the sled stays on the ground");
        Assert.True(step.Move.CollisionNormalValid, "the sled should have met the wall");
        Assert.Equal(-1f, step.Move.CollisionNormal.Y, 5);
        Assert.Equal(2f, driver.Body.Velocity.X, 5);
        Assert.Equal(-0.1f, driver.Body.Velocity.Y, 5);
        Assert.Equal(-9.8f / 30f, driver.Body.Velocity.Z, 5);
    }
}
