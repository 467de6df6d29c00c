using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// Missiles (retail MISSILE_PS objects: CPhysicsObj::get_object_info → PATH_CLIPPED, OBJECTINFO::init → no
/// step-down, OBJECTINFO::missile_ignore, handle_all_collisions → report once), one test per bug AC servers
/// report. Flat land at z = 0; every expected number is worked out from the launch in the comments.
/// </summary>
public class MissileTests
{
    private const uint ArcherId = 0x7200_0001, TargetId = 0x7200_0002, BystanderId = 0x7200_0003, GhostId = 0x7200_0004,
        OtherMissileId = 0x7200_0005, PostId = 0x7200_0006, WallId = 0x7200_0007, ArrowId = 0x7200_00A0;
    private const float CreatureRadius = 0.35f, CreatureHeight = 1.8f;

    private static PhysicsSetup Creature() => new() { CylSpheres = [new CylSphere(Vector3.Zero, CreatureRadius, CreatureHeight)] };

    private static void AddCreature(PhysicsWorld world, uint id, float x, float y) =>
        world.Objects.Register(id, Creature(), TestGeometry.At(x, y, 0), 1f, PhysicsState.None, ShadowFlags.IsCreature | ShadowFlags.HasWeenie);

    /// <summary>A static wall (environment), a box from <paramref name="min"/> to <paramref name="max"/> placed at the origin of (100, 100, 0).</summary>
    private static void AddWall(PhysicsWorld world, Vector3 min, Vector3 max)
    {
        var model = new PhysicsModel(TestGeometry.BoxTree(min, max), name: "wall");
        world.Objects.Register(WallId, new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] }, TestGeometry.At(100, 100, 0), 1f, PhysicsState.Static);
    }

    /// <summary>The archer at (100, 90) and its target, a creature 10 m north at (100, 100).</summary>
    private static PhysicsWorld Range()
    {
        var world = TestGeometry.FlatWorld();
        AddCreature(world, ArcherId, 100, 90);
        AddCreature(world, TargetId, 100, 100);
        return world;
    }

    private sealed record Flight(List<MissileHit> Hits, int StepsRun);

    /// <summary>Steps <paramref name="missile"/> at <paramref name="hz"/> for <paramref name="seconds"/>, collecting every reported hit.</summary>
    private static Flight Fly(PhysicsWorld world, Missile missile, double hz, double seconds)
    {
        var engine = new PhysicsEngine(world);
        var hits = new List<MissileHit>();
        int steps = (int)Math.Round(seconds * hz);
        for (int i = 0; i < steps; i++)
        {
            var r = engine.Step(missile, 1.0 / hz);
            if (r.Hit.Kind != MissileHitKind.None)
                hits.Add(r.Hit);
        }
        return new Flight(hits, steps);
    }

    /// <summary>
    /// Launched inside the archer's cylinder (0.2 m in front of its axis, radius 0.35) at 30 m/s towards a
    /// creature 10 m away: a missile with a target ignores every other creature (missile_ignore), so it passes
    /// the archer and hits the target. The target's face is at y = 99.65, so the arrow (r = 0.1) stops with its
    /// centre at most at 99.55 and at most one sub-step (one radius) short of it: 9.35 m at 30 m/s is 9.35
    /// quanta of 1/30 s, so the 10th quantum hits.
    /// </summary>
    [Fact]
    public void FromInsideTheArcher_PassesTheArcher_AndHitsItsTarget()
    {
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90.2f, 1.2f), new Vector3(0, 30, 0), TargetId, gravity: false);
        var flight = Fly(Range(), missile, 30, 1);
        var hit = Assert.Single(flight.Hits);
        Assert.Equal(MissileHitKind.Object, hit.Kind);
        Assert.Equal(TargetId, hit.ObjectId);
        Assert.Equal(10, hit.Quantum);
        Assert.InRange(hit.Position.Frame.Origin.Y, 99.55f - 0.1f, 99.55f + 1e-4f);
    }

    /// <summary>
    /// Servers place a new missile in the world before it flies (the placement transition). A missile has no
    /// step-down (OBJECTINFO::init: step_down = !MISSILE_PS), so one launched low, its sphere (r = 0.1) 2 cm above
    /// the ground at the archer's feet, stays where it was put and airborne — a plain object there is settled onto
    /// the ground (centre z = 0.1, in contact) — and its level flight reports the target 10 m away, never the
    /// ground 2 cm below it.
    /// </summary>
    [Fact]
    public void LaunchedJustAboveTheArchersFeet_IsNotSettledOnTheGround_AndHitsTheTarget()
    {
        var world = Range();
        var launch = TestGeometry.At(100, 90.5f, 0.12f);
        var description = Missile.Launch(ArrowId, 0.1f, launch, Vector3.Zero, TargetId, gravity: false).Description
            .With(stepDownHeight: MoverDescription.PlayerStepDownHeight);
        var engine = new PhysicsEngine(world);
        var plain = engine.Place(description.With(physicsState: PhysicsState.Gravity), launch);
        Assert.True(plain.Next.Contact, "control: a plain object placed there is settled onto the ground");
        Assert.Equal(0.1f, plain.Position.Frame.Origin.Z, 1e-4f);

        var placed = engine.Place(description, launch);
        Assert.True(placed.Succeeded);
        Assert.Equal(0.12f, placed.Position.Frame.Origin.Z);
        Assert.False(placed.Next.Contact);

        var missile = new Missile(description, placed.Position, new Vector3(0, 30, 0));
        var hit = Assert.Single(Fly(world, missile, 30, 1).Hits);
        Assert.Equal(MissileHitKind.Object, hit.Kind);
        Assert.Equal(TargetId, hit.ObjectId);
        Assert.Equal(0.12f, hit.Position.Frame.Origin.Z);
    }

    /// <summary>
    /// A 50 m/s arrow (r = 0.05) at a post of radius 0.05 twenty metres away, no gravity: at every frame rate
    /// the transition cuts each quantum into sub-steps of one radius (a 0.2 s quantum at 5 Hz … 1/30 s), so
    /// the arrow cannot step over the post. The post's face is at y = 99.95: the arrow's centre stops in
    /// [99.80, 99.90], one sub-step of 0.05 m short of touching at most.
    /// </summary>
    [Theory]
    [InlineData(5.0)]
    [InlineData(10.0)]
    [InlineData(30.0)]
    [InlineData(60.0)]
    [InlineData(144.0)]
    public void FiftyMetresASecond_HitsAThinPost_AtEveryFrameRate(double hz)
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(PostId, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.05f, 2f)] },
            TestGeometry.At(100, 100, 0), 1f, PhysicsState.Static);
        var missile = Missile.Launch(ArrowId, 0.05f, TestGeometry.At(100, 80, 1), new Vector3(0, 50, 0), gravity: false);
        var flight = Fly(world, missile, hz, 1);
        var hit = Assert.Single(flight.Hits);
        Assert.Equal(MissileHitKind.Environment, hit.Kind); // a static object counts as environment
        Assert.InRange(hit.Position.Frame.Origin.Y, 99.85f, 99.90f + 1e-4f);
        Assert.True(hit.NormalValid);
        Assert.True(hit.Normal.Y < -0.99f, $"normal {hit.Normal} should face the arrow (−Y)");
        Assert.True(missile.State.Position.Frame.Origin.Y < 99.95f, "the arrow ends on the near side of the post");
    }

    /// <summary>
    /// Point-blank: the arrow (r = 0.1) starts 0.05 m from a wall's face (y = 100) flying into it at 30 m/s.
    /// The first quantum's first sub-step meets the wall; the path is clipped there and the hit reported at once,
    /// with the wall's normal (0, −1, 0) and the arrow still in front of the face.
    /// </summary>
    [Fact]
    public void PointBlankIntoAWall_HitsTheWall()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 3));
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 99.85f, 1.2f), new Vector3(0, 30, 0), gravity: false);
        var hit = Assert.Single(Fly(world, missile, 30, 0.5).Hits);
        Assert.Equal(MissileHitKind.Environment, hit.Kind);
        Assert.Equal(1, hit.Quantum);
        Assert.Equal(new Vector3(0, -1, 0), hit.Normal);
        Assert.InRange(hit.Position.Frame.Origin.Y, 99.85f, 99.9f + 1e-4f);
    }

    /// <summary>
    /// An arcing shot over a 2 m wall (y = 100 … 100.3): launched from (100, 90, 1.2) at (0, 10, v) with
    /// v = (0.1 − 1.2 + 4.9 · 1.95²) / 1.95 = 8.990897 m/s, the arrow (r = 0.1) is at z = 1.2 + v − 4.9 = 5.29 over
    /// the wall at t = 1 s and its sphere reaches the ground (centre z = 0.1) at t = 1.95 s, y = 109.5, inside
    /// quantum 59 (1.9333 … 1.9667 s). Retail's integration is exact for constant gravity, so the hit is the ground
    /// beyond the wall, normal up. The terrain does not stop the sub-step that sinks into it, it lifts the sphere
    /// back onto the ground (OBJECTINFO::validate_walkable: Adjusted), so the centre ends between one quantum
    /// (0.333 m) short of y = 109.5 and one sub-step past it: 0.1 m along a path falling at 19.11 − 8.99 = 10.12 m/s
    /// while moving 10 m/s north, 0.1 · 10 / 14.23 = 0.070 m, with z = 0.1.
    /// </summary>
    [Fact]
    public void ArcingOverAWall_LandsOnTheGroundBeyond()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 2));
        float vz = (0.1f - 1.2f + 4.9f * 1.95f * 1.95f) / 1.95f;
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90, 1.2f), new Vector3(0, 10, vz));
        var hit = Assert.Single(Fly(world, missile, 30, 3).Hits);
        Assert.Equal(MissileHitKind.Environment, hit.Kind);
        Assert.Equal(0u, hit.ObjectId);
        Assert.Equal(59, hit.Quantum);
        Assert.True(hit.Normal.Z > 0.99f, $"normal {hit.Normal} should be the ground's (up)");
        Assert.InRange(hit.Position.Frame.Origin.Y, 109.5f - 0.34f, 109.5f + 0.071f);
        Assert.InRange(hit.Position.Frame.Origin.Z, 0.1f - 1e-3f, 0.1f + 1e-3f);
    }

    /// <summary>
    /// The hit is reported once: retail clears Missile, AlignPath and PathClipped at the first report
    /// (report_object_collision / report_environment_collision, state &amp;= 0xFFFFFCBF), and the object then moves
    /// as a plain body. The arrow into the wall, stepped on for 3 s (it bounces off by its elasticity 0.05, falls
    /// and lies on the ground, touching the ground and the wall again): one report, and the description has lost
    /// the three states.
    /// </summary>
    [Fact]
    public void TheHit_IsReportedExactlyOnce()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 3));
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 99, 1.2f), new Vector3(0, 30, 0));
        var flight = Fly(world, missile, 60, 3);
        Assert.Single(flight.Hits);
        Assert.False(missile.InFlight);
        Assert.Equal(missile.Hit.Quantum, flight.Hits[0].Quantum);
        Assert.Equal(PhysicsState.ReportCollisions | PhysicsState.Gravity, missile.Description.PhysicsState);
        Assert.True(missile.State.Contact, "the spent arrow has fallen onto the ground");
    }

    /// <summary>
    /// The first report clears Missile, AlignPath and PathClipped (handle_all_collisions), also between the quanta of
    /// one step: 0.5 s stepped at once (quanta of 0.2, 0.2 and 0.1 s, the hit in the first) ends where the same arrow
    /// ends stepped 0.2 s as a missile and then 0.3 s (0.2 and 0.1 s) as the plain body it has become, turned and
    /// placed bit for bit (still aligning its path, it would turn to face its fall).
    /// </summary>
    [Fact]
    public void AfterTheHit_TheRestOfTheSameStep_MovesAPlainBody()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 3));
        var engine = new PhysicsEngine(world);
        var once = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 99, 1.2f), new Vector3(0, 30, 0));
        var split = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 99, 1.2f), new Vector3(0, 30, 0));

        var whole = engine.Step(once, 0.5);
        engine.Step(split, 0.2);
        Assert.False(split.InFlight);
        var rest = engine.Step(split.Description, split.State, split.Body, 0.3, Vector3.Zero);

        Assert.Equal(MissileHitKind.Environment, whole.Hit.Kind); // the wall is static
        Assert.Equal(1, whole.Hit.Quantum);
        Assert.Equal(3, whole.Step.Quanta);
        Assert.Equal(2, rest.Quanta);
        Assert.True(Position.SameBits(rest.Next.Position, once.State.Position), $"{once.State.Position} {once.State.Position.Frame.Orientation}, as a plain body {rest.Next.Position} {rest.Next.Position.Frame.Orientation}");
    }

    /// <summary>
    /// missile_ignore (CObjectInfo.c:314069): between the archer and its target stand a creature that is not the
    /// target, an ethereal weenie object and another missile; the arrow passes all three and hits the target.
    /// </summary>
    [Fact]
    public void MissileIgnoreObjects_ArePassed()
    {
        var world = Range();
        AddCreature(world, BystanderId, 100, 94);
        var ball = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, 1.2f), 0.5f)] };
        world.Objects.Register(GhostId, ball, TestGeometry.At(100, 96, 0), 1f, PhysicsState.Ethereal, ShadowFlags.HasWeenie);
        world.Objects.Register(OtherMissileId, ball, TestGeometry.At(100, 98, 0), 1f, PhysicsState.Missile, ShadowFlags.HasWeenie);
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90.5f, 1.2f), new Vector3(0, 30, 0), TargetId, gravity: false);
        var hit = Assert.Single(Fly(world, missile, 30, 1).Hits);
        Assert.Equal(MissileHitKind.Object, hit.Kind);
        Assert.Equal(TargetId, hit.ObjectId);
    }

    /// <summary>Without a target a missile ignores only ethereal weenie objects and missiles: a creature in its way is hit (retail missile_ignore needs targetID for creatures).</summary>
    [Fact]
    public void WithoutATarget_ACreatureInTheWayIsHit()
    {
        var world = Range();
        AddCreature(world, BystanderId, 100, 94);
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90.5f, 1.2f), new Vector3(0, 30, 0), targetId: 0, gravity: false);
        var hit = Assert.Single(Fly(world, missile, 30, 1).Hits);
        Assert.Equal(BystanderId, hit.ObjectId);
    }

    /// <summary>
    /// A target that is not in the world (or the missile itself) is no error: retail's missile_ignore compares ids only,
    /// so every creature is passed and the level arrow (z = 1.2, no gravity) flies on over the range, hitting nothing.
    /// </summary>
    [Theory]
    [InlineData(0xDEAD_BEEFu)]
    [InlineData(ArrowId)]
    public void AnUnknownOrSelfTarget_PassesEveryCreature(uint target)
    {
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90.5f, 1.2f), new Vector3(0, 30, 0), target, gravity: false);
        Assert.Empty(Fly(Range(), missile, 30, 1).Hits);
        Assert.True(missile.InFlight);
        Assert.Equal(120.5f, missile.State.Position.Frame.Origin.Y, 0.01f);
    }

    /// <summary>get_object_info turns MISSILE_PS into PATH_CLIPPED for any move, also through Resolve: the missile stops at the wall instead of sliding along it.</summary>
    [Fact]
    public void AMissileMover_IsPathClipped_InResolveToo()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 3));
        var description = new MoverDescription(ArrowId, [new Sphere(Vector3.Zero, 0.1f)], 0, 0, PhysicsState.Missile);
        var engine = new PhysicsEngine(world);
        // 1 m north-east into the wall from 0.5 m in front of it: a slider would end ~0.5 m east; clipped, it stops at the wall.
        var r = engine.Resolve(description, MoverState.Airborne(TestGeometry.At(100, 99.5f, 1.2f)), TestGeometry.At(100.7071f, 100.2071f, 1.2f));
        Assert.True(r.CollisionNormalValid);
        Assert.InRange(r.Position.Frame.Origin.X, 100.3f, 100.45f);
    }

    [Fact]
    public void Stepping_AllocatesNothingOnceWarm()
    {
        var world = TestGeometry.FlatWorld();
        AddWall(world, new Vector3(-5, 0, 0), new Vector3(5, 0.3f, 3));
        var engine = new PhysicsEngine(world);
        void Volley()
        {
            var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 95, 1.2f), new Vector3(0, 20, 2));
            for (int i = 0; i < 60; i++)
                engine.Step(missile, 1.0 / 60);
        }
        var warm = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 95, 1.2f), new Vector3(0, 20, 2));
        void Steps()
        {
            for (int i = 0; i < 60; i++)
                engine.Step(warm, 1.0 / 60);
        }
        Assert.Equal(0, Allocations.PerRound(() => { Volley(); Volley(); }, Steps));
    }

    [Fact]
    public void SameLaunch_SameBits()
    {
        (Vector3, MissileHit) Run()
        {
            var world = Range();
            var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90.5f, 1.2f), new Vector3(0.3f, 25, 3), TargetId);
            var flight = Fly(world, missile, 60, 1);
            return (missile.State.Position.Frame.Origin, flight.Hits.Single());
        }
        var (a, hitA) = Run();
        var (b, hitB) = Run();
        Assert.Equal(a, b);
        Assert.Equal(hitA.Position.Frame.Origin, hitB.Position.Frame.Origin);
        Assert.Equal(hitA.Quantum, hitB.Quantum);
    }

    [Theory]
    [InlineData(float.NaN, 0f, 0f, "missile.velocity")]
    [InlineData(0f, float.PositiveInfinity, 0f, "missile.velocity")]
    [InlineData(0f, 0f, 5000f, "missile.velocity")]
    public void BadVelocity_IsRefused_NamingTheField(float x, float y, float z, string field)
    {
        var ex = Assert.Throws<ArgumentException>(() => Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90, 1), new Vector3(x, y, z)));
        Assert.StartsWith(field + ":", ex.Message);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(-0.1f)]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    public void BadRadius_IsRefused_NamingTheField(float radius)
    {
        var ex = Assert.Throws<ArgumentException>(() => Missile.Launch(ArrowId, radius, TestGeometry.At(100, 90, 1), Vector3.UnitY));
        Assert.StartsWith("missile.radius:", ex.Message);
    }

    [Fact]
    public void ADescriptionWithoutTheMissileState_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => new Missile(MoverDescription.Player(), TestGeometry.At(100, 90, 1), Vector3.UnitY));
        Assert.StartsWith("missile.description.physicsState:", ex.Message);
    }

    [Fact]
    public void ALaunchWithABadFrame_IsRefused_NamingTheField()
    {
        var start = TestGeometry.At(100, 90, 1);
        start.Frame.Origin.X = float.NaN;
        var ex = Assert.Throws<ArgumentException>(() => Missile.Launch(ArrowId, 0.1f, start, Vector3.UnitY));
        Assert.StartsWith("missile.start", ex.Message);
    }

    [Fact]
    public void BadTimeOrAnUnknownCell_IsRefused_AndTheMissileIsUnchanged()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var missile = Missile.Launch(ArrowId, 0.1f, TestGeometry.At(100, 90, 1), Vector3.UnitY);
        var before = missile.State.Position;
        Assert.StartsWith("elapsed:", Assert.Throws<ArgumentException>(() => engine.Step(missile, double.NaN)).Message);
        var lost = Missile.Launch(ArrowId, 0.1f, new Position(0x1234_0001, new Vector3(10, 10, 1)), Vector3.UnitY);
        Assert.StartsWith("state.position.cell", Assert.Throws<ArgumentException>(() => engine.Step(lost, 0.1)).Message);
        Assert.Equal(before, missile.State.Position);
        Assert.True(missile.InFlight);
        Assert.Equal(0, missile.Quanta);
    }
}
