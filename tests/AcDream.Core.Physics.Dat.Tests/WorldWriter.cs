using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using DrwCylSphere = DatReaderWriter.Types.CylSphere;
using DrwFrame = DatReaderWriter.Types.Frame;
using DrwSphere = DatReaderWriter.Types.Sphere;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// Small worlds written as the DAT objects retail stores them in: the Region (its height table), LandBlocks,
/// LandBlockInfos placing static objects, and Setups made of a cylinder-sphere (a post).
/// </summary>
internal static class WorldWriter
{
    /// <summary>The height table: entry i is i / 4 metres.</summary>
    public static float TableHeight(int index) => index / 4f;

    /// <summary>The Region object holding the given land definitions (the rest of a region is not read by physics).</summary>
    public static Region Region(DatReaderWriter.Types.LandDefs defs) =>
        new() { Id = DatWorld.RegionId, LandDefs = defs, GameTime = new GameTime(), TerrainInfo = new TerrainDesc { LandSurfaces = new LandSurf { TexMerge = new TexMerge() } } };

    public static Region Region()
    {
        var defs = new DatReaderWriter.Types.LandDefs { NumBlockLength = 255, NumBlockWidth = 255, SquareLength = 24, LBlockLength = 8, VertexPerCell = 1, LandHeightTable = new float[256] };
        for (int i = 0; i < 256; i++)
            defs.LandHeightTable[i] = TableHeight(i);
        return Region(defs);
    }

    /// <summary>
    /// A landblock of rolling land: the height index of a vertex is a triangle wave of its global grid coordinates, so
    /// neighbouring landblocks meet. <paramref name="hasObjects"/> is the flag saying a LandBlockInfo is written beside
    /// it (retail's lbi_exists): set it exactly when one is.
    /// </summary>
    public static LandBlock Land(uint landblock, bool hasObjects = false)
    {
        var land = new LandBlock { Id = landblock << 16 | 0xFFFF, HasObjects = hasObjects };
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                land.Height[x * 9 + y] = HeightIndex(landblock, x, y);
        return land;
    }

    public static byte HeightIndex(uint landblock, int x, int y)
    {
        int gx = (int)(landblock >> 8) * 8 + x, gy = (int)(landblock & 0xFF) * 8 + y;
        return (byte)(Math.Abs(gx % 12 - 6) + 2 * Math.Abs(gy % 10 - 5));
    }

    public static LandBlockInfo Info(uint landblock, uint numCells, params (uint Model, Vector3 Origin)[] objects)
    {
        var info = new LandBlockInfo { Id = landblock << 16 | 0xFFFE, NumCells = numCells };
        foreach (var (model, origin) in objects)
            info.Objects.Add(new Stab { Id = model, Frame = new DrwFrame { Origin = origin, Orientation = Quaternion.Identity } });
        return info;
    }

    public static Setup Post(uint id, float radius = 0.6f, float height = 4f) => new()
    {
        Id = id,
        CylSpheres = [new DrwCylSphere { Origin = Vector3.Zero, Radius = radius, Height = height }],
        Height = height,
        Radius = radius,
        SortingSphere = new DrwSphere(),
        SelectionSphere = new DrwSphere(),
    };

    /// <summary>The landblocks x0..x1 × y0..y1, each with a post at (96, 100.9) in its info, and the portal side (region, post setup).</summary>
    public static TempDats Grid(int x0, int x1, int y0, int y1, uint postId = 0x02000001)
    {
        var cell = new List<DBObj>();
        for (int x = x0; x <= x1; x++)
            for (int y = y0; y <= y1; y++)
            {
                uint lb = (uint)(x << 8 | y);
                cell.Add(Land(lb, hasObjects: true));
                cell.Add(Info(lb, 0, (postId, new Vector3(96f, 100.9f, 0f))));
            }
        return new TempDats([Region(), Post(0x02000001)], cell);
    }
}
