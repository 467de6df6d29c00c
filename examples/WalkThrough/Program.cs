// A walk through a small world built in code: a flat landblock, a door, trees, a rock and a cottage with
// an indoor cell. The player bumps into the door, goes round it, passes the trees, and walks through the
// cottage's doorway into its room, printing where it is. The README's "Using the library" section is
// made of the regions marked "readme" below (a test checks that they are the same text).
// Exit code: 0 when the walk ends inside the cottage, the replay matches and the runner lands, 1 otherwise.

#region readme
using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Scenes;

const uint landblock = 0xA9B4;                                        // landblock x 0xA9, y 0xB4: 192 m × 192 m
var world = new PhysicsWorld();
world.Cells.AddLandblock(Terrain.Flat(landblock, 0f));                // outdoor cells 0xA9B40001..0xA9B40040, ground at z = 0

// A door: a BSP slab 1 m × 0.26 m × 2.2 m (door space, facing -Y) and a foot cylinder, standing at (100, 90).
var slab = new PhysicsModel(BspShapes.Slab(new Vector3(0f, 0.12f, 1.1f), new Vector3(1f, 0.26f, 2.2f), Quaternion.Identity), name: "door");
var door = new PhysicsSetup
{
    Parts = [new SetupPart(slab, Frame.Identity)],
    CylSpheres = [new CylSphere(new Vector3(0f, 0.12f, 0f), 0.5f, 0.2f)],
    Height = 2.2f,
    Radius = 0.9f,
};
world.Objects.Register(0x7000_0001, door, Position.Outdoor(landblock, new Vector3(100f, 90f, 0f)), 1f,
    PhysicsState.HasPhysicsBsp | PhysicsState.ReportCollisions);     // state 0x10008: retail collides it through the slab only

// Trees are cylinders (cylspheres); a rock is a sphere.
var tree = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.3f, 6f)], Height = 6f, Radius = 0.3f };
var rock = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0f, 0f, 0.3f), 0.6f)], Height = 0.9f, Radius = 0.6f };
world.Objects.Register(0x7000_0010, tree, Position.Outdoor(landblock, new Vector3(102.2f, 95f, 0f)), 1f, PhysicsState.ReportCollisions);
world.Objects.Register(0x7000_0011, tree, Position.Outdoor(landblock, new Vector3(94f, 100f, 0f)), 1f, PhysicsState.ReportCollisions);
world.Objects.Register(0x7000_0020, rock, Position.Outdoor(landblock, new Vector3(102.6f, 98.5f, 0f)), 1f, PhysicsState.ReportCollisions);
#endregion

// A cottage: one room (env cell 0xA9B40100) spanning x -2..2, y 0..4, z 0..3 in its own space, placed at
// (100, 110, 0), with a doorway 1.2 m wide and 2.2 m high in its south wall that is a portal to the outside;
// and the building standing in the outdoor cell, whose shell is the outer walls and roof.
const uint roomId = (landblock << 16) | 0x0100;
var roomOrigin = new Vector3(100f, 110f, 0f);
var doorway = Quad(new(-0.6f, 0f, 0f), new(-0.6f, 0f, 2.2f), new(0.6f, 0f, 2.2f), new(0.6f, 0f, 0f));
var room = new EnvCell(roomId, new Frame(roomOrigin), BspCompiler.Compile(RoomSurfaces(), "room"),
    BspShapes.CellBox(new Vector3(-2f, 0f, 0f), new Vector3(2f, 4f, 3f)), [new CellPortal(doorway, CellPortal.Outside, portalSide: true)]);
world.Cells.AddEnvCell(room);
var shell = new PhysicsModel(BspCompiler.Compile(ShellSurfaces(), "shell"), name: "cottage shell");
world.Cells.AddBuilding(new Building(shell, Position.Outdoor(landblock, roomOrigin), [roomId]));

#region readme
var engine = new PhysicsEngine(world);                                // one engine per thread, reused every frame
var player = MoverDescription.Player();                               // the retail player: two spheres, steps up 0.6 m
var state = engine.Place(player, Position.Outdoor(landblock, new Vector3(100f, 84f, 0f))).Next;

// The walk: legs towards waypoints (landblock-local), at most 0.1 m a frame (3 m/s at 30 frames a second).
(string Name, Vector3 Waypoint, int Frames)[] legs =
[
    ("north into the door", new Vector3(100f, 92f, 0f), 70),
    ("east round the door", new Vector3(102f, 89.5f, 0f), 25),
    ("north past a tree", new Vector3(102f, 100.5f, 0f), 120),
    ("west to the cottage", new Vector3(100f, 100.5f, 0f), 30),
    ("north into the cottage", new Vector3(100f, 113f, 0f), 130),
];
Console.WriteLine("frame leg                           x         y        z  cell        hit");
int frame = 0;
foreach (var (name, waypoint, frames) in legs)
{
    for (int i = 0; i < frames; i++, frame++)
    {
        var toWaypoint = (waypoint - state.Position.Origin) with { Z = 0f };
        var target = state.Position;                                  // where the player asks to be this frame
        target.Frame.Origin += toWaypoint.Length() > 0.1f ? Vector3.Normalize(toWaypoint) * 0.1f : toWaypoint;
        var result = engine.Resolve(player, state, target);
        string hit = result.CollidedObjects.Length > 0 ? $"0x{result.CollidedObjects.Span[0]:X8}" : "-";
        if (i % 10 == 0 || hit != "-" || result.Position.CellId != state.Position.CellId)
            Console.WriteLine($"{frame,5} {name,-25} {result.Position.Origin.X,9:F3} {result.Position.Origin.Y,9:F3} " +
                $"{result.Position.Origin.Z,8:F3}  0x{result.Position.CellId:X8}  {hit}");
        state = result.Next;                                          // resolved position, ground contact, sliding normal
    }
}
#endregion

bool inside = state.Position.CellId == roomId;
Console.WriteLine($"{frame} frames: the player ends at {state.Position} ({(inside ? "inside the cottage" : "NOT inside the cottage")}), " +
    $"global {state.Position.ToGlobal()}.");

#region readme
// The same library runs scene files and replays recordings (the acdream-physics tool is built on this).
var scene = SceneLibrary.Load("door");                                // or SceneLoader.LoadFile("my-scene.json")
var trajectory = SceneRunner.Run(scene);                              // every mover, every frame
var path = Path.Combine(Path.GetTempPath(), "door.trajectory.json");
File.WriteAllText(path, trajectory.ToJson());
var replay = TrajectoryReplay.Replay(scene, Trajectory.LoadFile(path));
Console.WriteLine(replay.Matches ? "door scene: replay matches" : replay.FirstDifference!.ToString());
#endregion

#region readme
// A player moves the retail way, by motion commands through its motion table (retail CMotionInterp and
// CSequence): here it holds run forward for one second, jumps once (extent 0.5) and runs on until it lands.
var motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill: 200, jumpSkill: 200));
var body = BodyState.Creature();                                      // retail friction 0.95, elasticity 0.05
var runner = engine.Place(player, Position.Outdoor(landblock, new Vector3(60f, 40f, 0f))).Next;
motion.Place(player, runner, ref body);                               // enters the table's default: Ready
motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), player, ref runner, ref body);
int stepped = 0, airborne = 0;
for (; stepped <= 30 || !runner.OnWalkable; stepped++)                // 1 s of running, the jump, until it lands
{
    if (stepped == 30 && motion.ChargeJump(player, runner, body) == MotionError.None)
        motion.Jump(0.5f, staminaOk: true, player, ref runner, ref body);  // leaves the ground with the run's speed
    var step = engine.Step(player, runner, body, motion, 1.0 / 30);   // elapsed seconds, at any frame rate
    runner = step.Next;                                               // position, heading, contact, walkable ground
    body = step.Body;                                                 // velocity, time carried to the next call
    airborne += runner.Contact ? 0 : 1;
}
Console.WriteLine($"ran and jumped: {runner.Position} after {stepped} frames, {airborne} in the air, standing: {runner.OnWalkable}");
#endregion

File.Delete(path);
bool landed = runner.Contact && runner.OnWalkable && runner.Position.Origin.Y > 55f;
return inside && replay.Matches && landed ? 0 : 1;

static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d) => new([a, b, c, d]);

// The room's floor, ceiling and walls (cell space), facing into the room; the south wall has the doorway.
static Polygon[] RoomSurfaces() =>
[
    Quad(new(-2, 0, 0), new(2, 0, 0), new(2, 4, 0), new(-2, 4, 0)),              // floor
    Quad(new(-2, 0, 3), new(-2, 4, 3), new(2, 4, 3), new(2, 0, 3)),              // ceiling
    Quad(new(-2, 4, 0), new(2, 4, 0), new(2, 4, 3), new(-2, 4, 3)),              // north wall
    Quad(new(2, 0, 0), new(2, 0, 3), new(2, 4, 3), new(2, 4, 0)),                // east wall
    Quad(new(-2, 0, 0), new(-2, 4, 0), new(-2, 4, 3), new(-2, 0, 3)),            // west wall
    Quad(new(-2, 0, 0), new(-2, 0, 3), new(-0.6f, 0, 3), new(-0.6f, 0, 0)),      // south wall, west of the doorway
    Quad(new(0.6f, 0, 0), new(0.6f, 0, 3), new(2, 0, 3), new(2, 0, 0)),          // south wall, east of the doorway
    Quad(new(-0.6f, 0, 2.2f), new(-0.6f, 0, 3), new(0.6f, 0, 3), new(0.6f, 0, 2.2f)), // above the doorway
];

// The outer walls 0.2 m outside the room's and a flat roof, facing out; a gap at the doorway.
static Polygon[] ShellSurfaces() =>
[
    Quad(new(-2.2f, -0.2f, 0), new(-0.6f, -0.2f, 0), new(-0.6f, -0.2f, 3.2f), new(-2.2f, -0.2f, 3.2f)),
    Quad(new(0.6f, -0.2f, 0), new(2.2f, -0.2f, 0), new(2.2f, -0.2f, 3.2f), new(0.6f, -0.2f, 3.2f)),
    Quad(new(-0.6f, -0.2f, 2.2f), new(0.6f, -0.2f, 2.2f), new(0.6f, -0.2f, 3.2f), new(-0.6f, -0.2f, 3.2f)),
    Quad(new(-2.2f, 4.2f, 0), new(-2.2f, 4.2f, 3.2f), new(2.2f, 4.2f, 3.2f), new(2.2f, 4.2f, 0)),
    Quad(new(2.2f, -0.2f, 0), new(2.2f, 4.2f, 0), new(2.2f, 4.2f, 3.2f), new(2.2f, -0.2f, 3.2f)),
    Quad(new(-2.2f, -0.2f, 0), new(-2.2f, -0.2f, 3.2f), new(-2.2f, 4.2f, 3.2f), new(-2.2f, 4.2f, 0)),
    Quad(new(-2.2f, -0.2f, 3.2f), new(2.2f, -0.2f, 3.2f), new(2.2f, 4.2f, 3.2f), new(-2.2f, 4.2f, 3.2f)),
];
