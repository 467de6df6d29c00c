using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Bench.Server;

/// <summary>
/// The server bench's world: a 3 × 3 landblock group (0xA8B3..0xAAB5) of rolling terrain (heights up to
/// ±3 m, flat under each building), in each landblock the cottage's building (its shell and its room, an
/// indoor cell behind a doorway) at (100, 100), 60 trees (an upright cylinder, 0.4 m × 6 m) and 40 rocks
/// (a 0.8 m sphere) at fixed-seed random places. One world, shared read-only by every engine.
/// </summary>
internal sealed class ServerWorld
{
    /// <summary>The south-west landblock's x and y bytes.</summary>
    public const int FirstX = 0xA8, FirstY = 0xB3, Side = 3;

    /// <summary>The group's extent on X and Y, metres (from the south-west landblock's corner).</summary>
    public const float Extent = Side * PhysicsConstants.LandblockLength;

    /// <summary>The world.</summary>
    public PhysicsWorld World { get; } = new();

    /// <summary>Trees and rocks registered.</summary>
    public int Props { get; private set; }

    public ServerWorld()
    {
        var cottage = SceneLibrary.Load("cottage").World;
        var room = (EnvCell)cottage.Cells.Get(0xA9B40100)!;
        var building = ((LandCell)cottage.Cells.Get(0xA9B40025)!).Building!;
        var tree = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, 0.4f, 6f)], Height = 6f, Radius = 0.4f };
        var rock = new PhysicsSetup { Spheres = [new Sphere(Vector3.Zero, 0.8f)], Height = 0.8f, Radius = 0.8f };
        var rng = new Random(2025);
        Span<float> heights = stackalloc float[Terrain.VerticesPerSide * Terrain.VerticesPerSide];
        uint id = 0x7200_0000;
        for (int bx = 0; bx < Side; bx++)
            for (int by = 0; by < Side; by++)
            {
                uint block = (uint)(((FirstX + bx) << 8) | (FirstY + by));
                for (int x = 0; x < Terrain.VerticesPerSide; x++)
                    for (int y = 0; y < Terrain.VerticesPerSide; y++)
                        heights[x * Terrain.VerticesPerSide + y] = VertexHeight(bx * 8 + x, by * 8 + y);
                World.Cells.AddLandblock(new Terrain(block, heights));
                // The cottage's room and shell, moved to this landblock (same local place, flat ground).
                uint roomId = (block << 16) | 0x100;
                var portals = new List<CellPortal>();
                foreach (var p in room.Portals)
                    portals.Add(new CellPortal(p.Polygon, p.LeadsOutside ? CellPortal.Outside : (block << 16) | (p.OtherCellId & 0xFFFF), p.PortalSide));
                World.Cells.AddEnvCell(new EnvCell(roomId, room.Position.Frame, room.PhysicsBsp, room.CellBsp, portals));
                var at = building.Position.Frame;
                World.Cells.AddBuilding(new Building(building.Shell, new Position(LandDefs.LandCellAt(block, at.Origin), at), [roomId]));
                for (int i = 0; i < 100; i++)
                {
                    Vector3 p;
                    do p = new Vector3(2 + 188 * rng.NextSingle(), 2 + 188 * rng.NextSingle(), 0);
                    while (p.X > 92 && p.X < 108 && p.Y > 92 && p.Y < 110);
                    p.Z = GroundAt(bx * PhysicsConstants.LandblockLength + p.X, by * PhysicsConstants.LandblockLength + p.Y);
                    World.Objects.Register(id++, i < 60 ? tree : rock, new Position(LandDefs.LandCellAt(block, p), p), 1f);
                    Props++;
                }
            }
    }

    /// <summary>The landblock id of a group cell index (0..8, column-major).</summary>
    public static uint Block(int index) => (uint)(((FirstX + index / Side) << 8) | (FirstY + index % Side));

    /// <summary>A position in the group's frame (metres from the south-west corner) as a retail position.</summary>
    public static Position At(Vector3 group)
    {
        int bx = Math.Clamp((int)(group.X / PhysicsConstants.LandblockLength), 0, Side - 1);
        int by = Math.Clamp((int)(group.Y / PhysicsConstants.LandblockLength), 0, Side - 1);
        uint block = (uint)(((FirstX + bx) << 8) | (FirstY + by));
        var local = group - new Vector3(bx * PhysicsConstants.LandblockLength, by * PhysicsConstants.LandblockLength, 0);
        return new Position(LandDefs.LandCellAt(block, local), local);
    }

    /// <summary>A retail position in the group's frame.</summary>
    public static Vector3 InGroup(in Position p)
    {
        uint block = p.CellId >> 16;
        return p.Origin + new Vector3(((int)(block >> 8) - FirstX) * PhysicsConstants.LandblockLength,
            ((int)(block & 0xFF) - FirstY) * PhysicsConstants.LandblockLength, 0);
    }

    /// <summary>
    /// The height of terrain vertex (gx, gy) of the group (24 m apart): rolling hills from one formula, so
    /// landblock edges agree; 0 around each landblock's building (its cell's four vertices).
    /// </summary>
    private static float VertexHeight(int gx, int gy)
    {
        int lx = gx % 8, ly = gy % 8;
        if ((lx == 4 || lx == 5) && (ly == 4 || ly == 5))
            return 0f;
        return 3f * MathF.Sin(gx * 0.9f) * MathF.Cos(gy * 0.7f);
    }

    /// <summary>The terrain height at a group point, bilinear over its land cell's vertices (within a few centimetres of the triangles on these hills: enough to stand a prop on).</summary>
    public static float GroundAt(float gx, float gy)
    {
        float fx = gx / PhysicsConstants.LandCellLength, fy = gy / PhysicsConstants.LandCellLength;
        int cx = (int)fx, cy = (int)fy;
        float u = fx - cx, v = fy - cy;
        return (1 - u) * ((1 - v) * VertexHeight(cx, cy) + v * VertexHeight(cx, cy + 1))
            + u * ((1 - v) * VertexHeight(cx + 1, cy) + v * VertexHeight(cx + 1, cy + 1));
    }

    /// <summary>The highest of the four vertex heights of the land cell under a group point (a safe height to place something on or above).</summary>
    public static float GroundBelow(float gx, float gy)
    {
        int cx = (int)(gx / PhysicsConstants.LandCellLength), cy = (int)(gy / PhysicsConstants.LandCellLength);
        return MathF.Max(MathF.Max(VertexHeight(cx, cy), VertexHeight(cx + 1, cy)), MathF.Max(VertexHeight(cx, cy + 1), VertexHeight(cx + 1, cy + 1)));
    }
}
