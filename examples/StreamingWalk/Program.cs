// A streaming walk: a runner crosses three landblocks of rolling land while only the 3 × 3 landblocks around it
// are loaded; it brushes a post in each landblock (contact start and end events), is drawn at 144 frames a
// second between the 30 Hz quanta (smooth frames), and is saved and restored at the end (snapshots). The
// README's "A client's world" section is made of the regions marked "client-world" below (a test checks that
// they are the same text).
// Exit code: 0 when the runner reaches the third landblock having started and ended contacts, and the
// snapshot round-trips; 1 otherwise.

#region client-world
using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics;

// The host's data: rolling terrain from the global grid (neighbouring landblocks meet), and in every
// landblock a post just beside the runner's line.
static Terrain Land(uint landblock)
{
    var heights = new float[81];
    int gx = (int)(landblock >> 8) * 8, gy = (int)(landblock & 0xFF) * 8;
    for (int x = 0; x < 9; x++)
        for (int y = 0; y < 9; y++)
            heights[x * 9 + y] = 2f * MathF.Sin((gx + x) * 0.5f) + 1.5f * MathF.Cos((gy + y) * 0.4f);
    return new Terrain(landblock, heights);
}
var post = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.6f, 12f)], Height = 12f, Radius = 0.6f };
uint PostId(uint landblock) => 0x7A00_0000 | landblock;

// Streaming: keep the 3 × 3 landblocks around the player loaded. A landblock's objects are registered after
// its cells; one still registered (it straddles into a loaded neighbour) is not registered again.
var world = new PhysicsWorld();
var loaded = new HashSet<uint>();
void Stream(uint centre)
{
    foreach (uint lb in new List<uint>(loaded))
        if (Math.Abs((int)(lb >> 8) - (int)(centre >> 8)) > 1 || Math.Abs((int)(lb & 0xFF) - (int)(centre & 0xFF)) > 1)
        {
            world.UnloadLandblock(lb);                                // its cells, buildings and the objects' rows
            loaded.Remove(lb);
        }
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++)
        {
            uint lb = (uint)((((int)(centre >> 8) + dx) << 8) | ((int)(centre & 0xFF) + dy));
            if (!loaded.Add(lb))
                continue;
            world.LoadLandblock(Land(lb));                            // env cells and buildings would go here too
            if (!world.Objects.Contains(PostId(lb)))
                world.Objects.Register(PostId(lb), post, Position.Outdoor(lb, new Vector3(96f, 100.9f, -6f)));
        }
}
#endregion

#region client-world
const uint start = 0x8040;
Stream(start);
var engine = new PhysicsEngine(world);
var player = MoverDescription.Player();
var state = engine.Place(player, Position.Outdoor(start, new Vector3(20f, 100f, 5f))).Next;
var body = BodyState.Creature();
var contacts = new ContactTracker(world);                             // the player's collision records
double now = 0;                                                       // the host's clock, seconds
int starts = 0, ends = 0, frame = 0;
while (state.Position.CellId >> 16 != start + 0x200 && frame < 144 * 90)
{
    var before = state;
    var steer = new Vector3(8f, 100f - state.Position.Origin.Y, 0f);  // east along y = 100, 8 m/s
    var step = engine.Step(player, state, body, 1.0 / 144, desiredVelocity: steer);
    now += 1.0 / 144;
    contacts.Track(step, before, now);                                // after every step of this mover
    foreach (var e in contacts.Events)
    {
        Console.WriteLine($"{now,7:F3} s  {e}");                      // ObjectStart 0x7A008140 … ObjectEnd …
        if (e.Kind == ContactEventKind.ObjectStart) starts++;
        if (e.Kind == ContactEventKind.ObjectEnd) ends++;
    }
    state = step.Next;
    body = step.Body;
    var drawn = step.SmoothPose;                                      // what to draw this frame, between quanta
    if (frame++ % 720 == 0)
        Console.WriteLine($"{now,7:F3} s  drawn at {drawn.Origin} in 0x{state.Position.CellId:X8}, " +
            $"on {state.Ground} ({state.GroundState}), {loaded.Count} landblocks loaded");
    if (step.Quanta > 0 && state.Position.CellId >> 16 != before.Position.CellId >> 16)
        Stream(state.Position.CellId >> 16);                          // the player crossed into another landblock
}
#endregion

#region client-world
// Snapshots: the player's state in 175 bytes; a world's objects by the host's setup keys.
byte[] saved = Snapshot.SaveMover(state, body);
Snapshot.LoadMover(saved, out var restored, out var restoredBody);
byte[] objects = Snapshot.SaveObjects(world, setup => 1u);            // key 1: the post's setup
Console.WriteLine($"{frame} frames, {starts} contacts started, {ends} ended; snapshot {saved.Length} + {objects.Length} bytes");
#endregion

bool across = state.Position.CellId >> 16 == start + 0x200;
bool same = restored.Position.CellId == state.Position.CellId && restored.Position.Origin == state.Position.Origin
    && restoredBody.Velocity == body.Velocity && restoredBody.PendingTime == body.PendingTime;
Console.WriteLine(across ? "the runner crossed two landblock borders" : "the runner did NOT cross the landblocks");
return across && starts > 0 && ends > 0 && same ? 0 : 1;
