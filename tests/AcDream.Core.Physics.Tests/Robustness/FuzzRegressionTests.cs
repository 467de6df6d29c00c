using AcDream.Core.Physics;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
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
    /// as retail behaviour; this pins the depth so a change in it is noticed (update the docs when it fails).
    /// </summary>
    [Fact]
    public void Seed603042950_TheFindingIsStillThere()
        => Assert.InRange(Seed603042950_Depth(), 0.004f, 0.005f);
}
