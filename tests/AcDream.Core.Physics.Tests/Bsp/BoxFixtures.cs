using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Bsp;

/// <summary>Hand-built trees around the axis-aligned box [-1, 1]³.</summary>
internal static class BoxFixtures
{
    public const uint Cell = 0xA9B40001;

    // Faces in the order +X, -X, +Y, -Y, +Z, -Z; vertices counter-clockwise seen from outside.
    public static readonly Vector3[] Normals =
    {
        Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitZ,
    };

    public static Polygon[] Faces() => new[]
    {
        new Polygon(new Vector3[] { new(1, -1, -1), new(1, 1, -1), new(1, 1, 1), new(1, -1, 1) }),
        new Polygon(new Vector3[] { new(-1, -1, -1), new(-1, -1, 1), new(-1, 1, 1), new(-1, 1, -1) }),
        new Polygon(new Vector3[] { new(-1, 1, -1), new(-1, 1, 1), new(1, 1, 1), new(1, 1, -1) }),
        new Polygon(new Vector3[] { new(-1, -1, -1), new(1, -1, -1), new(1, -1, 1), new(-1, -1, 1) }),
        new Polygon(new Vector3[] { new(-1, -1, 1), new(1, -1, 1), new(1, 1, 1), new(-1, 1, 1) }),
        new Polygon(new Vector3[] { new(-1, -1, -1), new(-1, 1, -1), new(1, 1, -1), new(1, -1, -1) }),
    };

    /// <summary>
    /// A physics tree: a chain of the 6 face planes (front = outside = empty), ending in a solid leaf
    /// that holds the 6 faces.
    /// </summary>
    public static BspTree SolidBox(out Polygon[] faces)
    {
        faces = Faces();
        var nodes = new List<BspNodeData>();
        for (int i = 0; i < 6; i++)
            nodes.Add(new BspNodeData { SplitPlane = new Plane(Normals[i], -1f), Front = -1, Back = i + 1 });
        nodes.Add(new BspNodeData { IsLeaf = true, Solid = true, Polygons = new[] { 0, 1, 2, 3, 4, 5 } });
        return BspTree.Create(faces, nodes);
    }

    /// <summary>A cell tree: a chain of the 6 face planes facing inward (front = inside), no leaves.</summary>
    public static BspTree CellBox()
    {
        var nodes = new List<BspNodeData>();
        for (int i = 0; i < 6; i++)
            nodes.Add(new BspNodeData
            {
                SplitPlane = new Plane(-Normals[i], 1f),
                Front = i < 5 ? i + 1 : -1,
                Bounds = new Sphere(Vector3.Zero, 2f),
            });
        return BspTree.Create(Array.Empty<Polygon>(), nodes);
    }

    /// <summary>
    /// A transition whose path has one sphere (or two, stacked 1 m apart) of radius <paramref name="radius"/>,
    /// moving from <paramref name="from"/> to <paramref name="to"/>, with the tested space the landblock itself.
    /// </summary>
    public static Transition MakeTransition(Vector3 from, Vector3 to, float radius, bool twoSpheres = false, Shortcuts? shortcuts = null)
    {
        var t = shortcuts is { } taken ? new Transition(new PhysicsWorld(), taken) : new Transition(new PhysicsWorld());
        var path = t.SpherePath;
        Span<Sphere> spheres = stackalloc Sphere[2];
        spheres[0] = new Sphere(Vector3.Zero, radius);
        spheres[1] = new Sphere(new Vector3(0, 0, 1f), radius);
        path.InitSphere(twoSpheres ? spheres : spheres[..1], 1f);
        path.InitPath(null, new Position(Cell, from), new Position(Cell, to));
        path.SetCheckPos(new Position(Cell, to), null);
        path.WalkableAllowance = PhysicsConstants.FloorZ;
        path.WalkInterp = 1f;
        path.CacheLocalSpaceSphere(new Position(Cell, Vector3.Zero), 1f);
        return t;
    }
}
