using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.World;

/// <summary>
/// Loading and unloading landblocks (PhysicsWorld.LoadLandblock / UnloadLandblock): cells, buildings and the
/// objects' rows go together, engines and queries see it, and a walk streamed through a 3 × 3 window is the
/// walk through the whole area, bit for bit.
/// </summary>
public class LandblockStreamingTests
{
    private const uint Lb = TestGeometry.Landblock;
    private const uint East = Lb + 0x100;

    private static PhysicsSetup Crate(float half = 1f)
    {
        var model = new PhysicsModel(TestGeometry.BoxTree(new Vector3(-half, -half, 0), new Vector3(half, half, 2)), name: "crate");
        return new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] };
    }

    [Fact]
    public void Unload_TakesTheLandCellsEnvCellsAndBuildingsOut()
    {
        var world = Cottage.Build();
        var outdoor = LandDefs.LandCellAt(Lb, Cottage.RoomOrigin);
        Assert.NotNull(((LandCell)world.Cells.Get(outdoor)!).Building);

        world.UnloadLandblock(Lb);

        Assert.False(world.Cells.HasLandblock(Lb));
        Assert.Null(world.Cells.Get(outdoor));
        Assert.Null(world.Cells.Get(Cottage.RoomId));
        Assert.Null(world.Cells.Get((Lb << 16) | 1));
        Assert.Empty(world.Cells.CellIds);
    }

    [Fact]
    public void Unload_DropsTheRowsInTheLandblocksEnvCells_AndUnregistersAnObjectIndoors()
    {
        // A small crate on the cottage room's floor is listed in the room (an env cell); unloading the landblock
        // takes that row out too, so the crate, left with no row, is unregistered.
        var world = Cottage.Build();
        world.Objects.Register(77, Crate(0.2f), new Position(Cottage.RoomId, Cottage.RoomOrigin), 1f, PhysicsState.Static);
        Assert.Contains(Cottage.RoomId, world.Objects.CellsOf(77));

        world.UnloadLandblock(Lb);

        Assert.False(world.Objects.Contains(77), "the crate indoors stayed registered after its landblock was unloaded");
    }

    [Fact]
    public void Unload_AnUnknownLandblock_ThrowsNamingIt()
    {
        var world = TestGeometry.FlatWorld();
        var ex = Assert.Throws<ArgumentException>(() => world.UnloadLandblock(0x1234));
        Assert.StartsWith("landblock 0x1234", ex.Message);
        world.UnloadLandblock(Lb);
        ex = Assert.Throws<ArgumentException>(() => world.UnloadLandblock(Lb));
        Assert.Contains($"0x{Lb:X4}", ex.Message);
    }

    [Fact]
    public void Load_TwiceOrWithACellOfAnotherLandblock_ThrowsAndLeavesTheWorld()
    {
        var world = TestGeometry.FlatWorld();
        Assert.Throws<ArgumentException>(() => world.LoadLandblock(Terrain.Flat(Lb, 0)));
        var stray = new EnvCell((Lb << 16) | 0x100, Frame.Identity, null, AcDream.Core.Physics.Scenes.BspShapes.CellBox(Vector3.Zero, Vector3.One));
        var ex = Assert.Throws<ArgumentException>(() => world.LoadLandblock(Terrain.Flat(East, 0), [stray]));
        Assert.StartsWith("envCells[0]", ex.Message);
        Assert.False(world.Cells.HasLandblock(East));
        Assert.Null(world.Cells.Get((East << 16) | 1));
    }

    [Fact]
    public void Unload_AnObjectStraddlingTheBorder_KeepsItsOtherRows_AndOneInside_IsUnregistered()
    {
        var world = TestGeometry.FlatWorld();
        world.LoadLandblock(Terrain.Flat(East, 0));
        // A crate across the border x = 192 (home: the west block), and one well inside the east block.
        world.Objects.Register(1, Crate(), TestGeometry.At(191.5f, 100, 0), 1f, PhysicsState.Static);
        world.Objects.Register(2, Crate(), Position.Outdoor(East, new Vector3(100, 100, 0)), 1f, PhysicsState.Static);
        Assert.Contains(world.Objects.CellsOf(1), c => c >> 16 == East);

        world.UnloadLandblock(East);

        Assert.True(world.Objects.Contains(1));
        Assert.All(world.Objects.CellsOf(1), c => Assert.Equal(Lb, c >> 16));
        Assert.NotEmpty(world.Objects.CellsOf(1));
        Assert.False(world.Objects.Contains(2));
        Assert.Equal(1, world.Objects.Count);
        // Every listed row is in a loaded cell, and each cell's rows are the objects that list that cell.
        foreach (uint cell in world.Cells.CellIds)
            foreach (var row in world.Objects.RowsInCell(cell).ToArray())
                Assert.Contains(cell, world.Objects.CellsOf(row.EntityId));
    }

    [Fact]
    public void Unload_ThenLoadAgain_ListsTheStraddlersAsIfTheyHadBeenThereAllAlong()
    {
        var whole = TestGeometry.FlatWorld();
        whole.LoadLandblock(Terrain.Flat(East, 0));
        var streamed = TestGeometry.FlatWorld();
        streamed.LoadLandblock(Terrain.Flat(East, 0));
        foreach (var w in new[] { whole, streamed })
        {
            w.Objects.Register(1, Crate(), TestGeometry.At(191.5f, 100, 0), 1f, PhysicsState.Static); // west home, crosses east
            w.Objects.Register(3, Crate(), Position.Outdoor(Lb, new Vector3(192.4f, 50, 0)), 1f, PhysicsState.Static); // east home, crosses west
        }
        streamed.UnloadLandblock(East);
        Assert.True(streamed.Objects.Contains(3)); // it keeps its west rows
        streamed.UnloadLandblock(Lb);
        Assert.Equal(0, streamed.Objects.Count); // nothing is left anywhere
        streamed.LoadLandblock(Terrain.Flat(Lb, 0));
        streamed.LoadLandblock(Terrain.Flat(East, 0));
        streamed.Objects.Register(3, Crate(), Position.Outdoor(Lb, new Vector3(192.4f, 50, 0)), 1f, PhysicsState.Static);
        streamed.Objects.Register(1, Crate(), TestGeometry.At(191.5f, 100, 0), 1f, PhysicsState.Static);
        // Unload the west block, then load it again: object 1 (homed there) kept its east rows, object 3
        // (homed east) lost its west rows; both are listed again in the west.
        streamed.UnloadLandblock(Lb);
        Assert.All(streamed.Objects.CellsOf(1), c => Assert.Equal(East, c >> 16));
        Assert.All(streamed.Objects.CellsOf(3), c => Assert.Equal(East, c >> 16));
        streamed.LoadLandblock(Terrain.Flat(Lb, 0));

        foreach (uint id in new uint[] { 1, 3 })
            Assert.Equal(whole.Objects.CellsOf(id).Order(), streamed.Objects.CellsOf(id).Order());
        Assert.Contains(whole.Objects.CellsOf(3), c => c >> 16 == Lb);
    }

    [Fact]
    public void Engine_RefusesAStateInAnUnloadedCell_NamingTheCell_EvenAfterAnAnsweredRefusal()
    {
        var world = TestGeometry.FlatWorld();
        world.LoadLandblock(Terrain.Flat(East, 0));
        world.Objects.Register(9, Crate(), Position.Outdoor(Lb, new Vector3(196, 100, 0)), 1f, PhysicsState.Static);
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var state = MoverState.OnFloor(Position.Outdoor(Lb, new Vector3(193.5f, 100, 0)), 0f);
        // Walk into the box until a move is refused before its first sub-step (remembered by the engine).
        MoveResult r = default;
        for (int i = 0; i < 20; i++)
        {
            var target = state.Position;
            target.Frame.Origin += new Vector3(0.3f, 0, 0);
            r = engine.Resolve(mover, state, target);
            if (!r.Succeeded) break;
            state = r.Next;
        }
        Assert.False(r.Succeeded);
        var again = state.Position;
        again.Frame.Origin += new Vector3(0.3f, 0, 0);
        Assert.False(engine.Resolve(mover, state, again).Succeeded);

        world.UnloadLandblock(East);

        var ex = Assert.Throws<ArgumentException>(() => engine.Resolve(mover, state, again));
        Assert.Contains($"0x{state.Position.CellId:X8}", ex.Message);
    }

    [Fact]
    public void Queries_DoNotSeeAnUnloadedLandblock_AndRefuseAPointInIt()
    {
        var world = TestGeometry.FlatWorld(2f);
        world.LoadLandblock(Terrain.Flat(East, 5f));
        world.Objects.Register(4, Crate(), Position.Outdoor(East, new Vector3(4f, 50, 5)), 1f, PhysicsState.Static);
        var query = new WorldQuery(world);
        var inEast = Position.Outdoor(East, new Vector3(60, 60, 10));
        Assert.True(query.TryFindFloor(inEast, 20f, out _));
        Span<ObjectOverlap> found = stackalloc ObjectOverlap[4];
        var nearBorder = TestGeometry.At(191f, 50, 6); // west of the border; the crate stands just east of it
        Assert.Equal(1, query.OverlapSphere(nearBorder, 4.5f, found));
        Assert.True(query.SphereCast(TestGeometry.At(191f, 70, 8), new Vector3(196f, 90, 3), 0.5f, out var east));
        Assert.Equal(SurfaceKind.Terrain, east.Kind);
        Assert.Equal(East, east.CellId >> 16);

        world.UnloadLandblock(East);

        var ex = Assert.Throws<ArgumentException>(() => query.TryFindFloor(inEast, 20f, out _));
        Assert.Contains($"0x{inEast.CellId:X8}", ex.Message);
        Assert.Equal(0, query.OverlapSphere(nearBorder, 4.5f, found));
        // The cast no longer meets the east block's higher ground; the west block still answers.
        Assert.False(query.SphereCast(TestGeometry.At(191f, 70, 8), new Vector3(196f, 90, 3), 0.5f, out _));
        Assert.True(query.TryFindFloor(TestGeometry.At(100, 100, 10), 20f, out var floor));
        Assert.Equal(2f, floor.Point.Z, 4);
    }

    [Fact]
    public void Unload_AllocatesNothing_OnceWarm()
    {
        var land = new StreamedLand();
        var world = land.Full();
        long bytes = Allocations.PerRound(
            warmUp: () =>
            {
                for (int i = 0; i < 3; i++)
                {
                    world.UnloadLandblock(StreamedLand.Landblock(2, 2));
                    land.Load(world, 2, 2);
                }
            },
            round: () => world.UnloadLandblock(StreamedLand.Landblock(2, 2)),
            rounds: 1);
        Assert.Equal(0, bytes);
    }

    /// <summary>One frame of a walk, bit for bit.</summary>
    private static string Fingerprint(in BodyStepResult r)
    {
        var s = r.Next;
        var f = s.Position.Frame;
        static int B(float v) => BitConverter.SingleToInt32Bits(v);
        return $"{s.Position.CellId:X8} {B(f.Origin.X)} {B(f.Origin.Y)} {B(f.Origin.Z)} {B(f.Orientation.W)} {B(f.Orientation.Z)} " +
            $"{s.Contact} {s.OnWalkable} {s.ContactPlaneCellId:X8} {B(s.ContactPlane.Normal.X)} {B(s.ContactPlane.Normal.Y)} {B(s.ContactPlane.Normal.Z)} {B(s.ContactPlane.D)} " +
            $"{s.SlidingNormalValid} {B(s.SlidingNormal.X)} {B(s.SlidingNormal.Y)} {B(r.Body.Velocity.X)} {B(r.Body.Velocity.Y)} {B(r.Body.Velocity.Z)} " +
            $"{r.Move.CollisionNormalValid} {string.Join(',', r.Move.CollidedObjects.ToArray())}";
    }

    private sealed record Walk(List<string> Frames, int Loads, int Unloads, int FramesWithObjects, uint LastLandblock);

    private static Walk RunWalk(bool stream, int frames)
    {
        var land = new StreamedLand();
        var world = stream ? new PhysicsWorld() : land.Full();
        var loaded = new HashSet<(int, int)>();
        int loads = 0, unloads = 0;
        void Window(uint landblock)
        {
            var (cx, cy) = StreamedLand.BlockOf(landblock);
            foreach (var b in loaded.ToList())
                if (Math.Abs(b.Item1 - cx) > 1 || Math.Abs(b.Item2 - cy) > 1)
                {
                    world.UnloadLandblock(StreamedLand.Landblock(b.Item1, b.Item2));
                    loaded.Remove(b);
                    unloads++;
                }
            for (int x = cx - 1; x <= cx + 1; x++)
                for (int y = cy - 1; y <= cy + 1; y++)
                    if (x >= 0 && y >= 0 && x < StreamedLand.Size && y < StreamedLand.Size && loaded.Add((x, y)))
                    {
                        land.Load(world, x, y);
                        loads++;
                    }
        }
        var state = StreamedLand.StartState();
        if (stream) Window(state.Position.CellId >> 16);
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var body = BodyState.Creature();
        var result = new List<string>();
        int withObjects = 0;
        for (int i = 0; i < frames; i++)
        {
            var r = engine.Step(mover, state, body, 1.0 / 30, StreamedLand.Desired);
            state = r.Next;
            body = r.Body;
            result.Add(Fingerprint(r));
            if (!r.Move.CollidedObjects.IsEmpty || r.Move.CollisionNormalValid) withObjects++;
            if (stream) Window(state.Position.CellId >> 16);
        }
        return new Walk(result, loads, unloads, withObjects, state.Position.CellId >> 16);
    }

    [Fact]
    public void AWalkStreamedThroughA3x3Window_IsTheWalkThroughTheWholeArea_BitForBit()
    {
        const int frames = 4200;
        var whole = RunWalk(stream: false, frames);
        var streamed = RunWalk(stream: true, frames);
        for (int i = 0; i < frames; i++)
            Assert.True(whole.Frames[i] == streamed.Frames[i], $"frame {i}:\n  whole:    {whole.Frames[i]}\n  streamed: {streamed.Frames[i]}");
        // The walk crossed the area (so the window moved) and met objects near the borders.
        Assert.Equal((4, 4), StreamedLand.BlockOf(whole.LastLandblock));
        Assert.True(streamed.Unloads >= 8, $"{streamed.Unloads} unloads");
        Assert.True(streamed.Loads >= 17, $"{streamed.Loads} loads");
        Assert.True(whole.FramesWithObjects >= 4, $"{whole.FramesWithObjects} frames with a collision");
    }
}
