using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Apparatus;

/// <summary>
/// Two retail quirks of a grounded, edge-sliding mover (the retail player: step-up 0.6, EdgeSlide) at the
/// edge of a walkable polygon, reproduced on small scenes built here. Both were first seen on real Holtburg
/// cells (docs/open-questions.md, "A walker that stops for good at a ledge it grazed" and "Standing on a
/// ramp's plane past its top edge"); both follow the 2013 client's code path, so they are pinned, not fixed.
/// </summary>
public class LedgeGrazeTests
{
    private const uint PlatformId = 0x7000_0031, RampId = 0x7000_0032;
    private const float Dt = 1f / 30f;
    private const float Radius = 0.48f, HalfRadius = 0.24f;

    /// <summary>One polygon as a model: a non-solid single leaf (a walkable ramp with nothing behind it).</summary>
    private static PhysicsModel Quad(string name, params Vector3[] vertices)
    {
        var polygon = new Polygon(vertices);
        var tree = BspTree.Create([polygon], [new BspNodeData { IsLeaf = true, Solid = false, Polygons = [0] }]);
        return new PhysicsModel(tree, name: name);
    }

    private static void Register(PhysicsWorld world, uint id, PhysicsModel model, float x, float y) =>
        world.Objects.Register(id, new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] }, TestGeometry.At(x, y, 0), 1f, PhysicsState.Static);

    // ---- (a) the ledge at the top of a ramp ----------------------------------------------------------------

    /// <summary>The platform's near face and the height of its top face.</summary>
    private const float FaceY = 105f, Top = 2f;

    /// <summary>
    /// A 2 m platform (box x 98..102, y 105..109) and, below its near face, a ramp of slope 0.8 whose top edge
    /// stops 0.5 m short of the face and 0.6 m (one step-up) below the top: between them is a gap with no
    /// floor within the mover's 1.5 m step-down probe (as at a cellar lip).
    /// </summary>
    private static PhysicsWorld LedgeAboveRamp()
    {
        var world = TestGeometry.FlatWorld();
        var box = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-2, 0, 0), new Vector3(2, 4, Top)), name: "platform");
        Register(world, PlatformId, box, 100, FaceY);
        const float rampTop = Top - 0.6f, rampTopY = -0.5f, rampFootY = rampTopY - rampTop / 0.8f;
        Register(world, RampId, Quad("ramp", new(-0.8f, rampFootY, 0), new(0.8f, rampFootY, 0), new(0.8f, rampTopY, rampTop), new(-0.8f, rampTopY, rampTop)), 100, FaceY);
        return world;
    }

    private static Mover WalkUpTheRamp(float speed, int frames)
    {
        var mover = new Mover(LedgeAboveRamp(), MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(100, 101.75f, 0), 0f));
        mover.Walk(new Vector3(0, speed * Dt, 0), frames);
        return mover;
    }

    /// <summary>
    /// Retail quirk (CTransition::step_up → step_down, acclient.c:312793, :312628; BSPTREE::step_sphere_down
    /// → find_walkable → CPolygon::walkable_hits_sphere / adjust_sphere_to_plane, acclient.c:361176,
    /// :360518, :359533): a step-up lands wherever the foot sphere merely overlaps the top face's edge
    /// (step_down skips check_walkable while stepping up; here the ramp below would pass it anyway). Once the
    /// centre has moved past the ramp's top, the next frame's step-down check (check_walkable → hits_walkable
    /// → check_small_walkable, acclient.c:312474, :360311) finds nothing walkable within half a radius under
    /// the centre, so edge_slide slides along the top face's crossed edge
    /// (precipice_slide, acclient.c:313979), a move square to the edge slides nowhere, and the frame ends
    /// in place with sliding normal (0, −1, 0). From then on adjust_offset (acclient.c:311863) projects every
    /// straight-ahead request onto the edge, to nothing, and find_transitional_position refuses the frame;
    /// CPhysicsObj keeps its carried sliding normal when a transition is refused (it is only rewritten by
    /// SetPositionInternal after an accepted one, acclient.c:322503), so the walker stops for good.
    /// </summary>
    [Fact]
    public void SlowWalker_StopsForGood_StandingOnTheTopPlaneOutsideTheFace()
    {
        var walker = WalkUpTheRamp(speed: 2f, frames: 120);

        var stop = walker.Frames.FindIndex(f => !f.Result.Succeeded);
        Assert.True(stop > 0, "the walker should be refused at the ledge");
        var stuck = walker.Frames[stop].Before;
        Assert.All(walker.Frames.Skip(stop), f => Assert.False(f.Result.Succeeded));
        Assert.All(walker.Frames.Skip(stop), f => Assert.Equal(stuck, f.After));

        // On the platform's top plane (origin 0.005 above it: sphere 0 at 0.475, radius 0.48) ...
        Assert.InRange(stuck.Z, Top + 0.005f - 1e-4f, Top + 0.005f + 1e-4f);
        Assert.Equal(Top, -walker.State.ContactPlane.D, 4);
        Assert.True(walker.State.Contact && walker.State.OnWalkable);
        // ... but with its centre outside the top face, by more than half a radius: only the sphere overlaps it.
        Assert.InRange(FaceY - stuck.Y, HalfRadius, Radius);
        Assert.True(walker.State.SlidingNormalValid);
        AssertVec.Near(new Vector3(0, -1, 0), walker.State.SlidingNormal, 1e-6f);
    }

    [Fact]
    public void FastWalker_StepsUpFarEnoughAndWalksOn()
    {
        var walker = WalkUpTheRamp(speed: 8f, frames: 30);
        Assert.True(walker.Origin.Y > FaceY + 1f, $"y = {walker.Origin.Y}");
        Assert.InRange(walker.Origin.Z, Top, Top + 0.01f);
    }

    /// <summary>
    /// What a client sees and can do: the stuck walker is not falling (contact on walkable ground, so a
    /// retail body applies no gravity, CPhysicsObj::calc_acceleration, acclient.c:317786). A request with a
    /// component along the edge slides along it (accepted); a step back clears the sliding normal
    /// (adjust_offset drops it when the move no longer opposes it).
    /// </summary>
    [Fact]
    public void StuckWalker_CanSlideAlongTheEdge_OrStepBack()
    {
        var walker = WalkUpTheRamp(speed: 2f, frames: 120);
        var stuck = walker.Origin;

        var sideways = walker.Step(new Vector3(0.05f, 2f * Dt, 0));
        Assert.True(sideways.Succeeded);
        Assert.Equal(stuck.X + 0.05f, walker.Origin.X, 4);
        Assert.Equal(stuck.Y, walker.Origin.Y, 4);

        var back = walker.Step(new Vector3(0, -2f * Dt, 0));
        Assert.True(back.Succeeded);
        Assert.True(walker.Origin.Y < stuck.Y - 0.05f, $"y = {walker.Origin.Y}");
    }

    /// <summary>
    /// A body-driven client (<see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>, retail update_object) sees the same: walking at
    /// 2 m/s it stops for good at the ledge, standing on walkable ground (no gravity, no fall) while every
    /// step is refused. A jump frees it: the body leaves the contact plane, so the first quantum's leap keeps
    /// only its part along the carried sliding normal's plane (straight up), that accepted transition drops the
    /// sliding normal, and the airborne body carries on forward and lands on the platform.
    /// </summary>
    [Fact]
    public void BodyDrivenWalker_StopsAtTheLedgeToo_AndAJumpFreesIt()
    {
        var engine = new PhysicsEngine(LedgeAboveRamp());
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(100, 101.75f, 0), 0f);
        var body = BodyState.Creature();
        var walk = new Vector3(0, 2f, 0);
        BodyStepResult last = default;
        for (int i = 0; i < 150; i++)
        {
            last = engine.Step(mover, state, body, Dt, walk);
            state = last.Next;
            body = last.Body;
        }

        Assert.False(last.Move.Succeeded);
        Assert.InRange(FaceY - state.Position.Origin.Y, HalfRadius, Radius);
        Assert.InRange(state.Position.Origin.Z, Top + 0.005f - 1e-4f, Top + 0.005f + 1e-4f);
        Assert.True(state.Contact && state.OnWalkable && state.SlidingNormalValid);

        var stuck = state.Position.Origin;
        var jump = engine.Step(mover, state, body, Dt, walk, jumpVelocity: 4f);
        Assert.True(jump.Jumped && jump.Move.Succeeded);
        Assert.Equal(stuck.Y, jump.Next.Position.Origin.Y);
        Assert.True(jump.Next.Position.Origin.Z > stuck.Z);
        Assert.False(jump.Next.SlidingNormalValid);
        state = jump.Next;
        body = jump.Body;
        for (int i = 0; i < 60; i++)
        {
            var r = engine.Step(mover, state, body, Dt, walk);
            state = r.Next;
            body = r.Body;
        }
        Assert.True(state.Position.Origin.Y > FaceY + 0.5f, $"y = {state.Position.Origin.Y}");
        Assert.InRange(state.Position.Origin.Z, Top, Top + 0.01f);
    }

    // ---- (b) the top edge of a ramp over nothing -----------------------------------------------------------

    /// <summary>The ramp's top edge: y and height, and its plane's normal Z.</summary>
    private const float EdgeY = 100f + 2f / 0.9f, EdgeZ = 2f;
    private static readonly float RampNormalZ = 1f / MathF.Sqrt(1f + 0.9f * 0.9f);

    /// <summary>A lone ramp of slope 0.9 rising from the ground at y 100 to a top edge 2 m up, with nothing beyond it.</summary>
    private static PhysicsWorld RampToNowhere()
    {
        var world = TestGeometry.FlatWorld();
        const float length = 2f / 0.9f;
        Register(world, RampId, Quad("ramp", new(-0.8f, 0, 0), new(0.8f, 0, 0), new(0.8f, length, EdgeZ), new(-0.8f, length, EdgeZ)), 100, 100);
        return world;
    }

    private static Mover ClimbToTheTop(float stepDown)
    {
        var mover = new Mover(RampToNowhere(), MoverDescription.Player(stepDownHeight: stepDown), MoverState.OnFloor(TestGeometry.At(100, 98.5f, 0), 0f));
        mover.Walk(new Vector3(0, 4f * Dt, 0), 90);
        return mover;
    }

    /// <summary>
    /// Retail quirk (CTransition::check_walkable, acclient.c:312474 → SPHEREPATH::check_walkables,
    /// acclient.c:313467 → CPolygon::check_walkable with half the radius, acclient.c:360226): with a 1.5 m
    /// step-down the grounded mover keeps the ramp as its floor while the vertical projection of its centre
    /// onto the ramp's plane is within half a radius (0.24 m, in the plane) of the polygon, so it walks on
    /// the plane's extension past the top edge, over nothing, and is then stopped by the precipice slide.
    /// The overhang is at most 0.24 × N.z horizontally.
    /// </summary>
    [Fact]
    public void LongStepDown_StandsOnTheRampsPlane_PastItsTopEdge()
    {
        var mover = ClimbToTheTop(stepDown: 1.5f);

        float overhang = mover.Origin.Y - EdgeY;
        Assert.InRange(overhang, 0.01f, HalfRadius * RampNormalZ + 1e-4f);
        // Resting on the ramp's plane (sphere 0 tangent to it), higher than the top edge, over nothing.
        var center = mover.Origin + new Vector3(0, 0, 0.475f);
        var plane = mover.State.ContactPlane;
        Assert.Equal(Radius, Vector3.Dot(plane.Normal, center) + plane.D, 3);
        Assert.Equal(RampNormalZ, plane.Normal.Z, 4);
        Assert.True(mover.Origin.Z > EdgeZ, $"z = {mover.Origin.Z}");
        Assert.True(mover.State.Contact && mover.State.OnWalkable);
        Assert.False(mover.Frames[^1].Result.Succeeded);
    }

    /// <summary>
    /// With the seed's 0.04 m step-down the probe below the centre stops reaching the polygon before the
    /// edge (the sphere's contact point runs ahead of its centre on a slope): the step-down fails, edge_slide
    /// finds the walkable polygon from the current position but no crossed edge, and the move is Collided
    /// (acclient.c:312684, :313979). The mover stops on the ramp, short of the edge.
    /// </summary>
    [Fact]
    public void ShortStepDown_StopsOnTheRamp_ShortOfTheEdge()
    {
        var mover = ClimbToTheTop(stepDown: 0.04f);
        Assert.InRange(EdgeY - mover.Origin.Y, 0.01f, Radius);
        var center = mover.Origin + new Vector3(0, 0, 0.475f);
        var plane = mover.State.ContactPlane;
        Assert.Equal(Radius, Vector3.Dot(plane.Normal, center) + plane.D, 3);
        Assert.True(mover.State.Contact && mover.State.OnWalkable);
    }
}
