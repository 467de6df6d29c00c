using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>
/// A 5 × 5 landblock area built procedurally: rolling terrain (a sum of sines of the global vertex
/// coordinates, so borders match), and on every landblock border, near the walk's line, a static box
/// straddling the border (homed just west of it, reaching 5 m east, where the walker slides along it) and a
/// creature-like cylinder. Where the line crosses an east-west and a south-north border close together, a
/// crate and a post share a land cell; both worlds list them crate first (the whole world registers in this
/// list's order; the streamed one loads the crate's home landblock first). A host streams it by
/// <see cref="Load"/> and <see cref="PhysicsWorld.UnloadLandblock"/>.
/// </summary>
internal sealed class StreamedLand
{
    /// <summary>The south-west landblock of the area.</summary>
    public const uint Origin = 0x8040;
    public const int Size = 5;
    private const float Block = PhysicsConstants.LandblockLength;

    public sealed record Thing(uint Id, uint Home, PhysicsSetup Setup, Position Position, PhysicsState State, ShadowFlags Flags);

    public readonly List<Thing> Things = new();

    public StreamedLand()
    {
        // A long crate whose origin sits just west of a border (its home) and whose body reaches 5 m east.
        var box = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-0.3f, -0.8f, -1f), new Vector3(5f, 0.8f, 2.5f)), name: "crate");
        var crate = new PhysicsSetup { Parts = [new SetupPart(box, Frame.Identity)] };
        var post = new PhysicsSetup { CylSpheres = [new CylSphere(new Vector3(0, 0, -0.5f), 0.7f, 2.5f)] };
        uint id = 0x7A000001;
        // The walk's line (area coordinates): from Start towards Start + Direction · t.
        for (int k = 1; k < Size; k++)
        {
            // The east-west border x = k blocks: where the line meets it, a crate a little north of the line
            // straddling the border, and a post 30 m south of it.
            float x = k * Block;
            float y = LineY(x);
            AddThing(ref id, crate, x - 0.1f, y + 1.1f, PhysicsState.Static, ShadowFlags.None);
            AddThing(ref id, post, x + 0.3f, y - 30f, PhysicsState.Gravity, ShadowFlags.IsCreature);
            // The south-north border y = k blocks.
            float yb = k * Block;
            float xb = LineX(yb);
            AddThing(ref id, post, xb + 0.9f, yb - 0.2f, PhysicsState.Gravity, ShadowFlags.IsCreature);
            AddThing(ref id, crate, xb - 30f, yb, PhysicsState.Static, ShadowFlags.None);
        }
    }

    public static readonly Vector2 Start = new(60f, 40f);
    public static readonly Vector2 Direction = Vector2.Normalize(new Vector2(4 * Block + 100f - 60f, 4 * Block + 150f - 40f));
    private static float LineY(float x) => Start.Y + (x - Start.X) * Direction.Y / Direction.X;
    private static float LineX(float y) => Start.X + (y - Start.Y) * Direction.X / Direction.Y;

    private void AddThing(ref uint id, PhysicsSetup setup, float x, float y, PhysicsState state, ShadowFlags flags)
    {
        var position = Position.Outdoor(Origin, new Vector3(x, y, 0f));
        position.Frame.Origin.Z = GroundBelow(x, y);
        Things.Add(new Thing(id++, position.CellId >> 16, setup, position, state, flags));
    }

    /// <summary>The terrain height at an area grid vertex (24 m steps from the area's south-west corner).</summary>
    public static float Height(int vx, int vy) =>
        (float)(3.0 * Math.Sin(vx * 0.61) + 2.0 * Math.Cos(vy * 0.47) + 1.2 * Math.Sin((vx + 2 * vy) * 0.83));

    /// <summary>The lowest corner height of the land cell under an area point (an object's base sits there, into the ground).</summary>
    private static float GroundBelow(float x, float y)
    {
        int cx = (int)MathF.Floor(x / 24f), cy = (int)MathF.Floor(y / 24f);
        return MathF.Min(MathF.Min(Height(cx, cy), Height(cx + 1, cy)), MathF.Min(Height(cx, cy + 1), Height(cx + 1, cy + 1)));
    }

    public static uint Landblock(int bx, int by) => (uint)((((Origin >> 8) + bx) << 8) | ((Origin & 0xFF) + by));

    public static Terrain TerrainOf(int bx, int by)
    {
        var heights = new float[81];
        for (int x = 0; x < 9; x++)
            for (int y = 0; y < 9; y++)
                heights[x * 9 + y] = Height(bx * 8 + x, by * 8 + y);
        return new Terrain(Landblock(bx, by), heights);
    }

    /// <summary>Loads a landblock and registers its objects that are not registered still.</summary>
    public void Load(PhysicsWorld world, int bx, int by)
    {
        world.LoadLandblock(TerrainOf(bx, by));
        uint lb = Landblock(bx, by);
        foreach (var t in Things)
            if (t.Home == lb && !world.Objects.Contains(t.Id))
                world.Objects.Register(t.Id, t.Setup, t.Position, 1f, t.State, t.Flags);
    }

    /// <summary>The whole area: every landblock's terrain first, then every object (no object is ever listed late).</summary>
    public PhysicsWorld Full()
    {
        var world = new PhysicsWorld();
        for (int bx = 0; bx < Size; bx++)
            for (int by = 0; by < Size; by++)
                world.Cells.AddLandblock(TerrainOf(bx, by));
        foreach (var t in Things)
            world.Objects.Register(t.Id, t.Setup, t.Position, 1f, t.State, t.Flags);
        return world;
    }

    /// <summary>The area block (0..4, 0..4) of a landblock id.</summary>
    public static (int X, int Y) BlockOf(uint landblock) => ((int)(landblock >> 8) - (int)(Origin >> 8), (int)(landblock & 0xFF) - (int)(Origin & 0xFF));

    public static MoverState StartState() =>
        MoverState.Airborne(Position.Outdoor(Origin, new Vector3(Start.X, Start.Y, GroundBelow(Start.X, Start.Y) + 6f)));

    public static Vector3 Desired => new(Direction.X * 9f, Direction.Y * 9f, 0f);
}
