using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// A random one-room building for the fuzzer: an env cell (a box room of random size and heading, floor on
/// the ground) whose south wall has a doorway portal leading outside, and the building shell in the
/// outdoor cell whose doorway leads in. The cottage of the apparatus tests, with random dimensions.
/// </summary>
internal sealed class FuzzRoom
{
    public const uint RoomId = (TestGeometry.Landblock << 16) | 0x0100;

    private readonly float _halfX, _depth;

    private FuzzRoom(Frame frame, float halfX, float depth)
    {
        Frame = frame;
        _halfX = halfX;
        _depth = depth;
    }

    /// <summary>The room's frame (origin at the doorway wall's middle, on the floor).</summary>
    public Frame Frame { get; }

    private static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new([a, b, c, d]);

    public static FuzzRoom Add(PhysicsWorld world, Random rng, List<string> description)
    {
        float R(float lo, float hi) => lo + (float)rng.NextDouble() * (hi - lo);
        float hx = R(2f, 5f), depth = R(3f, 8f), height = R(2.5f, 4f);
        float door = R(0.4f, hx - 0.3f), doorHeight = R(2f, height - 0.1f);
        var xy = SceneFuzzer.Centre + new Vector3(R(-6, 6), R(-6, 6), 0);
        var origin = new Vector3(xy.X, xy.Y, SceneFuzzer.Ground(world, xy));
        var frame = new Frame(origin, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, R(0, MathF.Tau)));

        Vector3 P(float x, float y, float z) => new(x, y, z);
        float h = height, w = door, dh = doorHeight, d = depth;
        Polygon[] inner =
        [
            Quad(P(-hx, 0, 0), P(hx, 0, 0), P(hx, d, 0), P(-hx, d, 0)),      // floor, up
            Quad(P(-hx, 0, h), P(-hx, d, h), P(hx, d, h), P(hx, 0, h)),      // ceiling, down
            Quad(P(-hx, d, 0), P(hx, d, 0), P(hx, d, h), P(-hx, d, h)),      // north wall, facing -y
            Quad(P(hx, 0, 0), P(hx, 0, h), P(hx, d, h), P(hx, d, 0)),        // east wall, facing -x
            Quad(P(-hx, 0, 0), P(-hx, d, 0), P(-hx, d, h), P(-hx, 0, h)),    // west wall, facing +x
            Quad(P(-hx, 0, 0), P(-hx, 0, h), P(-w, 0, h), P(-w, 0, 0)),      // south wall left of the doorway, facing +y
            Quad(P(w, 0, 0), P(w, 0, h), P(hx, 0, h), P(hx, 0, 0)),          // south wall right of the doorway
            Quad(P(-w, 0, dh), P(-w, 0, h), P(w, 0, h), P(w, 0, dh)),        // lintel
        ];
        Plane[] planes =
        [
            new(Vector3.UnitY, 0f), new(-Vector3.UnitY, d), new(Vector3.UnitX, hx),
            new(-Vector3.UnitX, hx), new(Vector3.UnitZ, 0f), new(-Vector3.UnitZ, h),
        ];
        var bounds = new Sphere(new Vector3(0, d / 2, h / 2), new Vector3(hx, d / 2, h / 2).Length() + 0.1f);
        var nodes = planes.Select((p, i) => new BspNodeData { SplitPlane = p, Front = i < 5 ? i + 1 : -1, Bounds = bounds }).ToList();
        var doorway = Quad(P(-w, 0, 0), P(-w, 0, dh), P(w, 0, dh), P(w, 0, 0));
        world.Cells.AddEnvCell(new EnvCell(RoomId, frame, BspCompiler.Compile(inner), BspTree.Create(Array.Empty<Polygon>(), nodes),
            [new CellPortal(doorway, CellPortal.Outside, portalSide: false)]));

        var shell = BspShapes.BoxPolygons(P(-hx, -0.2f, 0), P(-w, 0, h)).Concat(BspShapes.BoxPolygons(P(w, -0.2f, 0), P(hx, 0, h))).ToList();
        var outdoor = LandDefs.LandCellAt(TestGeometry.Landblock, origin);
        world.Cells.AddBuilding(new Building(new PhysicsModel(BspCompiler.Compile(shell), name: "fuzz room shell"),
            new Position(outdoor, frame), [RoomId]));
        description.Add($"room {2 * hx}x{d}x{h} doorway {2 * w}x{dh} at {origin} rot {frame.Orientation}");
        return new FuzzRoom(frame, hx, depth);
    }

    /// <summary>A start inside the room, clear of its walls: on the floor, or up to 1 m above it.</summary>
    public MoverState StartInside(Random rng, bool grounded)
    {
        float R(float lo, float hi) => lo + (float)rng.NextDouble() * (hi - lo);
        var local = new Vector3(R(-_halfX + 0.7f, _halfX - 0.7f), R(0.7f, _depth - 0.7f), grounded ? 0f : R(0.05f, 1f));
        var position = new Position(RoomId, new Frame(Frame.LocalToGlobal(local), Frame.Orientation));
        return grounded ? MoverState.OnFloor(position, Frame.Origin.Z) : MoverState.Airborne(position);
    }
}
