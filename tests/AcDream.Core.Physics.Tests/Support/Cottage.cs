using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>
/// A one-room cottage: an env cell (4 m × 4 m × 3 m, floor at z = 0) whose south wall has a 1.2 m × 2.2 m
/// doorway leading outside, and a building in the outdoor cell whose doorway leads into it. Only what a
/// walk through the doorway needs.
/// </summary>
internal static class Cottage
{
    public const uint RoomId = (TestGeometry.Landblock << 16) | 0x0100;
    public static readonly Vector3 RoomOrigin = new(100, 110, 0);
    public const float DoorHalfWidth = 0.6f, DoorHeight = 2.2f;

    private static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new([a, b, c, d]);

    /// <summary>The room's inner surfaces (cell space), facing into the room.</summary>
    private static Polygon[] InnerSurfaces()
    {
        Vector3 P(float x, float y, float z) => new(x, y, z);
        float w = DoorHalfWidth, h = DoorHeight;
        return
        [
            Quad(P(-2, 0, 0), P(2, 0, 0), P(2, 4, 0), P(-2, 4, 0)),          // floor, up
            Quad(P(-2, 0, 3), P(-2, 4, 3), P(2, 4, 3), P(2, 0, 3)),          // ceiling, down
            Quad(P(-2, 4, 0), P(2, 4, 0), P(2, 4, 3), P(-2, 4, 3)),          // north wall, facing -y
            Quad(P(2, 0, 0), P(2, 0, 3), P(2, 4, 3), P(2, 4, 0)),            // east wall, facing -x
            Quad(P(-2, 0, 0), P(-2, 4, 0), P(-2, 4, 3), P(-2, 0, 3)),        // west wall, facing +x
            Quad(P(-2, 0, 0), P(-2, 0, 3), P(-w, 0, 3), P(-w, 0, 0)),        // south wall left of the door, facing +y
            Quad(P(w, 0, 0), P(w, 0, 3), P(2, 0, 3), P(2, 0, 0)),            // south wall right of the door
            Quad(P(-w, 0, h), P(-w, 0, 3), P(w, 0, 3), P(w, 0, h)),          // lintel
        ];
    }

    /// <summary>The room's interior as a cell BSP: a chain of the six inward planes (front = inside).</summary>
    private static BspTree CellBounds()
    {
        Plane[] planes =
        [
            new(Vector3.UnitY, 0f), new(-Vector3.UnitY, 4f), new(Vector3.UnitX, 2f),
            new(-Vector3.UnitX, 2f), new(Vector3.UnitZ, 0f), new(-Vector3.UnitZ, 3f),
        ];
        var nodes = planes.Select((p, i) => new BspNodeData { SplitPlane = p, Front = i < 5 ? i + 1 : -1, Bounds = new Sphere(new Vector3(0, 2, 1.5f), 3.5f) }).ToList();
        return BspTree.Create(Array.Empty<Polygon>(), nodes);
    }

    public static PhysicsWorld Build()
    {
        var world = TestGeometry.FlatWorld();
        var doorway = Quad(new(-DoorHalfWidth, 0, 0), new(-DoorHalfWidth, 0, DoorHeight), new(DoorHalfWidth, 0, DoorHeight), new(DoorHalfWidth, 0, 0));
        var room = new EnvCell(RoomId, new Frame(RoomOrigin), BspCompiler.Compile(InnerSurfaces()), CellBounds(),
            [new CellPortal(doorway, CellPortal.Outside, portalSide: false)]);
        world.Cells.AddEnvCell(room);

        // The shell seen from outside: the south wall's two halves either side of the doorway.
        var shellPolygons = BspShapes.BoxPolygons(new Vector3(-2, -0.2f, 0), new Vector3(-DoorHalfWidth, 0, 3))
            .Concat(BspShapes.BoxPolygons(new Vector3(DoorHalfWidth, -0.2f, 0), new Vector3(2, -0f, 3))).ToList();
        var shell = new PhysicsModel(BspCompiler.Compile(shellPolygons), name: "cottage shell");
        var outdoorCell = LandDefs.LandCellAt(TestGeometry.Landblock, RoomOrigin);
        world.Cells.AddBuilding(new Building(shell, new Position(outdoorCell, new Frame(RoomOrigin)), [RoomId]));
        return world;
    }
}
