using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>Hand-built geometry for tests that must not depend on the BSP compiler.</summary>
internal static class TestGeometry
{
    public const uint Landblock = 0xA9B4;

    /// <summary>The six outward faces of an axis-aligned box, counter-clockwise seen from outside.</summary>
    public static Polygon[] BoxFaces(Vector3 min, Vector3 max)
    {
        Vector3 P(float x, float y, float z) => new(x, y, z);
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        return
        [
            new Polygon([P(x1, y0, z0), P(x1, y1, z0), P(x1, y1, z1), P(x1, y0, z1)]), // +X
            new Polygon([P(x0, y0, z0), P(x0, y0, z1), P(x0, y1, z1), P(x0, y1, z0)]), // -X
            new Polygon([P(x0, y1, z0), P(x0, y1, z1), P(x1, y1, z1), P(x1, y1, z0)]), // +Y
            new Polygon([P(x0, y0, z0), P(x1, y0, z0), P(x1, y0, z1), P(x0, y0, z1)]), // -Y
            new Polygon([P(x0, y0, z1), P(x1, y0, z1), P(x1, y1, z1), P(x0, y1, z1)]), // +Z
            new Polygon([P(x0, y0, z0), P(x0, y1, z0), P(x1, y1, z0), P(x1, y0, z0)]), // -Z
        ];
    }

    /// <summary>
    /// A box as an explicit physics BSP: a chain of the six face planes (front = outside, an empty leaf),
    /// ending in a solid leaf that holds the faces.
    /// </summary>
    public static BspTree BoxTree(Vector3 min, Vector3 max, int[]? faceOrder = null)
    {
        var faces = BoxFaces(min, max);
        if (faceOrder is not null)
            faces = faceOrder.Select(i => faces[i]).ToArray();
        var nodes = new List<BspNodeData>();
        for (int i = 0; i < 6; i++)
        {
            int self = nodes.Count;
            nodes.Add(new BspNodeData { SplitPlane = faces[i].Plane, Front = self + 1, Back = self + 2 });
            nodes.Add(new BspNodeData { IsLeaf = true, Solid = false });
        }
        nodes.Add(new BspNodeData { IsLeaf = true, Solid = true, Polygons = [0, 1, 2, 3, 4, 5] });
        return BspTree.Create(faces, nodes);
    }

    /// <summary>
    /// The door-like setup of the seed's Holtburg door: the slab (broad faces first), the foot cylsphere and
    /// the base sphere. One definition serves the tests and the benchmark (<see cref="Bench.DoorScene"/>).
    /// </summary>
    public static PhysicsSetup DoorSetup() => Bench.DoorScene.DoorSetup();

    public static PhysicsWorld FlatWorld(float height = 0f)
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(Landblock, height));
        return world;
    }

    public static Position At(float x, float y, float z) =>
        new(LandDefs.LandCellAt(Landblock, new Vector3(x, y, z)), new Vector3(x, y, z));
}
