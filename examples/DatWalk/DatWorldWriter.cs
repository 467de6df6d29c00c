using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using DatReaderWriter;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Options;
using DatReaderWriter.Types;

/// <summary>Writes the example's world as the two retail DAT files with DatReaderWriter (a client has its own).</summary>
internal static class DatWorldWriter
{
    // The world as DAT objects: the Region's height table (index i is i / 4 m), each landblock's 81 height indices
    // (a triangle wave of the global grid, so neighbours meet) and its LandBlockInfo placing setup 0x02000001, a post;
    // and the runner's motion table 0x09000001 with the animations it plays.
public static void Write(string folder)
{
    var defs = new LandDefs { NumBlockLength = 255, NumBlockWidth = 255, SquareLength = 24, LBlockLength = 8, VertexPerCell = 1, LandHeightTable = new float[256] };
    for (int i = 0; i < 256; i++)
        defs.LandHeightTable[i] = i / 4f;
    var region = new Region { Id = 0x13000000, LandDefs = defs, GameTime = new GameTime(), TerrainInfo = new TerrainDesc { LandSurfaces = new LandSurf { TexMerge = new TexMerge() } } };
    var post = new Setup
    {
        Id = 0x02000001, Height = 6f, Radius = 0.6f, SortingSphere = new Sphere(), SelectionSphere = new Sphere(),
        CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = 0.6f, Height = 6f }],
    };
    var cells = new List<DBObj>();
    for (int x = 0x7F; x <= 0x83; x++)
        for (int y = 0x3F; y <= 0x41; y++)
        {
            uint landblock = (uint)(x << 8 | y);
            var land = new LandBlock { Id = landblock << 16 | 0xFFFF, HasObjects = true };
            for (int vx = 0; vx < 9; vx++)
                for (int vy = 0; vy < 9; vy++)
                    land.Height[vx * 9 + vy] = (byte)(Math.Abs((x * 8 + vx) % 12 - 6) + Math.Abs((y * 8 + vy) % 10 - 5));
            cells.Add(land);
            var info = new LandBlockInfo { Id = landblock << 16 | 0xFFFE };
            info.Objects.Add(new Stab { Id = post.Id, Frame = new Frame { Origin = new Vector3(96f, 100.4f, 0f), Orientation = Quaternion.Identity } });
            cells.Add(info);
        }
    Write(Path.Combine(folder, "client_portal.dat"), DatFileType.Portal, [region, post, .. RunnerMotion()]);
    Write(Path.Combine(folder, "client_cell_1.dat"), DatFileType.Cell, cells);
}

// A small motion table in the NonCombat style: standing (Ready, its default), walking at 3.12 m/s, running at 4 m/s
// (scaled by the run skill) and falling, each a cycle of one animation with no root motion; no links or modifiers.
private const uint RunnerMotionTable = 0x09000001;

private static IEnumerable<DBObj> RunnerMotion()
{
    const uint nonCombat = 0x8000003D, ready = 0x41000003, walk = 0x45000005, run = 0x44000007, falling = 0x40000015;
    var table = new MotionTable { Id = RunnerMotionTable, DefaultStyle = (MotionCommand)nonCombat };
    table.StyleDefaults[(MotionCommand)nonCombat] = (MotionCommand)ready;
    (uint Motion, uint Animation, Vector3 Velocity)[] cycles =
        [(ready, 0x03000001, Vector3.Zero), (walk, 0x03000002, new(0f, 3.12f, 0f)), (run, 0x03000003, new(0f, 4f, 0f)), (falling, 0x03000004, Vector3.Zero)];
    foreach (var (motion, animation, velocity) in cycles)
    {
        var data = new MotionData { Flags = velocity == Vector3.Zero ? 0 : MotionDataFlags.HasVelocity, Velocity = velocity };
        data.Anims.Add(new AnimData { AnimId = animation, LowFrame = 0, HighFrame = -1, Framerate = 30f });
        table.Cycles[unchecked((int)(nonCombat << 16 | motion & 0xFFFFFF))] = data;   // key: style, then command
        var frames = new Animation { Id = animation, NumParts = 1 };
        for (int i = 0; i < 4; i++)
            frames.PartFrames.Add(new AnimationFrame(1) { Frames = [new Frame { Orientation = Quaternion.Identity }] });
        yield return frames;
    }
    yield return table;
}

private static void Write(string path, DatFileType type, IEnumerable<DBObj> objects)
{
    using var dat = new DatDatabase(o => { o.FilePath = path; o.AccessType = DatAccessType.ReadWrite; });
    dat.BlockAllocator.InitNew(type, 0);
    foreach (var obj in objects)
        if (!dat.TryWriteFile(obj).Success)
            throw new InvalidOperationException($"cannot write 0x{obj.Id:X8}");
}
}
