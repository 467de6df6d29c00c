using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// The camera arm walks a long stretch of its sub-steps in one go when a conservative test proves that
/// they touch nothing (see WorldQuery's skip): its answers must stay bit for bit the ones of the arm that
/// walks every sub-step. Checked two ways: against a table recorded from the walking arm before the skip
/// existed (origin, normal and cell as bits), and over many random arms against the walking arm itself.
/// </summary>
public class CameraArmSkipTests
{
    /// <summary>One recorded answer: the camera's cell and origin bits, placement, blocked, normal bits.</summary>
    private readonly record struct Recorded(string Name, uint Cell, uint X, uint Y, uint Z, CameraPlacement Placement, bool Blocked, uint Nx, uint Ny, uint Nz);

    // Recorded on main at 909926c (every sub-step walked), before the skip was written.
    private static readonly Recorded[] OnMain =
    [
        new("room, open, stays inside", 0xA9B40100, 0x42C60002, 0x42CCFFFD, 0x40000000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 99.000015 102.49998 2 n <0, 0, 0>
        new("room, 5 m, stops at the north wall", 0xA9B40100, 0x42C80000, 0x42CF666A, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0xBF800000, 0x00000000), // 100 103.70003 1.5 n <0, -1, 0>
        new("room, diagonal into the north-east corner", 0xA9B40100, 0x42CB6666, 0x42CF04BD, 0x40042AC7, CameraPlacement.Swept, true, 0xBF800000, 0x00000000, 0x00000000), // 101.7 103.509254 2.065111 n <-1, 0, 0>
        new("room, up into the ceiling", 0xA9B40100, 0x42C6B24F, 0x42CC87F3, 0x402CCCCD, CameraPlacement.Swept, true, 0x00000000, 0x00000000, 0xBF800000), // 99.34826 102.265526 2.7 n <0, 0, -1>
        new("room, towards the closed door", 0xA9B40100, 0x42C83333, 0x42C8CDD3, 0x3FB33333, CameraPlacement.Swept, true, 0x00000000, 0x3F800000, 0x00000000), // 100.1 100.402 1.4 n <0, 1, 0>
        new("room, through the open doorway", 0xA9B40025, 0x42C8666C, 0x42C00009, 0x3F800003, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100.20004 96.00007 1.0000004 n <0, 0, 0>
        new("room, beside the doorway into the south wall", 0xA9B40100, 0x42CA999A, 0x42C8999A, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0x3F800000, 0x00000000), // 101.3 100.3 1.5 n <0, 1, 0>
        new("room, down the stairwell portal into the cellar", 0xA9B40101, 0x42CA999D, 0x42CEFFFC, 0xBF333333, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 101.300026 103.49997 -0.7 n <0, 0, 0>
        new("cellar, up into the room", 0xA9B40100, 0x42C8CCCB, 0x42CBFFFD, 0x3FE66668, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100.39999 101.99998 1.8000002 n <0, 0, 0>
        new("outdoors, onto the door slab", 0xA9B40025, 0x42C80000, 0x42C761CB, 0x3FC00000, CameraPlacement.Swept, true, 0x00000000, 0xBF800000, 0x00000000), // 100 99.691 1.5 n <0, -1, 0>
        new("outdoors, into the ground", 0xA9B4001C, 0x42B40000, 0x42B6BE2F, 0x3E99999A, CameraPlacement.Swept, true, 0x00000000, 0x00000000, 0x3F800000), // 90 91.37145 0.3 n <0, 0, 1>
        new("outdoors, clear beside the door", 0xA9B4001D, 0x42C00000, 0x42CE0008, 0x3FC00000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 96 103.00006 1.5 n <0, 0, 0>
        new("outdoors, the door as the player", 0xA9B40025, 0x42C80000, 0x42CE0008, 0x3FC00000, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 100 103.00006 1.5 n <0, 0, 0>
        new("outdoors, grazing the trunk", 0xA9B40025, 0x42C962AB, 0x42C6D9D0, 0x3FB509DE, CameraPlacement.Swept, true, 0x3F4509C9, 0xBF237019, 0x00000000), // 100.69271 99.425415 1.4143636 n <0.76968056, -0.6384292, 0>
        new("outdoors, onto the boulder", 0xA9B40025, 0x42C5F2D3, 0x42C67475, 0x3F4D7572, CameraPlacement.Swept, true, 0xBF49FDBE, 0xBF1821DD, 0x3E1F90DA), // 98.974266 99.227455 0.8025733 n <-0.78902805, -0.5942667, 0.155826>
        new("outdoors, over the sloped ground", 0xA9B40002, 0x419FFFF7, 0x41F00014, 0x413FFFE7, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 19.999983 30.000038 11.999976 n <0, 0, 0>
        new("outdoors, into the slope", 0xA9B4000A, 0x4219F101, 0x4219F101, 0x4041E01A, CameraPlacement.Swept, true, 0x3D4C6B6D, 0x3D0F1801, 0x3F7F8647), // 38.485355 38.485355 3.029303 n <0.049907137, 0.034935, 0.99814266>
        new("outdoors, across a landblock's cells downhill", 0xA9B4000B, 0x421FFFDB, 0x4247FFFD, 0x421FFFDB, CameraPlacement.Swept, false, 0x00000000, 0x00000000, 0x00000000), // 39.99986 49.99999 39.99986 n <0, 0, 0>
    ];

    [Fact]
    public void TheHandPickedArms_GiveTheAnswersRecordedBeforeTheSkip_BitForBit()
    {
        Assert.Equal(CameraArmCases.Table.Length, OnMain.Length);
        for (int i = 0; i < OnMain.Length; i++)
        {
            var arm = CameraArmCases.Table[i];
            var expected = OnMain[i];
            Assert.Equal(expected.Name, arm.Name);
            var r = CameraArmCases.QueryFor(arm.World).CameraArm(new Position(arm.Cell, arm.Pivot), arm.Desired, arm.Player);
            var o = r.Camera.Origin;
            var got = new Recorded(arm.Name, r.Camera.CellId, Bits(o.X), Bits(o.Y), Bits(o.Z), r.Placement, r.Blocked, Bits(r.Normal.X), Bits(r.Normal.Y), Bits(r.Normal.Z));
            Assert.True(expected == got, $"{arm.Name}: expected {expected}, got {got} ({o}, n {r.Normal})");
        }
    }

    [Fact]
    public void InTheCottageRoom_TheArmToTheNorthWall_PassesOverTheSubStepsMoreThanACentimetreShortOfIt()
    {
        // From y 101 towards 106 in 17 sub-steps of 0.3 m: the wall's face is at y 104, so a sphere 1 cm wider
        // than the camera's (0.31 m) stays clear of it up to a centre at 103.69: sub-steps 1-8 (y 101.3 .. 103.4)
        // are passed over, the 9th (103.7) is walked and the 10th meets the wall.
        var counter = new ShortcutCounter();
        WorldQuery Query(CameraArmCases.Scene scene) => new(CameraArmCases.WorldOf(scene), Shortcuts.All, counter);
        var q = Query(CameraArmCases.Scene.Cottage);
        q.CameraArm(new Position(CameraArmCases.Room, new Vector3(100, 101, 1.5f)), new Vector3(100, 106, 1.5f));
        Assert.Equal(8, counter.ViewerSubSteps);
        // The two walked sub-steps (the 9th, centre y 103.7, and the 10th, backed off from the wall) are still more than
        // 1 cm in front of the wall's split (y 104), far from the doorway's portal (y 100) and outside the cellar's
        // cell: their cell searches are passed over too, one each.
        Assert.Equal(2, counter.ViewerCellSearches);
        // Outdoors nothing is passed over in a land cell with a building (the cottage's), nor along a cell's
        // border; over the sloped landblock's cell 0xA9B40001 (ground below 2.2 m there), up to 0.31 m short of its
        // north edge: 25.18 m in 84 sub-steps of 0.2979 m northwards, y <= 24 - 0.31 for the first 62.
        counter.Clear();
        q.CameraArm(new Position(CameraArmCases.Land, new Vector3(100, 97, 1.5f)), new Vector3(101, 90, 1.5f));
        Assert.Equal(0, counter.ViewerSubSteps);
        Query(CameraArmCases.Scene.Door).CameraArm(new Position(CameraArmCases.Land, new Vector3(96, 97, 1.5f)), new Vector3(96, 103, 1.5f));
        Assert.Equal(0, counter.ViewerSubSteps);
        Query(CameraArmCases.Scene.Slope).CameraArm(new Position(0xA9B40001, new Vector3(5, 5, 9)), new Vector3(5, 30, 12));
        Assert.Equal(62, counter.ViewerSubSteps);
    }

    /// <summary>
    /// An observer watches the path the engine runs without one: the camera's skip is taken, and the observer is
    /// told every sub-step as the walk tells it (the same steps, check origins and offsets, bit for bit), then how
    /// many were passed over. Went red with the passed sub-steps' reports left out, and with their origins taken
    /// one sub-step late.
    /// </summary>
    [Fact]
    public void AnObserver_SeesTheSkippingPath_ToldEverySubStepAsTheWalkTellsIt()
    {
        var world = CameraArmCases.WorldOf(CameraArmCases.Scene.Cottage);
        var viewer = new MoverDescription(0, [new Sphere(Vector3.Zero, WorldQuery.ViewerRadius)], 0f, 0f, PhysicsState.None, WorldQuery.ViewerFlags);
        var room = new Position(CameraArmCases.Room, new Vector3(100, 101, 1.5f));
        var target = new Position(CameraArmCases.Room, new Vector3(100, 106, 1.5f));
        var skipping = new Physics.Diagnostics.TransitionEventLog();
        var walking = new Physics.Diagnostics.TransitionEventLog();
        new PhysicsEngine(world, Shortcuts.All) { Observer = skipping }.Resolve(viewer, MoverState.Airborne(room), target);
        new PhysicsEngine(world, Shortcuts.None) { Observer = walking }.Resolve(viewer, MoverState.Airborne(room), target);
        static string Steps(Physics.Diagnostics.TransitionEventLog log) => string.Join("; ", log.Events
            .Where(e => e.Kind == Physics.Diagnostics.TransitionEventKind.SubStep)
            .Select(e => $"{e.Index} {Bits(e.Vector.X):X8} {Bits(e.Vector.Y):X8} {Bits(e.Vector.Z):X8} {Bits(e.Vector2.X):X8} {Bits(e.Vector2.Y):X8} {Bits(e.Vector2.Z):X8}"));
        Assert.Equal(10, walking.Events.Count(e => e.Kind == Physics.Diagnostics.TransitionEventKind.SubStep));
        Assert.Equal(Steps(walking), Steps(skipping));
        var passed = skipping.Events.Where(e => e.Kind == Physics.Diagnostics.TransitionEventKind.ShortcutSkip).ToArray();
        Assert.Equal([(Physics.Diagnostics.ShortcutSkip.ViewerSubSteps, 8), (Physics.Diagnostics.ShortcutSkip.ViewerCellSearches, 1), (Physics.Diagnostics.ShortcutSkip.ViewerCellSearches, 1)],
            passed.Select(e => (e.Shortcut, e.Index)).ToArray());
        Assert.DoesNotContain(walking.Events, e => e.Kind == Physics.Diagnostics.TransitionEventKind.ShortcutSkip);
    }

    [Fact]
    public void RandomArms_PassingOverClearSubSteps_AnswerAsWalkingEverySubStep_BitForBit()
    {
        // 12,000 arms (1,200 per world, fixed seed) in the built-in scenes, the furnished cottage, the open one with
        // a barrel at the doorway, a barrel at a land cell's border and a sloped landblock: pivots in the room, the cellar and outdoors, arms of every length (none, under a sub-step,
        // up to 15 m), a fifth of them along an axis (parallel to walls, floors, portals), the door or the
        // creature as the player now and then. Each arm is swung by a query that passes over the clear
        // sub-steps and by one that walks every sub-step; the viewer transitions under them are also run
        // through two engines and their whole results compared.
        var random = new Random(2512);
        int passed = 0, indoor = 0, searches = 0;
        foreach (var scene in Enum.GetValues<CameraArmCases.Scene>())
        {
            var world = CameraArmCases.WorldOf(scene);
            var (skipped, walked) = (new ShortcutCounter(), new ShortcutCounter());
            var skipping = new WorldQuery(world, Shortcuts.All, skipped);
            var walking = new WorldQuery(world, Shortcuts.None, walked);
            var fast = new PhysicsEngine(world, Shortcuts.All);
            var slow = new PhysicsEngine(world, Shortcuts.None);
            for (int n = 0; n < 1200; n++)
            {
                var (cell, pivot) = RandomPivot(random, scene);
                var desired = pivot + RandomArm(random);
                uint player = random.Next(20) switch { 0 or 1 => CameraArmCases.Door, 2 => 0x7000_0102, _ => 0u };
                var from = new Position(cell, pivot);
                string what = $"{scene} arm {n}: {from} -> {desired}, player 0x{player:X8}";

                skipped.Clear();
                var a = skipping.CameraArm(from, desired, player);
                int steps = skipped.ViewerSubSteps;
                searches += skipped.ViewerCellSearches;
                var b = walking.CameraArm(from, desired, player);
                Assert.Equal(0, walked.ViewerSubSteps);
                Assert.Equal(0, walked.ViewerCellSearches);
                Assert.True(Same(a, b), $"{what}: passing over {steps} sub-steps gave {Show(a)}, walking gave {Show(b)}");
                passed += steps > 0 ? 1 : 0;

                if (!skipping.TryFindCell(from, out var start))
                    continue;
                indoor += !LandDefs.IsLandCell(start.CellId) ? 1 : 0;
                var viewer = new MoverDescription(player, [new Sphere(Vector3.Zero, WorldQuery.ViewerRadius)], 0f, 0f, PhysicsState.None, WorldQuery.ViewerFlags);
                var target = new Position(start.CellId, desired - LandDefs.BlockOffset(cell, start.CellId));
                var x = fast.Resolve(viewer, MoverState.Airborne(start), target);
                var y = slow.Resolve(viewer, MoverState.Airborne(start), target);
                Assert.True(Same(x, y), $"{what}: the viewer transitions differ: {x.Next.Position} {x.CollisionNormal} against {y.Next.Position} {y.CollisionNormal}");
            }
        }
        // The skip must have happened for the comparison to mean anything: in a 4 m room many arms are short or
        // meet a wall within a sub-step or two, but a good share of those starting indoors pass over some.
        Assert.True(passed > indoor / 4, $"only {passed} of 12,000 arms ({indoor} starting indoors) passed over sub-steps");
        // And the walked sub-steps' cell searches passed over where the proof keeps the room alone.
        Assert.True(searches > passed / 2, $"only {searches} cell searches passed over in {passed} arms that passed over sub-steps");
    }

    private static (uint Cell, Vector3 Pivot) RandomPivot(Random random, CameraArmCases.Scene scene)
    {
        float U(float lo, float hi) => lo + (float)random.NextDouble() * (hi - lo);
        Vector3 InRoom() => new(U(98.05f, 101.95f), U(100.05f, 103.95f), U(0.05f, 2.95f));
        Vector3 Around() => new(U(94, 106), U(94, 106), U(0.2f, 3.5f));
        switch (scene)
        {
            case CameraArmCases.Scene.Cottage or CameraArmCases.Scene.OpenCottage or CameraArmCases.Scene.FurnishedCottage or CameraArmCases.Scene.BarrelAtTheDoorway:
                return random.Next(4) == 0 ? (CameraArmCases.Land, Around()) : (CameraArmCases.Room, InRoom());
            case CameraArmCases.Scene.CellarStair:
                return random.Next(2) == 0 ? (CameraArmCases.Room, InRoom())
                    : (CameraArmCases.Cellar, new Vector3(U(100.55f, 101.95f), U(101.05f, 103.95f), U(-1.15f, -0.05f)));
            case CameraArmCases.Scene.Slope:
                return (0xA9B40001, new Vector3(U(2, 190), U(2, 190), U(0, 15)));
            default:
                return (CameraArmCases.Land, Around());
        }
    }

    private static Vector3 RandomArm(Random random)
    {
        float length = random.Next(10) switch { 0 => (float)random.NextDouble() * 0.5f, < 7 => (float)random.NextDouble() * 6, _ => 6 + (float)random.NextDouble() * 9 };
        if (random.Next(50) == 0)
            return Vector3.Zero;
        Vector3 direction;
        if (random.Next(5) == 0)
        {
            direction = Vector3.Zero;
            direction[random.Next(3)] = random.Next(2) == 0 ? -1 : 1;
        }
        else
        {
            do direction = new Vector3((float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1, (float)random.NextDouble() * 2 - 1);
            while (direction.LengthSquared() is > 1 or < 1e-4f);
            direction = Vector3.Normalize(direction);
        }
        return direction * length;
    }

    private static bool Same(in CameraArmResult a, in CameraArmResult b) =>
        a.Camera.CellId == b.Camera.CellId && SameBits(a.Camera.Origin, b.Camera.Origin) && SameBits(a.Camera.Frame.Orientation, b.Camera.Frame.Orientation)
        && a.Placement == b.Placement && a.Blocked == b.Blocked && SameBits(a.Normal, b.Normal);

    private static bool Same(MoveResult a, MoveResult b) =>
        a.Succeeded == b.Succeeded && a.LastState == b.LastState && a.CollisionNormalValid == b.CollisionNormalValid && SameBits(a.CollisionNormal, b.CollisionNormal)
        && a.CollidedWithEnvironment == b.CollidedWithEnvironment && a.VelocityKilled == b.VelocityKilled && a.LastCollidedObject == b.LastCollidedObject
        && a.CollidedObjects.Span.SequenceEqual(b.CollidedObjects.Span)
        && a.Next.Position.CellId == b.Next.Position.CellId && SameBits(a.Next.Position.Origin, b.Next.Position.Origin)
        && SameBits(a.Next.Position.Frame.Orientation, b.Next.Position.Frame.Orientation)
        && a.Next.Contact == b.Next.Contact && a.Next.OnWalkable == b.Next.OnWalkable && a.Next.ContactPlaneCellId == b.Next.ContactPlaneCellId
        && SameBits(a.Next.ContactPlane.Normal, b.Next.ContactPlane.Normal) && Bits(a.Next.ContactPlane.D) == Bits(b.Next.ContactPlane.D)
        && a.Next.SlidingNormalValid == b.Next.SlidingNormalValid && SameBits(a.Next.SlidingNormal, b.Next.SlidingNormal);

    private static bool SameBits(Vector3 a, Vector3 b) => Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z);

    private static bool SameBits(Quaternion a, Quaternion b) => Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z) && Bits(a.W) == Bits(b.W);

    private static string Show(in CameraArmResult r) => $"{r.Placement} {r.Camera} blocked {r.Blocked} n {r.Normal}";

    private static uint Bits(float f) => (uint)BitConverter.SingleToInt32Bits(f);
}
