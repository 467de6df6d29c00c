using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>Failures the fuzzer found, reduced to fixed scenes.</summary>
public class FuzzRegressionTests
{
    // Fuzz case seed -603042950 (run seed 20250107), reduced: two cylinders removed, the mover started
    // grounded where the failing frame began, one frame. A one-sphere mover (r = 0.33) walks 2 m on a
    // flat floor past a box tilted in every axis; it slides along a face whose normal points down
    // (0.26, 0.92, -0.29) and ends 4.6 mm inside the box.
    internal const int CaseSeed = -603042950;
    private static readonly Quaternion BoxRotation = Quaternion.Normalize(new Quaternion(-0.51896274f, -0.29524797f, 0.5737003f, -0.5606908f));
    private static readonly Vector3 BoxHalf = new(1.4093894f, 0.68730354f, 1.1836429f);
    private static readonly Vector3 BoxAt = new(98.43752f, 97.34258f, 1.1987699f);
    private static readonly Vector3 PartOrigin = new(0.046684086f, -0.01669085f, -0.027557254f);
    private const float Floor = 0.53756905f, Radius = 0.32984954f;

    internal static float Seed603042950_Depth()
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(TestGeometry.Landblock, Floor));
        var setup = new PhysicsSetup { Parts = [new SetupPart(new PhysicsModel(BspShapes.Box(-BoxHalf, BoxHalf)), new Frame(PartOrigin))] };
        var boxPos = new Position(LandDefs.LandCellAt(TestGeometry.Landblock, BoxAt), new Frame(BoxAt, BoxRotation));
        world.Objects.Register(0x7000_0001, setup, boxPos, 1f, PhysicsState.None);
        var mover = new MoverDescription(SceneFuzzer.MoverId, [new Sphere(new Vector3(0, 0, Radius), Radius)], 0.18343462f, 0.42051238f, PhysicsState.Gravity, ObjectInfoState.IsPlayer);
        var solid = new SceneFuzzer.Solid(1, BoxHalf, boxPos.Frame.LocalToGlobal(PartOrigin), BoxRotation);
        var start = MoverState.OnFloor(TestGeometry.At(100.41472f, 98.84947f, Floor), Floor);
        Assert.True(Penetration.SphereIntoBox(start.Position.Origin + new Vector3(0, 0, Radius), Radius, solid) < -0.5f, "starts clear");
        var target = start.Position;
        target.Frame.Origin = new Vector3(98.52019f, 98.20544f, Floor);
        var result = new PhysicsEngine(world).Resolve(mover, start, target);
        return Penetration.SphereIntoBox(result.Next.Position.Origin + new Vector3(0, 0, Radius), Radius, solid);
    }

    /// <summary>
    /// Open finding (docs/robustness.md, Findings): the mover ends 4.6 mm inside the box. Not yet explained
    /// as retail behaviour; this pins the depth so a change in it is noticed. A fix (the mover no deeper
    /// than EPSILON) passes too, so fixing the bug never breaks the suite; the message then says to un-pin.
    /// </summary>
    [Fact]
    public void Seed603042950_StillInside_OrFixed()
    {
        float depth = Seed603042950_Depth();
        bool fixedNow = depth <= PhysicsConstants.Epsilon;
        bool stillPinned = depth >= 0.004f && depth <= 0.005f;
        Assert.True(fixedNow || stillPinned,
            $"case seed {CaseSeed}: the mover ends {depth} m inside the box; pinned at 4.6 mm (0.004..0.005). "
            + "If it is now at most EPSILON the finding is fixed: un-pin it (remove the seed from FuzzTests.KnownFailures, "
            + "this test and the Findings table of docs/robustness.md); any other depth is a new behaviour to explain.");
    }

    // Fuzz case seed 1901049213 (every-feature run seed 20261201), reduced to the one box it enters: a
    // one-sphere missile mover (r = 0.2018, PathClipped | PerfectClip), airborne, asks to move 0.75 m
    // past a long box tilted on every axis. The perfect-clip search (BSPTREE::adjust_to_plane, whose first
    // stage jumps to CPolygon::adjust_sphere_to_poly's touch time without clamping it to the move) puts it
    // 1.05 m along, beyond its target, and 0.40 m inside the box. Without PerfectClip it stops 0.15 m clear.
    internal const int PerfectClipCaseSeed = 1901049213;

    internal static float PerfectClipDepth(ObjectInfoState flags)
    {
        const float floor = 3.664565f, radius = 0.20179349f;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(TestGeometry.Landblock, floor));
        var half = new Vector3(16.724495f, 1.377327f, 0.9862494f);
        var at = new Vector3(98.14429f, 95.742905f, 3.5550103f);
        var rotation = Quaternion.Normalize(new Quaternion(-0.45673698f, 0.15194373f, 0.7517393f, -0.45076868f));
        var partOrigin = new Vector3(-0.1650613f, 0.25235283f, -0.16061491f);
        var setup = new PhysicsSetup { Parts = [new SetupPart(new PhysicsModel(BspShapes.Box(-half, half)), new Frame(partOrigin))] };
        var boxPos = new Position(LandDefs.LandCellAt(TestGeometry.Landblock, at), new Frame(at, rotation));
        world.Objects.Register(0x7000_0000, setup, boxPos, 1f, PhysicsState.None);
        var solid = new SceneFuzzer.Solid(0x7000_0000, half, boxPos.Frame.LocalToGlobal(partOrigin), rotation);
        var mover = new MoverDescription(SceneFuzzer.MoverId, [new Sphere(new Vector3(0, 0, radius), radius)], 0.5f, 0.3f, PhysicsState.Missile, flags);
        var start = MoverState.Airborne(TestGeometry.At(100.6689f, 98.66107f, 4.868141f));
        Assert.True(Penetration.SphereIntoBox(start.Position.Origin + new Vector3(0, 0, radius), radius, solid) < -0.4f, "starts clear");
        var target = start.Position;
        target.Frame.Origin += new Vector3(-0.7435875f, -0.092813164f, -0.03881681f);
        var result = new PhysicsEngine(world).Resolve(mover, start, target);
        return Penetration.SphereIntoBox(result.Next.Position.Origin + new Vector3(0, 0, radius), radius, solid);
    }

    /// <summary>
    /// Open finding (docs/robustness.md, Findings): a perfect-clip mover ends 0.40 m inside a tilted box. Pinned
    /// (0.40..0.41 m) or fixed (at most EPSILON) both pass; the path-clipped mover without PerfectClip is the control.
    /// </summary>
    [Fact]
    public void PerfectClipMissile_StillInside_OrFixed()
    {
        Assert.True(PerfectClipDepth(ObjectInfoState.PathClipped) < 0f, "control: without PerfectClip the missile stops outside the box");
        float depth = PerfectClipDepth(ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        Assert.True(depth <= PhysicsConstants.Epsilon || (depth >= 0.40f && depth <= 0.41f),
            $"case seed {PerfectClipCaseSeed}: the perfect-clip missile ends {depth} m inside the box; pinned at 0.4036 m. "
            + "If it is now at most EPSILON the finding is fixed: un-pin it (FuzzTests.IsKnownFinding, this test, docs/robustness.md); "
            + "any other depth is a new behaviour to explain.");
    }
}
