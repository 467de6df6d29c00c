using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>Step up onto ledges, stop at tall ones, and the edge behaviour of a grounded mover.</summary>
public class StepAndEdgeTests
{
    private const uint PlatformId = 0x7000_0020;

    /// <summary>A static 4 m × 4 m platform of the given height, its near edge at y = 102, centred on x = 100.</summary>
    private static PhysicsWorld Platform(float height)
    {
        var world = TestGeometry.FlatWorld();
        var box = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-2, 0, 0), new Vector3(2, 4, height)), name: "platform");
        var setup = new PhysicsSetup { Parts = [new SetupPart(box, Frame.Identity)] };
        world.Objects.Register(PlatformId, setup, TestGeometry.At(100, 102, 0), 1f, PhysicsState.Static);
        return world;
    }

    /// <summary>
    /// The retail player with its setup's step-down (1.5 m). Retail's step-up leaves the mover resting on the
    /// ledge's plane but short of its lip (the sphere pops up where it touched the riser), and the next
    /// frame's step-down probe must reach the top face from there: the seed's 0.04 m probe cannot.
    /// </summary>
    private static MoverDescription Climber() => MoverDescription.Player();

    [Fact]
    public void Ledge_0_3m_IsSteppedUp()
    {
        var player = TestScenes.Player(Platform(0.3f), 100, 100, Climber());
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y > 103f, $"the player should walk onto the platform, y = {player.Origin.Y}");
        Assert.InRange(player.Origin.Z, 0.3f, 0.3f + 0.01f);
        Assert.True(player.State.OnWalkable);
    }

    /// <summary>
    /// Retail quirk (CPolygon::adjust_sphere_to_plane, acclient; ACE Polygon.cs): the step-up probe accepts a
    /// walk fraction down to -0.5, so a mover can rise up to 1.5 × its step-up height when its sphere already
    /// overlaps the ledge's top face. With 0.1 m frames the player's sphere sinks 0.08 m into the riser
    /// before the step, enough to reach the top face of a 0.7 m ledge: it is climbed.
    /// </summary>
    [Fact]
    public void Ledge_0_7m_IsClimbed_TheRetailStepAllowanceIsOneAndAHalfStepHeights()
    {
        var player = TestScenes.Player(Platform(0.7f), 100, 100, Climber());
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.InRange(player.Origin.Z, 0.7f, 0.71f);
    }

    [Fact]
    public void Ledge_1m_Blocks()
    {
        var player = TestScenes.Player(Platform(1.0f), 100, 100, Climber());
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y <= 102f - TestScenes.PlayerRadius + PhysicsConstants.Epsilon * 5, $"y = {player.Origin.Y}");
        Assert.InRange(player.Origin.Z, 0f, 0.01f);
    }

    private static Mover OnPlatform(MoverDescription? description = null)
    {
        var world = Platform(1f);
        var start = TestGeometry.At(100, 104, 1f);
        return new Mover(world, description ?? TestScenes.SeedPlayer(), MoverState.OnFloor(start, 1f));
    }

    [Fact]
    public void WalkingOffALedge_WithEdgeSlide_StaysOnTheLedge()
    {
        var player = OnPlatform();
        player.Walk(new Vector3(0, 0.1f, 0), 40); // the far edge is at y = 106
        // The mover may hang over the lip while its step-down probe (sphere 0 lowered 0.04 m) still touches
        // the top face: (y - 106)² + (1.445 - 1)² ≤ 0.48².
        float overhang = MathF.Sqrt(0.48f * 0.48f - 0.445f * 0.445f);
        Assert.True(player.Origin.Y <= 106f + overhang + PhysicsConstants.Epsilon, $"edge slide should keep the player on the platform, y = {player.Origin.Y}");
        Assert.True(player.Origin.Y > 105.9f, "the player walks up to the edge");
        Assert.InRange(player.Origin.Z, 1f, 1.01f);
        Assert.True(player.State.Contact);
    }

    [Fact]
    public void WalkingOffALedge_WithoutEdgeSlide_LeavesTheGround()
    {
        var noEdgeSlide = new MoverDescription(0x50000003, MoverDescription.Player().Spheres, 0.6f, 0.04f, PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var player = OnPlatform(noEdgeSlide);
        player.Walk(new Vector3(0, 0.1f, 0), 40);
        Assert.True(player.Origin.Y > 106.4f, $"y = {player.Origin.Y}");
        Assert.False(player.State.Contact, "past the edge there is no ground within the step-down height");
    }

    /// <summary>
    /// The retail player's EdgeSlide holds it at a drop deeper than its step-down (2 m against 1.5 m): walking
    /// north off a 2 m platform it stops at the far edge (y = 106) and stays on the top face, in contact. Its
    /// copy without the flag (<see cref="MoverDescription.With"/>) walks on over the drop: no ground within
    /// 1.5 m below, so it ends beyond the edge, out of contact, still at the platform's height (a
    /// <c>Resolve</c> has no gravity; a body would fall).
    /// </summary>
    [Fact]
    public void TheRetailPlayer_StopsAtADeepDrop_ItsCopyWithoutEdgeSlide_WalksOff()
    {
        var start = MoverState.OnFloor(TestGeometry.At(100, 104, 2f), 2f);
        var held = new Mover(Platform(2f), MoverDescription.Player(), start);
        var walker = new Mover(Platform(2f), MoverDescription.Player().With(physicsState: PhysicsState.Gravity), start);
        held.Walk(new Vector3(0, 0.1f, 0), 40);
        walker.Walk(new Vector3(0, 0.1f, 0), 40);

        Assert.InRange(held.Origin.Y, 105.9f, 106.5f);
        Assert.InRange(held.Origin.Z, 2f, 2.01f);
        Assert.True(held.State.Contact && held.State.OnWalkable, "the retail player stays on the platform");
        Assert.True(walker.Origin.Y > 107.5f, $"without EdgeSlide the player walks on over the drop, y = {walker.Origin.Y}");
        Assert.False(walker.State.Contact, "past the edge there is no ground within the step-down height");
    }

    /// <summary>
    /// Walking diagonally off the platform's far edge with EdgeSlide: retail restores the check position and
    /// then slides along the precipice (CTransition::edge_slide), so the mover keeps moving along the edge
    /// every frame and never drops off.
    /// </summary>
    [Fact]
    public void WalkingDiagonallyAtALedge_WithEdgeSlide_SlidesAlongItEveryFrame()
    {
        var world = Platform(1f);
        var player = new Mover(world, MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(99, 105, 1f), 1f));
        player.Walk(new Vector3(0.0707f, 0.0707f, 0), 20);
        var atEdge = player.Frames.Skip(12).ToList();
        Assert.All(atEdge, f => Assert.True(f.After.X - f.Before.X > 0.01f, $"stalled at {f.Before}"));
        Assert.All(player.Frames, f => Assert.InRange(f.After.Z, 1f, 1.01f));
        Assert.True(player.State.Contact);
    }

    /// <summary>
    /// A two-sphere mover whose step-down (1.5 m) exceeds its diameter (0.96 m) probes twice, 0.75 m each,
    /// the second from where the first left it (retail: the check position is not restored between them),
    /// so it reaches 1.5 m. The player without edge slide crosses the platform's far edge (y = 106) in a
    /// 0.5 m frame (two 0.25 m sub-steps); at y = 106.5 its sphere (r = 0.48) is clear of the top face, so
    /// the first probe touches nothing. Off a 1.4 m platform the second probe reaches the ground: origin
    /// z = 0.005 (the player's sphere 0 rests 0.005 below its origin), in contact. Off a 1.6 m one both fall
    /// 0.1 m short: it walks on out of contact at z = 1.605.
    /// </summary>
    [Theory]
    [InlineData(1.4f, true)]
    [InlineData(1.6f, false)]
    public void WalkingOffALedge_TheStepDownReachesTwoHalfProbes(float height, bool steppedDown)
    {
        var noEdgeSlide = new MoverDescription(0x50000003, MoverDescription.Player().Spheres, 0.6f, 1.5f, PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var player = new Mover(Platform(height), noEdgeSlide, MoverState.OnFloor(TestGeometry.At(100, 105.5f, height), height));
        player.Walk(new Vector3(0, 0.5f, 0), 2);
        Assert.InRange(player.Frames[0].After.Z, height + 0.005f - 0.002f, height + 0.005f + 0.002f); // still on the platform at y = 106
        Assert.InRange(player.Origin.Y, 106.5f - 0.001f, 106.5f + 0.001f);
        float expectedZ = steppedDown ? 0.005f : height + 0.005f;
        Assert.InRange(player.Origin.Z, expectedZ - 0.002f, expectedZ + 0.002f);
        Assert.Equal(steppedDown, player.State.Contact);
    }
}
