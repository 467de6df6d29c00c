// A walk through a world loaded from DAT files. First the example writes its own small world as the two retail
// DAT files (a client has them already): 5 × 3 landblocks of rolling land, a post in each, and the Region that
// holds the height table. Then, as a client would, it opens them, keeps the 3 × 3 landblocks around a player
// loaded and runs the player east by motion commands across two landblock borders. The README's "The retail DAT
// files" section is made of the regions marked "dat-readme" below (a test checks that they are the same text).
// Exit code: 0 when the runner reaches the third landblock having brushed a post; 1 otherwise.

#region dat-readme
using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Dat;
#endregion

string folder = Path.Combine(Path.GetTempPath(), "acdream-datwalk-" + Guid.NewGuid().ToString("N"));
Directory.CreateDirectory(folder);
DatWorldWriter.Write(folder);
try
{
    return Walk(folder);
}
finally
{
    Directory.Delete(folder, recursive: true);
}

static int Walk(string folder)
{
#region dat-readme
    // Open the client's two DAT files (read-only; the client may hold them open too) and make a world that
    // loads landblocks from them: terrain, indoor cells, buildings and static objects, whole or not at all.
    using var files = DatFiles.Open(folder);                            // client_portal.dat, client_cell_1.dat
    var dats = new DatWorld(files);                                     // models and setups cached in files.Converted
    const uint start = 0x8040;
    dats.StreamAround(start);                                           // the 3 × 3 landblocks around the player
    var engine = new PhysicsEngine(dats.World);

    // A player runs east by motion commands; each time it crosses into another landblock the window follows.
    var player = MoverDescription.Player();
    var table = DatMotionTables.Load(files, 0x09000001);                // the runner's motion table and its animations
    var motion = new ObjectMotion(table, new RetailSkills(runSkill: 200, jumpSkill: 200));
    var body = BodyState.Creature();
    var at = Position.Outdoor(start, new Vector3(40f, 100f, 6f));
    at.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -MathF.PI / 2);  // face east (forward is +Y)
    var runner = engine.Place(player, at).Next;
    motion.Place(player, runner, ref body);
    motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), player, ref runner, ref body);
    int frames = 0, brushed = 0;
    while (runner.Position.CellId >> 16 != start + 0x200 && frames < 30 * 60)
    {
        var step = engine.Step(player, runner, body, motion, 1.0 / 30);
        if (step.Move.CollisionNormalValid && MathF.Abs(step.Move.CollisionNormal.Z) < 0.5f)
            brushed++;                                                  // a post (static: reported as environment)
        if (step.Next.Position.CellId >> 16 != runner.Position.CellId >> 16)
            dats.StreamAround(step.Next.Position.CellId >> 16);          // load ahead, unload behind
        runner = step.Next;
        body = step.Body;
        frames++;
    }
    Console.WriteLine($"{frames} frames: {runner.Position} with {dats.Loaded.Count} landblocks loaded, {brushed} frames against a post");
#endregion
    return runner.Position.CellId >> 16 == start + 0x200 && brushed > 0 ? 0 : 1;
}
