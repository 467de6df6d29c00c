using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Random small scenes and motions from one integer seed (System.Random with a seed is a fixed
/// algorithm, so a case seed reproduces its case on any machine). A scene is flat or random 9×9 terrain
/// in one landblock, with up to six objects (boxes and rotated slabs as BSP parts, cylinders, spheres)
/// around the landblock's centre; a motion is one mover (one or two spheres) started grounded or in the
/// air, then a few frames of random offsets and headings.
/// <see cref="Features"/> add kinds of scene the classic generator never makes; their random draws come
/// from a second generator, so <c>Make(seed)</c> (no features) gives exactly the classic case.
/// </summary>
internal sealed class SceneFuzzer
{
    /// <summary>What a case may contain beyond the classic generator.</summary>
    [Flags]
    public enum Features
    {
        /// <summary>The classic cases.</summary>
        None = 0,
        /// <summary>Terrain heights 0–30 m per vertex (slopes up to ~50°, many too steep to walk).</summary>
        SteepTerrain = 1,
        /// <summary>Objects registered at a scale of 0.25–3.</summary>
        ScaledObjects = 2,
        /// <summary>An ethereal mover: only static objects stop it.</summary>
        EtherealMover = 4,
        /// <summary>An airborne, path-clipped missile mover; some objects are missiles (ignored by every mover).</summary>
        MissileMover = 8,
        /// <summary>Boxes and slabs 24–40 m long along one axis (longer than a land cell).</summary>
        LargeObjects = 16,
        /// <summary>A random room (an env cell with a doorway portal and its building) near the centre; the mover may start inside.</summary>
        IndoorCell = 32,
        /// <summary>Every feature.</summary>
        All = SteepTerrain | ScaledObjects | EtherealMover | MissileMover | LargeObjects | IndoorCell,
    }

    public const uint MoverId = 0x5000_0001;
    public static readonly Vector3 Centre = new(96, 96, 0);

    /// <summary>A closed solid placed in the world: its box in its own space, and where that space is.</summary>
    public readonly record struct Solid(uint Id, Vector3 HalfSize, Vector3 Origin, Quaternion Rotation);

    public sealed class Case
    {
        public required int Seed;
        public required PhysicsWorld World;
        public required MoverDescription Mover;
        public required MoverState Start;
        public required List<Position> Targets;
        public readonly List<Solid> Solids = new();
        public readonly List<string> Description = new();
        /// <summary>The room, when the case has one.</summary>
        public FuzzRoom? Room;
        public override string ToString() => $"case seed {Seed}: " + string.Join("; ", Description);
    }

    /// <summary>The seed of case <paramref name="index"/> of a run with seed <paramref name="seed"/>.</summary>
    public static int CaseSeed(int seed, int index) => unchecked(seed * 1_000_003 + index);

    public static Case Make(int seed) => Make(seed, Features.None);

    public static Case Make(int seed, Features features)
    {
        var rng = new Random(seed);
        var extra = new Random(unchecked(~seed * 7919 + 1));
        float R(float lo, float hi) => lo + (float)rng.NextDouble() * (hi - lo);
        float X(float lo, float hi) => lo + (float)extra.NextDouble() * (hi - lo);
        bool Has(Features f) => (features & f) != 0;
        Quaternion AnyRotation()
        {
            var q = new Quaternion(R(-1, 1), R(-1, 1), R(-1, 1), R(-1, 1));
            return q.LengthSquared() < 1e-3f ? Quaternion.Identity : Quaternion.Normalize(q);
        }
        Quaternion Heading(float yaw) => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);

        var world = new PhysicsWorld();
        var desc = new List<string>();
        bool flat = rng.Next(2) == 0;
        if (flat)
        {
            float h = R(-5, 5);
            world.Cells.AddLandblock(Terrain.Flat(TestGeometry.Landblock, h));
            desc.Add($"flat terrain {h}");
        }
        else
        {
            var heights = new float[81];
            float top = Has(Features.SteepTerrain) && extra.Next(2) == 0 ? 30f : 6f;
            for (int i = 0; i < heights.Length; i++)
                heights[i] = R(0, 6) * (top / 6f);
            world.Cells.AddLandblock(new Terrain(TestGeometry.Landblock, heights));
            desc.Add(top > 6f ? "steep random terrain (0-30 m)" : "random terrain");
        }

        var c = new Case
        {
            Seed = seed, World = world, Mover = null!, Start = default, Targets = new(),
        };
        c.Description.AddRange(desc);
        bool etherealMover = Has(Features.EtherealMover) && extra.Next(2) == 0;
        bool missileMover = !etherealMover && Has(Features.MissileMover) && extra.Next(2) == 0;
        var passable = new HashSet<uint>(); // solids this mover may pass through
        if (Has(Features.IndoorCell) && extra.Next(2) == 0)
            c.Room = FuzzRoom.Add(world, extra, c.Description);

        int objects = rng.Next(0, 7);
        for (int i = 0; i < objects; i++)
        {
            uint id = 0x7000_0000u + (uint)i;
            var xy = Centre + new Vector3(R(-4, 4), R(-4, 4), 0);
            var at = new Vector3(xy.X, xy.Y, Ground(world, xy) + R(-0.5f, 1.5f));
            var pos = new Position(LandDefs.LandCellAt(TestGeometry.Landblock, at), new Frame(at, AnyRotation()));
            var state = rng.Next(6) switch
            {
                0 => PhysicsState.Ethereal,
                1 => PhysicsState.Static,
                2 => PhysicsState.ReportCollisions,
                _ => PhysicsState.None,
            };
            if (Has(Features.MissileMover) && extra.Next(4) == 0)
                state |= PhysicsState.Missile;
            if (etherealMover && (state & PhysicsState.Static) == 0)
                passable.Add(id);
            if ((state & PhysicsState.Missile) != 0)
                passable.Add(id); // missile objects are ignored by every mover
            float scale = Has(Features.ScaledObjects) && extra.Next(2) == 0 ? X(0.25f, 3f) : 1f;
            int kind = rng.Next(4);
            PhysicsSetup setup;
            switch (kind)
            {
                case 0:
                case 1:
                {
                    // A box (kind 0) or a thin slab (kind 1), as a BSP part with its own rotation inside the object.
                    var half = kind == 0 ? new Vector3(R(0.2f, 2f), R(0.2f, 2f), R(0.2f, 2f)) : new Vector3(R(0.5f, 2f), R(0.02f, 0.2f), R(0.5f, 2f));
                    if (Has(Features.LargeObjects) && extra.Next(2) == 0)
                    {
                        // Longer than a land cell along X or Y (scaled objects are then kept at scale 1).
                        if (extra.Next(2) == 0) half.X = X(12f, 20f); else half.Y = X(12f, 20f);
                        scale = 1f;
                    }
                    var partRotation = rng.Next(2) == 0 ? Quaternion.Identity : AnyRotation();
                    var partOrigin = new Vector3(R(-0.5f, 0.5f), R(-0.5f, 0.5f), R(-0.5f, 0.5f));
                    var model = new PhysicsModel(BspShapes.Box(-half, half));
                    setup = new PhysicsSetup { Parts = [new SetupPart(model, new Frame(partOrigin, partRotation))] };
                    if ((state & PhysicsState.Ethereal) == 0)
                    {
                        var objFrame = pos.Frame;
                        c.Solids.Add(new Solid(id, half * scale, objFrame.LocalToGlobal(partOrigin * scale), Quaternion.Normalize(objFrame.Orientation * partRotation)));
                    }
                    c.Description.Add($"{(kind == 0 ? "box" : "slab")} 0x{id:X8} half {half} at {at} rot {pos.Frame.Orientation} part {partOrigin} {partRotation} {state} scale {scale}");
                    break;
                }
                case 2:
                    setup = new PhysicsSetup { CylSpheres = [new CylSphere(Vector3.Zero, R(0.1f, 1.5f), R(0.1f, 3f))] };
                    c.Description.Add($"cylinder 0x{id:X8} {setup.CylSpheres[0]} at {at} {state}");
                    break;
                default:
                    setup = new PhysicsSetup { Spheres = [new Sphere(new Vector3(0, 0, R(0, 1)), R(0.1f, 1.5f))] };
                    c.Description.Add($"sphere 0x{id:X8} {setup.Spheres[0]} at {at} {state}");
                    break;
            }
            world.Objects.Register(id, setup, pos, scale, state);
        }
        c.Solids.RemoveAll(solid => passable.Contains(solid.Id));

        // The mover: one or two spheres, started clear of every solid (a few tries, then no solids are checked).
        float radius = R(0.2f, 0.6f);
        var spheres = rng.Next(2) == 0
            ? new[] { new Sphere(new Vector3(0, 0, radius), radius) }
            : new[] { new Sphere(new Vector3(0, 0, radius), radius), new Sphere(new Vector3(0, 0, radius + R(0.3f, 1.2f)), radius) };
        var flags = rng.Next(3) == 0 ? PhysicsState.Gravity : PhysicsState.Gravity | PhysicsState.EdgeSlide;
        var info = ObjectInfoState.IsPlayer;
        if (etherealMover)
            flags |= PhysicsState.Ethereal;
        if (missileMover)
        {
            flags = PhysicsState.Missile;
            info = extra.Next(2) == 0 ? ObjectInfoState.PathClipped : ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip;
        }
        c.Mover = new MoverDescription(MoverId, spheres, R(0f, 1f), R(0f, 0.5f), flags, info);
        bool grounded = rng.Next(3) != 0 && !missileMover;
        MoverState start = default;
        for (int attempt = 0; attempt < 20; attempt++)
        {
            var xy = Centre + new Vector3(R(-6, 6), R(-6, 6), 0);
            float ground = Ground(world, xy);
            var at = new Vector3(xy.X, xy.Y, grounded ? ground : ground + R(0.05f, 3f));
            var position = new Position(LandDefs.LandCellAt(TestGeometry.Landblock, at), new Frame(at, Heading(R(0, MathF.Tau))));
            start = grounded ? OnGround(world, position) : MoverState.Airborne(position);
            if (Penetration.Worst(c, start.Position) <= PhysicsConstants.Epsilon)
                break;
        }
        if (c.Room is { } room && extra.Next(2) == 0)
            start = room.StartInside(extra, grounded);
        c.Start = start;
        c.Description.Add($"mover r={radius} spheres={spheres.Length} {flags} {info} {(grounded ? "grounded" : "airborne")} at {start.Position}");

        int frames = rng.Next(1, 6);
        for (int i = 0; i < frames; i++)
        {
            float length = R(0, 3f);
            float yaw = R(0, MathF.Tau);
            float climb = grounded ? 0f : R(-1.5f, 0.5f);
            var offset = new Vector3(MathF.Cos(yaw) * length, MathF.Sin(yaw) * length, climb);
            if (rng.Next(10) == 0)
                offset = Vector3.Zero;
            c.Targets.Add(new Position(0, new Frame(offset, Heading(R(0, MathF.Tau))))); // an offset; made absolute per frame
            c.Description.Add($"frame {i} offset {offset}");
        }
        return c;
    }

    /// <summary>Terrain height under a landblock-local point.</summary>
    public static float Ground(PhysicsWorld world, Vector3 xy)
    {
        var cell = (LandCell)world.Cells.Get(LandDefs.LandCellAt(TestGeometry.Landblock, xy))!;
        var plane = cell.FindTerrainPolygon(xy)!.Plane;
        return -(plane.Normal.X * xy.X + plane.Normal.Y * xy.Y + plane.D) / plane.Normal.Z;
    }

    private static MoverState OnGround(PhysicsWorld world, Position position)
    {
        var cell = (LandCell)world.Cells.Get(position.CellId)!;
        var plane = cell.FindTerrainPolygon(position.Origin)!.Plane;
        return new MoverState
        {
            Position = position,
            Contact = true,
            OnWalkable = plane.Normal.Z >= PhysicsConstants.FloorZ,
            ContactPlane = plane,
            ContactPlaneCellId = position.CellId,
        };
    }

    /// <summary>One frame's target: the current position moved by the case's offset, heading replaced, same cell label.</summary>
    public static Position TargetFor(in MoverState state, Position offset)
    {
        var target = state.Position;
        target.Frame.Origin += offset.Frame.Origin;
        target.Frame.Orientation = offset.Frame.Orientation;
        return target;
    }
}
