using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>Hand-picked camera arms in the built-in scenes and a sloped landblock, shared by the camera-arm tests.</summary>
internal static class CameraArmCases
{
    public const uint Land = 0xA9B40025, Room = 0xA9B40100, Cellar = 0xA9B40101, Door = 0x7000_0001;

    /// <summary>The worlds the arms are swung in.</summary>
    public enum Scene { Cottage, OpenCottage, CellarStair, Door, Trunk, Boulder, Slope, FurnishedCottage, BarrelAtTheDoorway, BarrelAtACellBorder }

    public readonly record struct Arm(string Name, Scene World, uint Cell, Vector3 Pivot, Vector3 Desired, uint Player = 0);

    public static readonly Arm[] Table =
    [
        new("room, open, stays inside", Scene.Cottage, Room, new(100, 101, 1.5f), new(99, 102.5f, 2f)),
        new("room, 5 m, stops at the north wall", Scene.Cottage, Room, new(100, 101, 1.5f), new(100, 106, 1.5f)),
        new("room, diagonal into the north-east corner", Scene.Cottage, Room, new(99.2f, 101.3f, 1.6f), new(103.5f, 105.1f, 2.4f)),
        new("room, up into the ceiling", Scene.Cottage, Room, new(99.5f, 102, 1.6f), new(99.1f, 102.7f, 4.5f)),
        new("room, towards the closed door", Scene.Cottage, Room, new(100.1f, 102.5f, 1.4f), new(100.1f, 97, 1.4f)),
        new("room, through the open doorway", Scene.OpenCottage, Room, new(100, 102.5f, 1.2f), new(100.2f, 96, 1.0f)),
        new("room, beside the doorway into the south wall", Scene.OpenCottage, Room, new(101.3f, 102, 1.5f), new(101.3f, 97, 1.5f)),
        new("room, down the stairwell portal into the cellar", Scene.CellarStair, Room, new(101.25f, 101.5f, 1.2f), new(101.3f, 103.5f, -0.7f)),
        new("cellar, up into the room", Scene.CellarStair, Cellar, new(101.2f, 103.5f, -0.6f), new(100.4f, 102, 1.8f)),
        new("outdoors, onto the door slab", Scene.Door, Land, new(100, 97, 1.5f), new(100, 103, 1.5f)),
        new("outdoors, into the ground", Scene.Door, Land, new(90, 90, 1.5f), new(90, 94, -2)),
        new("outdoors, clear beside the door", Scene.Door, Land, new(96, 97, 1.5f), new(96, 103, 1.5f)),
        new("outdoors, the door as the player", Scene.Door, Land, new(100, 97, 1.5f), new(100, 103, 1.5f), Door),
        new("outdoors, grazing the trunk", Scene.Trunk, Land, new(100.5f, 96, 1.5f), new(100.95f, 104, 1.3f)),
        new("outdoors, onto the boulder", Scene.Boulder, Land, new(97, 97.5f, 1.0f), new(101, 101, 0.6f)),
        new("outdoors, over the sloped ground", Scene.Slope, 0xA9B40001, new(5, 5, 9), new(20, 30, 12)),
        new("outdoors, into the slope", Scene.Slope, 0xA9B40001, new(30, 30, 20), new(40, 40, 0)),
        new("outdoors, across a landblock's cells downhill", Scene.Slope, 0xA9B40001, new(60, 70, 60), new(40, 50, 40)),
    ];

    private static readonly Dictionary<Scene, PhysicsWorld> Worlds = new();

    /// <summary>A query over a scene's world (worlds are built once and never modified).</summary>
    public static WorldQuery QueryFor(Scene scene) => new(WorldOf(scene));

    public static PhysicsWorld WorldOf(Scene scene)
    {
        lock (Worlds)
        {
            if (!Worlds.TryGetValue(scene, out var world))
                Worlds[scene] = world = Build(scene);
            return world;
        }
    }

    /// <summary>
    /// The cottage with things in its room, one of each kind the viewer treats apart: a table (a BSP box), a
    /// standing creature (a cylinder the viewer ignores), an ethereal sphere that ignores collisions (passed
    /// untested), an ethereal sphere (tested, passed through), a static sphere, a lamp with two rows.
    /// </summary>
    private static PhysicsWorld Furnished()
    {
        var world = SceneLibrary.Load("cottage").World;
        static Position In(float x, float y, float z) => new(Room, new Vector3(x, y, z));
        static PhysicsSetup Ball(float r) => new() { Spheres = [new Sphere(Vector3.Zero, r)] };
        var table = new PhysicsSetup { Parts = [new SetupPart(new PhysicsModel(BspShapes.Box(new Vector3(-0.4f, -0.4f, 0), new Vector3(0.4f, 0.4f, 0.8f)), name: "table"), Frame.Identity)] };
        world.Objects.Register(0x7000_0101, table, In(99, 103, 0), 1f, PhysicsState.Static);
        world.Objects.Register(0x7000_0102, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 1.8f)] }, In(101, 102, 0), 1f,
            PhysicsState.None, ShadowFlags.IsCreature);
        world.Objects.Register(0x7000_0103, Ball(0.5f), In(99.2f, 101, 1.5f), 1f, PhysicsState.Ethereal | PhysicsState.IgnoreCollisions);
        world.Objects.Register(0x7000_0104, Ball(0.3f), In(101.3f, 103.2f, 2.2f), 1f, PhysicsState.Ethereal);
        world.Objects.Register(0x7000_0105, Ball(0.25f), In(100.8f, 100.8f, 2.5f), 1f, PhysicsState.Static);
        world.Objects.Register(0x7000_0106, new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.15f), new Sphere(new Vector3(0, 0, 0.5f), 0.1f)] },
            In(98.5f, 101.5f, 2.0f), 1f, PhysicsState.Static);
        return world;
    }

    private static PhysicsWorld Build(Scene scene)
    {
        switch (scene)
        {
            case Scene.Cottage: return SceneLibrary.Load("cottage").World;
            case Scene.OpenCottage:
                var open = SceneLibrary.Load("cottage").World;
                Assert.True(open.Objects.Unregister(Door));
                return open;
            case Scene.BarrelAtACellBorder:
                // The door scene with the same scaled barrel 0.3 m east of the border x = 96 between land cells
                // 0xA9B4001D and 0xA9B40025: listed in 0025 only, its side reaches 0.3 m into 001D, where a camera
                // meets it only once the cell search adds 0025 (its sphere within its radius of the border).
                var border = SceneLibrary.Load("door").World;
                border.Objects.Register(0x7000_0202, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.2f, 0.7f)] },
                    new Position(Land, new Vector3(96.3f, 101, 0)), 3f, PhysicsState.Static);
                Assert.Equal([Land], border.Objects.CellsOf(0x7000_0202));
                return border;
            case Scene.CellarStair: return SceneLibrary.Load("cellar").World;
            case Scene.Door: return SceneLibrary.Load("door").World;
            case Scene.Trunk: return SceneLibrary.Load("trunk").World;
            case Scene.Boulder: return SceneLibrary.Load("boulder").World;
            case Scene.FurnishedCottage: return Furnished();
            case Scene.BarrelAtTheDoorway:
                // The open cottage with a barrel (a cylinder scaled 3x) just outside the doorway: retail lists a
                // cylinder object by its unscaled feet, so it is listed outdoors only, yet its scaled side reaches
                // 0.1 m into the room. A camera in the room meets it only once the sphere nears the doorway's
                // portal plane and the cell search adds the outside cells.
                var barrel = SceneLibrary.Load("cottage").World;
                Assert.True(barrel.Objects.Unregister(Door));
                barrel.Objects.Register(0x7000_0201, new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.2f, 0.7f)] },
                    new Position(Land, new Vector3(100, 99.5f, 0)), 3f, PhysicsState.Static);
                Assert.Equal([Land], barrel.Objects.CellsOf(0x7000_0201));
                return barrel;
            default:
                // A landblock rising to the north-east with a ripple: every triangle its own slope.
                var heights = new float[Terrain.VerticesPerSide * Terrain.VerticesPerSide];
                for (int x = 0; x < Terrain.VerticesPerSide; x++)
                    for (int y = 0; y < Terrain.VerticesPerSide; y++)
                        heights[x * Terrain.VerticesPerSide + y] = 0.25f * x * 24 * 0.1f + 0.15f * y * 24 * 0.1f + (x * 7 + y * 3) % 5 * 0.6f;
                var world = new PhysicsWorld();
                world.Cells.AddLandblock(new Terrain(0xA9B4, heights));
                return world;
        }
    }
}
