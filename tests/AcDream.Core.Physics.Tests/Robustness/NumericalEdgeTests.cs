using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Exact-boundary cases against an axis-aligned box (x 99..101, y 99..101, z 0..2) on flat ground: a
/// one-sphere mover (r = 0.5, centre 1 m up, airborne) touching at EPSILON, moving parallel to a face,
/// centred on an edge or vertex line, not moving, moving exactly in a split plane. Each must end finite,
/// in a known cell, no deeper than EPSILON into the box.
/// </summary>
public class NumericalEdgeTests
{
    private const float R = 0.5f, Eps = PhysicsConstants.Epsilon;
    private static readonly Vector3 Min = new(99, 99, 0), Max = new(101, 101, 2);

    private static (PhysicsWorld World, MoverDescription Mover, SceneFuzzer.Solid Box) Scene()
    {
        var world = TestGeometry.FlatWorld();
        var half = (Max - Min) * 0.5f;
        var centre = (Min + Max) * 0.5f;
        world.Objects.Register(0x7000_0001, new PhysicsSetup { Parts = [new SetupPart(new PhysicsModel(BspShapes.Box(-half, half)), Frame.Identity)] },
            TestGeometry.At(centre.X, centre.Y, centre.Z), 1f, PhysicsState.Static);
        var mover = new MoverDescription(SceneFuzzer.MoverId, [new Sphere(new Vector3(0, 0, 1f), R)], 0.6f, 0.04f, PhysicsState.Gravity);
        return (world, mover, new SceneFuzzer.Solid(0x7000_0001, half, centre, Quaternion.Identity));
    }

    public static TheoryData<string, Vector3, Vector3> Cases() => new()
    {
        // name, start origin (sphere centre is 1 m above), offset
        { "touching at EPSILON, still", new(101 + R + Eps, 100, 0), Vector3.Zero },
        { "touching at EPSILON, pushing in", new(101 + R + Eps, 100, 0), new(-0.3f, 0, 0) },
        { "touching exactly, pushing in", new(101 + R, 100, 0), new(-0.3f, 0, 0) },
        { "parallel to a face, touching", new(101 + R + Eps, 98, 0), new(0, 4, 0) },
        { "parallel to a face, exactly touching", new(101 + R, 98, 0), new(0, 4, 0) },
        { "centre on a vertical edge's diagonal, into the edge", new(102, 102, 0), new(-1, -1, 0) },
        { "centre on a vertical edge line, along a face plane", new(101, 98, 0), new(0, 0.9f, 0) },
        { "centre exactly on a vertex's diagonal, 3D", new(102, 102, 2f), new(-1, -1, -1f) },
        { "zero motion, clear", new(103, 100, 0), Vector3.Zero },
        { "zero motion, touching", new(101 + R, 100, 0), Vector3.Zero },
        { "exactly along a split plane (x = 101) into the -Y face", new(101, 97, 0), new(0, 3, 0) },
        { "exactly along a split plane (y = 99) into the +X face", new(103, 99, 0), new(-3, 0, 0) },
        { "exactly along the top face plane (z = 2, centre on it)", new(103, 100, 1f), new(-3, 0, 0) },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void ExactBoundaries_StayFiniteKnownAndOutside(string name, Vector3 start, Vector3 offset)
    {
        var (world, mover, box) = Scene();
        var state = MoverState.Airborne(TestGeometry.At(start.X, start.Y, start.Z));
        var target = state.Position;
        target.Frame.Origin += offset;
        var engine = new PhysicsEngine(world);
        var result = engine.Resolve(mover, state, target);
        var end = result.Next.Position;
        Assert.True(float.IsFinite(end.Origin.X) && float.IsFinite(end.Origin.Y) && float.IsFinite(end.Origin.Z), $"{name}: {end}");
        Assert.NotNull(world.Cells.Get(end.CellId));
        float before = Penetration.SphereIntoBox(start + new Vector3(0, 0, 1f), R, box);
        float after = Penetration.SphereIntoBox(end.Origin + new Vector3(0, 0, 1f), R, box);
        Assert.True(after <= Math.Max(Eps, before) + 1e-6f, $"{name}: ends {after} m inside the box (started {before}), at {end.Origin}");
        if (offset == Vector3.Zero)
        {
            Assert.True(result.Succeeded, name);
            Assert.Equal(BitConverter.SingleToUInt32Bits(start.X), BitConverter.SingleToUInt32Bits(end.Origin.X));
            Assert.Equal(BitConverter.SingleToUInt32Bits(start.Y), BitConverter.SingleToUInt32Bits(end.Origin.Y));
            Assert.Equal(BitConverter.SingleToUInt32Bits(start.Z), BitConverter.SingleToUInt32Bits(end.Origin.Z));
        }
    }
}
