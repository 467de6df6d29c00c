using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// Step-up (and cylinder step-down) heights just below and just above their limits, for every kind of
/// shape: BSP object, env-cell floor, cylsphere, sphere, terrain. Each limit is derived by hand from the
/// retail rule in the comment; the heights tested sit 0.02 m either side of it.
/// </summary>
public class StepLimitTests
{
    private const uint ObstacleId = 0x7000_0030;
    private const float R = 0.5f, StepUp = 0.6f;

    /// <summary>A one-sphere walker: radius 0.5 centred 0.5 above its origin, step-up 0.6, step-down 0.8, no edge slide.</summary>
    private static MoverDescription Walker(float stepDown = 0.8f, int spheres = 1) =>
        new(0x5000_0009, spheres == 1 ? [new Sphere(new Vector3(0, 0, R), R)] : [new Sphere(new Vector3(0, 0, R), R), new Sphere(new Vector3(0, 0, 1.3f), R)],
            StepUp, stepDown, PhysicsState.Gravity, ObjectInfoState.IsPlayer);

    private static PhysicsWorld WithObstacle(PhysicsSetup setup, Vector3 at, PhysicsState state = PhysicsState.Static, float scale = 1f)
    {
        var world = TestGeometry.FlatWorld();
        world.Objects.Register(ObstacleId, setup, TestGeometry.At(at.X, at.Y, at.Z), scale, state);
        return world;
    }

    // ---- BSP object ------------------------------------------------------------------------------------
    // A box whose riser is the plane y = 102. The walker starts 0.05 m clear (centre y = 101.45) and asks
    // for one 0.3 m frame (one sub-step, 0.3 < r): the check centre y = 101.75 is 0.25 m before the riser,
    // at z = 0.5. The riser is hit first (the move enters its front); step_up probes 0.6 m down for
    // walkable ground. The top face (z = H) is hit by the check sphere while its edge (102, H) is within
    // r: 0.25² + (0.5 − H)² < 0.25, true for both heights below. adjust_sphere_to_plane then moves the
    // sphere by the probe (0, 0, −0.6) back-off: distance to the plane 0.5 − H, gap = distance − r = −H,
    // back-off = −H / −0.6, walk fraction 1 − H / 0.6, accepted down to −0.5 (retail quirk), i.e.
    // H ≤ 0.9 = 1.5 × step-up. So H = 0.88 is climbed (origin z = 0.88) and H = 0.92 is not (z stays 0 and
    // the slide along the riser, straight into it, is shorter than √EPSILON: the frame is refused).

    private static PhysicsWorld Ledge(float height)
    {
        var box = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-2, 0, 0), new Vector3(2, 4, height)), name: "ledge");
        return WithObstacle(new PhysicsSetup { Parts = [new SetupPart(box, Frame.Identity)] }, new Vector3(100, 102, 0));
    }

    [Fact]
    public void BspLedge_JustBelowOneAndAHalfStepHeights_IsClimbed()
    {
        var walker = new Mover(Ledge(0.88f), Walker(), MoverState.OnFloor(TestGeometry.At(100, 101.45f, 0), 0f));
        walker.Step(new Vector3(0, 0.3f, 0));
        Assert.InRange(walker.Origin.Z, 0.88f - 0.002f, 0.88f + 0.002f);
        Assert.InRange(walker.Origin.Y, 101.75f - 0.002f, 101.75f + 0.002f);
        Assert.True(walker.State.Contact && walker.State.OnWalkable);
    }

    [Fact]
    public void BspLedge_JustAboveOneAndAHalfStepHeights_Blocks()
    {
        var walker = new Mover(Ledge(0.92f), Walker(), MoverState.OnFloor(TestGeometry.At(100, 101.45f, 0), 0f));
        walker.Step(new Vector3(0, 0.3f, 0));
        Assert.InRange(walker.Origin.Z, -0.002f, 0.002f);
        Assert.True(walker.Origin.Y <= 101.5f + PhysicsConstants.Epsilon, $"y = {walker.Origin.Y}");
    }

    // ---- env-cell floor -------------------------------------------------------------------------------
    // The same step as the BSP ledge, but inside an env cell: the room's physics BSP holds its floor, walls
    // and a step block (riser at local y = 2, i.e. world y = 102 with the room at y = 100), and the walker
    // collides with it through the cell's own BSP (scale 1). Same numbers: 0.88 climbed, 0.92 blocked.

    private const uint RoomId = (TestGeometry.Landblock << 16) | 0x0100;

    private static PhysicsWorld RoomWithStep(float height)
    {
        Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new([a, b, c, d]);
        Vector3 P(float x, float y, float z) => new(x, y, z);
        var surfaces = new List<Polygon>
        {
            Quad(P(-4, -4, 0), P(4, -4, 0), P(4, 8, 0), P(-4, 8, 0)),      // floor
            Quad(P(-4, -4, 4), P(-4, 8, 4), P(4, 8, 4), P(4, -4, 4)),      // ceiling
            Quad(P(-4, 8, 0), P(4, 8, 0), P(4, 8, 4), P(-4, 8, 4)),        // north wall
            Quad(P(4, -4, 0), P(4, -4, 4), P(4, 8, 4), P(4, 8, 0)),        // east wall
            Quad(P(-4, -4, 0), P(-4, 8, 0), P(-4, 8, 4), P(-4, -4, 4)),    // west wall
            Quad(P(-4, -4, 0), P(-4, -4, 4), P(4, -4, 4), P(4, -4, 0)),    // south wall
        };
        surfaces.AddRange(BspShapes.BoxPolygons(P(-2, 2, 0), P(2, 6, height)).Where(p => p.Plane.Normal.Z > -0.5f)); // the step, no bottom face
        Plane[] planes = [new(Vector3.UnitY, 4f), new(-Vector3.UnitY, 8f), new(Vector3.UnitX, 4f), new(-Vector3.UnitX, 4f), new(Vector3.UnitZ, 0f), new(-Vector3.UnitZ, 4f)];
        var bounds = new Sphere(new Vector3(0, 2, 2), 10f);
        var nodes = planes.Select((p, i) => new BspNodeData { SplitPlane = p, Front = i < 5 ? i + 1 : -1, Bounds = bounds }).ToList();
        var world = TestGeometry.FlatWorld();
        world.Cells.AddEnvCell(new EnvCell(RoomId, new Frame(new Vector3(100, 100, 0)), BspCompiler.Compile(surfaces), BspTree.Create(Array.Empty<Polygon>(), nodes), []));
        return world;
    }

    private static Mover InRoom(float height) =>
        new(RoomWithStep(height), Walker(), MoverState.OnFloor(new Position(RoomId, new Frame(new Vector3(100, 101.45f, 0))), 0f));

    [Fact]
    public void EnvCellStep_JustBelowOneAndAHalfStepHeights_IsClimbed()
    {
        var walker = InRoom(0.88f);
        walker.Step(new Vector3(0, 0.3f, 0));
        Assert.InRange(walker.Origin.Z, 0.88f - 0.002f, 0.88f + 0.002f);
        Assert.Equal(RoomId, walker.State.Position.CellId);
        Assert.True(walker.State.Contact && walker.State.OnWalkable);
    }

    [Fact]
    public void EnvCellStep_JustAboveOneAndAHalfStepHeights_Blocks()
    {
        var walker = InRoom(0.92f);
        walker.Step(new Vector3(0, 0.3f, 0));
        Assert.InRange(walker.Origin.Z, -0.002f, 0.002f);
        Assert.True(walker.Origin.Y <= 101.5f + PhysicsConstants.Epsilon, $"y = {walker.Origin.Y}");
    }

    // ---- cylsphere ------------------------------------------------------------------------------------
    // CCylSphere::step_sphere_up slides when step-up < r + h − disp.z, with disp.z the sphere centre above
    // the cylinder's low point: a walker on the ground (centre 0.5, low point at 0) needs h ≤ 0.6. Below it,
    // step_up probes down 0.6 from the check position and step_sphere_down lifts the sphere by
    // h + r − disp.z = h onto the cap (walk fraction 1 − h / 0.6 ≥ −0.1): origin z = h.
    // The cylinder (radius 1 at x = 100, y = 102) is met from y = 100.45 with 0.1 m frames.

    private static PhysicsWorld Cylinder(float height, float x = 100f, float y = 102f) =>
        WithObstacle(new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 1f, height)] }, new Vector3(x, y, 0));

    [Theory]
    [InlineData(0.58f, true)]
    [InlineData(0.62f, false)]
    public void Cylinder_IsClimbed_UpToTheStepUpHeight(float height, bool climbed)
    {
        var walker = new Mover(Cylinder(height), Walker(), MoverState.OnFloor(TestGeometry.At(100, 100.45f, 0), 0f));
        walker.Walk(new Vector3(0, 0.1f, 0), 10);
        if (climbed)
        {
            Assert.InRange(walker.Origin.Z, height - 0.002f, height + 0.002f);
            Assert.True(walker.State.Contact && walker.State.OnWalkable);
        }
        else
        {
            Assert.InRange(walker.Origin.Z, -0.002f, 0.002f);
            // Blocked at the cylinder's wall: centre no closer than radius sum 1 + 0.5 − EPSILON.
            Assert.True(102f - walker.Origin.Y >= 1.5f - 2 * PhysicsConstants.Epsilon, $"y = {walker.Origin.Y}");
        }
    }

    // Cylinder step-down: the two-sphere walker (diameter 1 ≥ step-down 0.8: one probe of 0.8) stands on a
    // 1 m static box and walks onto a cylinder (radius 1 at x = 101, y = 100, touching the box's edge at
    // x = 100) whose cap is d lower. KeepGrounded probes 0.8 down; CCylSphere::step_sphere_down lifts the
    // sphere by h + r − disp.z = 0.8 − d back onto the cap (walk fraction 1 − (0.8 − d) / 0.8 = d / 0.8,
    // which must stay below 1): d = 0.78 is stepped down (origin z = 0.22), d = 0.82 is not (no edge
    // slide: the walker walks on, out of contact, at z = 1).

    [Theory]
    [InlineData(0.78f, true)]
    [InlineData(0.82f, false)]
    public void Cylinder_IsSteppedDownOnto_UpToTheStepDownHeight(float drop, bool steppedDown)
    {
        var world = TestGeometry.FlatWorld();
        var box = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-2, -2, 0), new Vector3(0, 2, 1)), name: "block");
        world.Objects.Register(ObstacleId, new PhysicsSetup { Parts = [new SetupPart(box, Frame.Identity)] }, TestGeometry.At(100, 100, 0), 1f, PhysicsState.Static);
        world.Objects.Register(ObstacleId + 1, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 1f, 1f - drop)] }, TestGeometry.At(101, 100, 0), 1f, PhysicsState.Static);
        var walker = new Mover(world, Walker(stepDown: 0.8f, spheres: 2), MoverState.OnFloor(TestGeometry.At(99.5f, 100, 1f), 1f));
        walker.Walk(new Vector3(0.1f, 0, 0), 15); // ends over the cylinder, x = 101
        if (steppedDown)
        {
            Assert.InRange(walker.Origin.Z, 1f - drop - 0.002f, 1f - drop + 0.002f);
            Assert.True(walker.State.Contact && walker.State.OnWalkable);
        }
        else
        {
            Assert.InRange(walker.Origin.Z, 1f - 0.002f, 1f + 0.002f);
            Assert.False(walker.State.Contact);
        }
    }

    // ---- sphere ---------------------------------------------------------------------------------------
    // CSphere::step_sphere_up slides when step-up < (R + r + EPSILON) − disp.z, disp.z = centre height
    // difference r − c (target centre at height c, radius R): the climb is the target's top plus EPSILON,
    // c + R + EPSILON ≤ 0.6. Below it a step-up is tried (reported by OnStepUp; it fails here because the
    // rest normal on the small sphere's flank is too steep); above it none is tried. Target: R = 0.3.

    [Theory]
    [InlineData(0.58f, true)]
    [InlineData(0.62f, false)]
    public void Sphere_StepUpIsTried_OnlyUpToTheStepUpHeight(float top, bool tried)
    {
        const float targetRadius = 0.3f;
        var world = WithObstacle(new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, top - targetRadius), targetRadius)] }, new Vector3(100, 101, 0));
        var walker = new Mover(world, Walker(), MoverState.OnFloor(TestGeometry.At(100, 100.1f, 0), 0f)).WithLog();
        walker.Walk(new Vector3(0, 0.05f, 0), 4); // contact at centre distance 0.8: y ≈ 100.2 (both heights)
        Assert.True(walker.Frames.Any(f => f.Collided.Length > 0 || f.Result.CollisionNormalValid), "the walker reaches the sphere");
        Assert.Equal(tried, walker.Log!.Events.Any(e => e.Kind == TransitionEventKind.StepUp));
        Assert.InRange(walker.Origin.Z, -0.002f, 0.002f);
    }

    // ---- terrain --------------------------------------------------------------------------------------
    // Terrain has no risers; its limit is the walkable slope, FloorZ = 0.66417414 (cos 48.4°). A landblock
    // rising Δh over one 24 m cell along +x has normal z = 24 / √(24² + Δh²): Δh = 26 m → 0.6783 (walkable),
    // Δh = 28 m → 0.6508 (too steep). The walker starts on the flat at x = 95 and walks 0.1 m frames up the
    // slope that starts at x = 96: on the walkable slope it climbs (z rises by Δh / 24 per metre); on the
    // steep one it is not on walkable ground and does not climb it. On the slope adjust_offset projects each
    // 0.1 m onto the contact plane (n = (−26, 0, 24) / 35.38): the horizontal part is 0.1 (1 − nx²) = 0.046 m,
    // so 10 frames reach x = 96 and 20 more about 96.9.

    private static PhysicsWorld Slope(float rise)
    {
        var heights = new float[81];
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                heights[x * 9 + y] = x <= 4 ? 0f : rise;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(new Terrain(TestGeometry.Landblock, heights));
        return world;
    }

    [Fact]
    public void TerrainSlope_JustBelowTheWalkableLimit_IsWalkedUp()
    {
        var walker = new Mover(Slope(26f), Walker(), MoverState.OnFloor(TestGeometry.At(95, 100, 0), 0f));
        walker.Walk(new Vector3(0.1f, 0, 0), 30);
        float expected = (walker.Origin.X - 96f) * 26f / 24f;
        Assert.True(walker.Origin.X > 96.8f && walker.Origin.X < 97.1f, $"x = {walker.Origin.X}");
        Assert.InRange(walker.Origin.Z, expected - 0.01f, expected + 0.01f);
        Assert.True(walker.State.OnWalkable);
    }

    [Fact]
    public void TerrainSlope_JustAboveTheWalkableLimit_IsNotWalkedUp()
    {
        var walker = new Mover(Slope(28f), Walker(), MoverState.OnFloor(TestGeometry.At(95, 100, 0), 0f));
        walker.Walk(new Vector3(0.1f, 0, 0), 30);
        Assert.False(walker.State.Contact && walker.State.OnWalkable && walker.Origin.Z > 0.5f,
            $"the walker climbed a slope steeper than FloorZ: {walker.Origin}, walkable {walker.State.OnWalkable}");
    }
}
