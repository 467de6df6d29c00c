using AcDream.Core.Physics.Bench;
using AcDream.Core.Physics.Bench.Accuracy;

namespace AcDream.Core.Physics.Tests.Stability;

/// <summary>
/// The door benchmark's stability measures as tests (not timed): the retail method's guarantees over the
/// approach grid, and the known failures of the methods, pinned as counts so that a change is noticed.
/// </summary>
public class DoorStabilityTests
{
    private const float Eps = PhysicsConstants.Epsilon;
    private static readonly DoorScene Scene = DoorScene.Create();
    private static readonly Lazy<ApproachOutcome[]> RetailFull = new(() => AccuracyRunner.Run(Scene, DoorMethod.Retail, DoorApproaches.Grid()));
    private static readonly Lazy<ApproachOutcome[]> Scale4Full = new(() => AccuracyRunner.Run(Scene, DoorMethod.Scale4, DoorApproaches.Grid()));

    private static string Describe(IEnumerable<ApproachOutcome> outcomes) =>
        string.Join("; ", outcomes.Take(5).Select(o => $"{o.Approach}: {o.Failures}, max penetration {o.MaxPenetration}"));

    [Fact]
    public void Retail_At30Hz_UpTo50MetresPerSecond_NeverNaN_NeverTunnels_NeverPenetratesBeyondEpsilon()
    {
        var at30 = RetailFull.Value.Where(o => o.Approach.Hz == 30).ToArray();
        Assert.Equal(DoorApproaches.Headings.Length * DoorApproaches.Laterals.Length * DoorApproaches.Speeds.Length, at30.Length);
        Assert.Contains(at30, o => o.Approach.Speed == 50f);
        var nan = at30.Where(o => o.NaNFrames > 0).ToArray();
        Assert.True(nan.Length == 0, "NaN: " + Describe(nan));
        var tunnels = at30.Where(o => o.TunnelFrames > 0).ToArray();
        Assert.True(tunnels.Length == 0, "tunnelled: " + Describe(tunnels));
        var deep = at30.Where(o => o.MaxPenetration > Eps).ToArray();
        Assert.True(deep.Length == 0, "penetrated: " + Describe(deep));
        Assert.True(at30.Max(o => o.MaxPenetration) > -0.05f, "the grid should bring the player within 5 cm of the slab");
    }

    [Fact]
    public void Retail_At10Hz_NeverNaN_NeverTunnels_NeverPenetratesBeyondEpsilon()
    {
        var at10 = RetailFull.Value.Where(o => o.Approach.Hz == 10).ToArray();
        Assert.DoesNotContain(at10, o => o.NaNFrames > 0 || o.TunnelFrames > 0 || o.MaxPenetration > Eps);
    }

    /// <summary>
    /// NE (front face, moving +X) and SE (back face, moving +X) approaches aimed at the slab: whenever the
    /// tangential step per sub-step exceeds √EPSILON the mover never stays put while the reference moves.
    /// </summary>
    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Retail_NeverStuck_OnNorthEastAndSouthEastApproaches(bool fromBack)
    {
        var grid = DoorApproaches.Grid(fromBack, headings: [5, 10, 20, 30, 45, 60, 75, 85], laterals: [-0.45f, -0.2f, 0f, 0.2f, 0.45f]);
        var outcomes = AccuracyRunner.Run(Scene, DoorMethod.Retail, grid);
        var stuck = outcomes.Where(o => o.StuckFrames > 0).ToArray();
        Assert.True(stuck.Length == 0, "stuck: " + Describe(stuck));
        Assert.Contains(outcomes, o => o.Approach.TangentialStep > AccuracyRunner.SlideThreshold && o.Slid);
        Assert.DoesNotContain(outcomes, o => o.MaxPenetration > Eps || o.TunnelFrames > 0 || o.NaNFrames > 0);
    }

    /// <summary>
    /// Known retail behaviour, pinned: a slow walk that meets the slab's vertical edge from beside it
    /// (aim 0.7 m off centre, heading towards the centre) is pinned at the edge, the collision normal
    /// alternating between the front face and the side face every frame (the reference rolls round the
    /// edge). Reproduce with <c>dotnet run --project bench/AcDream.Core.Physics.Bench -- trace Retail 45 -0.7 1 30</c>.
    /// </summary>
    [Fact]
    public void Retail_KnownFailures_AreTheEdgePins()
    {
        var outcomes = RetailFull.Value;
        var stuck = outcomes.Where(o => (o.Failures & DoorFailure.Stuck) != 0).ToArray();
        var jitter = outcomes.Where(o => (o.Failures & DoorFailure.Jitter) != 0).ToArray();
        Assert.All(stuck, o => Assert.Equal(0.7f, MathF.Abs(o.Approach.Lateral)));
        Assert.All(stuck, o => Assert.True(o.Approach.Speed <= 5f, o.Approach.ToString()));
        Assert.All(stuck, o => Assert.True(MathF.Sign(o.Approach.Heading) == -MathF.Sign(o.Approach.Lateral), o.Approach.ToString()));
        Assert.All(jitter, o => Assert.Equal(0.7f, MathF.Abs(o.Approach.Lateral)));
        Assert.Equal(ExpectedRetailStuck, stuck.Length);
        Assert.Equal(ExpectedRetailJitter, jitter.Length);
    }

    private const int ExpectedRetailStuck = 62;
    private const int ExpectedRetailJitter = 74;
    private const int ExpectedScale4Tunnels = 2;
    private const int ExpectedScale4Stuck = 118;

    /// <summary>Sub-steps of four radii cut the slab's corners at 20 m/s and 10 Hz (2 approaches), and get pinned more often; pinned.</summary>
    [Fact]
    public void Scale4_KnownFailures_Pinned()
    {
        var outcomes = Scale4Full.Value;
        var tunnels = outcomes.Where(o => o.TunnelFrames > 0).ToArray();
        Assert.Equal(ExpectedScale4Tunnels, tunnels.Length);
        Assert.All(tunnels, o => Assert.Equal(10, o.Approach.Hz));
        Assert.Equal(ExpectedScale4Stuck, outcomes.Count(o => o.StuckFrames > 0));
        Assert.DoesNotContain(outcomes, o => o.NaNFrames > 0);
    }

    [Fact]
    public void Reference_NeverFails_AndIsItsOwnTruth()
    {
        var grid = DoorApproaches.Grid(rates: [30, 10], speeds: [1f, 10f, 50f]);
        var outcomes = AccuracyRunner.Run(Scene, DoorMethod.Reference, grid);
        Assert.DoesNotContain(outcomes, o => o.Failures != DoorFailure.None);
        Assert.All(outcomes, o => Assert.True(o.MaxPenetration <= 1e-5f, $"{o.Approach}: {o.MaxPenetration}"));
        Assert.All(outcomes, o => Assert.Equal(0f, o.FinalError));
        Assert.Contains(outcomes, o => o.Slid);
    }
}
