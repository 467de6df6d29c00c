using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Reference;

namespace AcDream.Core.Physics.Bench;

/// <summary>
/// The synthetic Holtburg door of the apparatus tests, built in code: a 1 m × 0.261 m × 2.2 m slab (a BSP
/// part; door-local X −0.5..0.5, Y −0.009..0.252, Z 0..2.2), a foot cylinder and a base sphere, state
/// 0x10008 (HasPhysicsBsp | ReportCollisions), standing at (100, 100, 0) on a flat landblock, facing −Y.
/// Holds the engine's world and the same door as a <see cref="ReferenceScene"/> for the exact sweep.
/// </summary>
public sealed class DoorScene
{
    public const uint Landblock = 0xA9B4;
    public const uint DoorId = 0x7000_0001;
    public static readonly Vector3 DoorOrigin = new(100, 100, 0);
    public const float SlabFront = -0.009f, SlabBack = 0.252f, SlabHalfWidth = 0.5f, SlabHeight = 2.2f;
    public const float PlayerRadius = 0.48f;
    public static readonly float[] PlayerSphereHeights = [0.475f, 1.35f];

    /// <summary>The player's centre when its spheres touch the slab's front face head-on.</summary>
    public static float FrontStop => DoorOrigin.Y + SlabFront - PlayerRadius;

    /// <summary>The y of the slab's middle plane (landblock space).</summary>
    public static float SlabMidY => DoorOrigin.Y + 0.5f * (SlabFront + SlabBack);

    private DoorScene(PhysicsWorld world, ReferenceScene reference)
    {
        World = world;
        Reference = reference;
    }

    /// <summary>The engine's world: the flat landblock, the door, and any extra objects.</summary>
    public PhysicsWorld World { get; }

    /// <summary>The door as the reference sweep sees it (the slab's polygons; the retail dispatch never uses the cylinder).</summary>
    public ReferenceScene Reference { get; }

    /// <summary>The retail player.</summary>
    public static MoverDescription Player { get; } = MoverDescription.Player();

    /// <summary>Builds the scene with <paramref name="extraObjects"/> small props scattered over the landblock (most in other cells).</summary>
    /// <param name="extraObjects">Props to register besides the door.</param>
    /// <param name="seed">Seed of the props' placement.</param>
    /// <param name="nearShare">Put one prop in a hundred in the door's own cell (true), or every prop elsewhere (false).</param>
    /// <param name="allInDoorCell">Put every prop in the door's own cell (at least 4 m from the door); overrides <paramref name="nearShare"/>.</param>
    public static DoorScene Create(int extraObjects = 0, int seed = 1234, bool nearShare = true, bool allInDoorCell = false)
    {
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(Landblock, 0f));
        var door = DoorSetup();
        world.Objects.Register(DoorId, door, At(DoorOrigin), 1f, (PhysicsState)0x10008);
        var reference = new ReferenceScene();
        reference.AddObject(door, new Frame(DoorOrigin));
        AddProps(world, extraObjects, seed, nearShare, allInDoorCell);
        return new DoorScene(world, reference);
    }

    /// <summary>
    /// Registers props: one in a hundred (or all) in the door's 24 m cell (at least 4 m from the door), the
    /// rest anywhere else in the landblock. Props alternate between a barrel (a cylinder) and a rock (a sphere).
    /// </summary>
    private static void AddProps(PhysicsWorld world, int count, int seed, bool nearShare, bool allInDoorCell)
    {
        if (count <= 0)
            return;
        var rng = new Random(seed);
        var barrel = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 1.0f)], Height = 1f, Radius = 0.4f };
        var rock = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, 0.3f), 0.3f)], Height = 0.6f, Radius = 0.3f };
        const float cellMin = 96f, cellMax = 120f;
        for (int i = 0; i < count; i++)
        {
            Vector3 p;
            if (allInDoorCell || (nearShare && i % 100 == 0))
            {
                do p = new Vector3(cellMin + 1 + 22 * rng.NextSingle(), cellMin + 1 + 22 * rng.NextSingle(), 0);
                while (Vector2.Distance(new Vector2(p.X, p.Y), new Vector2(DoorOrigin.X, DoorOrigin.Y)) < 4f);
            }
            else
            {
                do p = new Vector3(1 + 190 * rng.NextSingle(), 1 + 190 * rng.NextSingle(), 0);
                while (p.X > cellMin - 2 && p.X < cellMax + 2 && p.Y > cellMin - 2 && p.Y < cellMax + 2);
            }
            world.Objects.Register(0x7100_0000u + (uint)i, (i & 1) == 0 ? barrel : rock, At(p), 1f, PhysicsState.ReportCollisions);
        }
    }

    /// <summary>The door's setup: the slab as an explicit BSP (broad faces first), a foot cylinder and a base sphere.</summary>
    public static PhysicsSetup DoorSetup()
    {
        var slab = new PhysicsModel(SlabTree(new Vector3(-SlabHalfWidth, SlabFront, 0f), new Vector3(SlabHalfWidth, SlabBack, SlabHeight)), name: "door slab");
        return new PhysicsSetup
        {
            Parts = [new SetupPart(slab, Frame.Identity)],
            CylSpheres = [new CylSphere(new Vector3(0, 0.12f, 0), 0.5f, 0.2f)],
            Spheres = [new Sphere(new Vector3(0, 0.06f, 0.1f), 0.1f)],
            Height = 2.2f,
            Radius = 0.892f,
        };
    }

    /// <summary>
    /// A box as a chain of its face planes (front of each: an empty leaf) ending in a solid leaf holding
    /// the faces, in the order front (−Y), back (+Y), +X, −X, top, bottom — the tests' door.
    /// </summary>
    private static BspTree SlabTree(Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new([a, b, c, d]);
        Polygon[] faces =
        [
            Quad(new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1)), // −Y (front)
            Quad(new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0)), // +Y (back)
            Quad(new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1)), // +X
            Quad(new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0)), // −X
            Quad(new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1)), // +Z
            Quad(new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)), // −Z
        ];
        var nodes = new List<BspNodeData>();
        for (int i = 0; i < faces.Length; i++)
        {
            int self = nodes.Count;
            nodes.Add(new BspNodeData { SplitPlane = faces[i].Plane, Front = self + 1, Back = self + 2 });
            nodes.Add(new BspNodeData { IsLeaf = true, Solid = false });
        }
        nodes.Add(new BspNodeData { IsLeaf = true, Solid = true, Polygons = [0, 1, 2, 3, 4, 5] });
        return BspTree.Create(faces, nodes, "door slab");
    }

    /// <summary>A position in the door's landblock (cell from the point).</summary>
    public static Position At(Vector3 p) => new(LandDefs.LandCellAt(Landblock, p), p);

    /// <summary>A grounded player standing at <paramref name="p"/>.</summary>
    public static MoverState Standing(Vector3 p) => MoverState.OnFloor(At(p), 0f);

    /// <summary>How deep the player's spheres at <paramref name="origin"/> reach into the slab (≤ 0 when clear).</summary>
    public static float SlabPenetration(Vector3 origin)
    {
        var min = DoorOrigin + new Vector3(-SlabHalfWidth, SlabFront, 0);
        var max = DoorOrigin + new Vector3(SlabHalfWidth, SlabBack, SlabHeight);
        float worst = float.NegativeInfinity;
        foreach (float z in PlayerSphereHeights)
        {
            var c = origin + new Vector3(0, 0, z);
            var inside = c.X > min.X && c.X < max.X && c.Y > min.Y && c.Y < max.Y && c.Z > min.Z && c.Z < max.Z;
            var closest = Vector3.Clamp(c, min, max);
            float depth = inside
                ? PlayerRadius + MathF.Min(MathF.Min(c.Y - min.Y, max.Y - c.Y), MathF.Min(c.X - min.X, max.X - c.X))
                : PlayerRadius - Vector3.Distance(c, closest);
            worst = MathF.Max(worst, depth);
        }
        return worst;
    }
}
