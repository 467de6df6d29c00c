using System.IO;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Snapshots;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Snapshots;

/// <summary>Snapshot: mover, body and objects round-trip bit for bit; a bad snapshot is refused naming the field.</summary>
public class SnapshotTests
{
    private static string Bits(in MoverState s, in BodyState b)
    {
        static string P(in Position p) => $"{p.CellId:X8} {V(p.Frame.Origin)} {BitConverter.SingleToInt32Bits(p.Frame.Orientation.X)} {BitConverter.SingleToInt32Bits(p.Frame.Orientation.Y)} {BitConverter.SingleToInt32Bits(p.Frame.Orientation.Z)} {BitConverter.SingleToInt32Bits(p.Frame.Orientation.W)}";
        static string V(Vector3 v) => $"{BitConverter.SingleToInt32Bits(v.X)},{BitConverter.SingleToInt32Bits(v.Y)},{BitConverter.SingleToInt32Bits(v.Z)}";
        return $"{P(s.Position)} {s.Contact} {s.OnWalkable} {V(s.ContactPlane.Normal)} {BitConverter.SingleToInt32Bits(s.ContactPlane.D)} {s.ContactPlaneCellId:X8} {s.ContactPlaneIsWater} " +
            $"{s.SlidingNormalValid} {V(s.SlidingNormal)} {s.Ground} {s.GroundObjectId:X8} | {V(b.Velocity)} {V(b.Omega)} {BitConverter.SingleToInt32Bits(b.Friction)} " +
            $"{BitConverter.SingleToInt32Bits(b.Elasticity)} {b.HasMotionInterpreter} {V(b.Acceleration)} {b.StationaryFall} {BitConverter.DoubleToInt64Bits(b.PendingTime)} {P(b.QuantumStart)}";
    }

    private sealed record Walk(List<string> Frames, byte[] Mover, byte[] Objects);

    /// <summary>The streamed land's walk at 70 Hz (a quantum every third frame, so frame 100 is saved with time gathered); saves at <paramref name="saveAt"/>.</summary>
    private static Walk RunWalk(PhysicsWorld world, MoverState state, BodyState body, int from, int to, int saveAt, Func<PhysicsSetup, uint> key)
    {
        var engine = new PhysicsEngine(world);
        var mover = MoverDescription.Player();
        var frames = new List<string>();
        byte[] saved = [], objects = [];
        for (int i = from; i < to; i++)
        {
            if (i == saveAt)
            {
                saved = Snapshot.SaveMover(state, body);
                objects = Snapshot.SaveObjects(world, key);
            }
            var r = engine.Step(mover, state, body, 1.0 / 70, StreamedLand.Desired);
            state = r.Next;
            body = r.Body;
            frames.Add(Bits(state, body));
        }
        return new Walk(frames, saved, objects);
    }

    [Fact]
    public void AWalkInterruptedAtFrame100_SavedAndRestoredIntoANewWorldAndEngine_ContinuesBitIdentically()
    {
        var land = new StreamedLand();
        var setups = land.Things.Select(t => t.Setup).Distinct().ToList();
        uint Key(PhysicsSetup s) => (uint)setups.IndexOf(s) + 0x0200_0000u;
        PhysicsSetup SetupOf(uint key) => setups[(int)(key - 0x0200_0000u)];

        var whole = RunWalk(land.Full(), StreamedLand.StartState(), BodyState.Creature(), 0, 400, 100, Key);

        // A new world from the same data: its cells only; its objects come from the snapshot.
        var world = new PhysicsWorld();
        for (int bx = 0; bx < StreamedLand.Size; bx++)
            for (int by = 0; by < StreamedLand.Size; by++)
                world.LoadLandblock(StreamedLand.TerrainOf(bx, by));
        Assert.Equal(land.Things.Count, Snapshot.LoadObjects(whole.Objects, world, SetupOf));
        Snapshot.LoadMover(whole.Mover, out var state, out var body);
        Assert.Equal(whole.Frames[99], Bits(state, body));
        var resumed = RunWalk(world, state, body, 100, 400, -1, Key);

        for (int i = 100; i < 400; i++)
            Assert.True(whole.Frames[i] == resumed.Frames[i - 100], $"frame {i}:\n  whole:   {whole.Frames[i]}\n  resumed: {resumed.Frames[i - 100]}");
        // The mover was saved with time gathered (1/70 s: 100 frames are 33 quanta and one frame), and moving.
        Assert.NotEqual(0, state.Position.Frame.Origin.X);
        Assert.Equal(1.0 / 70, body.PendingTime, 12);
    }

    [Fact]
    public void AMoverSnapshot_IsCompact_AndSkipsSectionsItDoesNotKnow()
    {
        var state = MoverState.OnFloor(TestGeometry.At(1, 2, 3), 3f);
        state.Ground = GroundKind.Object;
        state.GroundObjectId = 0x1234;
        var body = BodyState.Creature();
        body.Velocity = new Vector3(1.5f, -0f, 7e-30f);
        var bytes = Snapshot.SaveMover(state, body);
        Assert.Equal(4 + 2 + 5 + 70 + 5 + 89, bytes.Length);
        // A newer writer's section (tag 9) in front is read past.
        var newer = bytes[..6].Concat(new byte[] { 9, 3, 0, 0, 0, 1, 2, 3 }).Concat(bytes[6..]).ToArray();
        Snapshot.LoadMover(newer, out var s2, out var b2);
        Assert.Equal(Bits(state, body), Bits(s2, b2));
    }

    public static TheoryData<string, string> BadSnapshots() => new()
    {
        { "empty", "snapshot magic" },
        { "not a snapshot", "snapshot magic" },
        { "version 2", "snapshot version" },
        { "cut short", "snapshot section.length" },
        { "section longer than the data", "snapshot section.length" },
        { "NaN origin", "snapshot mover.position.origin.x" },
        { "unknown ground", "snapshot mover.ground" },
        { "no body section", "snapshot body (" },
    };

    [Theory]
    [MemberData(nameof(BadSnapshots))]
    public void ABadMoverSnapshot_IsRefusedNamingTheField(string row, string message)
    {
        var good = Snapshot.SaveMover(MoverState.OnFloor(TestGeometry.At(1, 2, 3), 3f), BodyState.Creature());
        const int moverAt = 6 + 5; // header, then the mover section's tag and length
        byte[] bad = row switch
        {
            "empty" => [],
            "not a snapshot" => "XXXX\u0001\u0000"u8.ToArray(),
            "version 2" => [.. good[..4], 2, 0, .. good[6..]],
            "cut short" => good[..^3],
            "section longer than the data" => [.. good[..7], 0xFF, 0xFF, 0, 0, .. good[11..]],
            "NaN origin" => Patch(good, moverAt + 4, BitConverter.GetBytes(float.NaN)),
            "unknown ground" => Patch(good, moverAt + 32 + 1 + 16 + 4 + 12, [9]),
            "no body section" => good[..(moverAt + 70)],
            _ => throw new ArgumentException(row),
        };
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadMover(bad, out _, out _));
        Assert.StartsWith(message, ex.Message);
    }

    /// <summary>
    /// A body's pending time beyond HugeQuantum (a frame retail drops, CPhysics::UseTime) or below zero is a state no
    /// step leaves behind: the snapshot is refused naming body.pendingTime; HugeQuantum itself loads.
    /// </summary>
    [Theory]
    [InlineData(PhysicsConstants.HugeQuantum + 0.5, false)]
    [InlineData(-1.0 / 70, false)]
    [InlineData(PhysicsConstants.HugeQuantum, true)]
    public void ABodysPendingTime_OutsideZeroToHugeQuantum_IsRefused(double pending, bool loads)
    {
        var body = BodyState.Creature();
        body.PendingTime = 1.0 / 70; // a bit pattern found once in the bytes
        var good = Snapshot.SaveMover(MoverState.OnFloor(TestGeometry.At(1, 2, 3), 3f), body);
        byte[] marker = BitConverter.GetBytes(1.0 / 70);
        int at = good.AsSpan().IndexOf(marker);
        Assert.True(at > 0 && good.AsSpan(at + 1).IndexOf(marker) < 0, "the pending time's bytes are not found once");
        var bad = Patch(good, at, BitConverter.GetBytes(pending));
        if (loads)
        {
            Snapshot.LoadMover(bad, out _, out var loaded);
            Assert.Equal(pending, loaded.PendingTime);
            return;
        }
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadMover(bad, out _, out _));
        Assert.StartsWith("snapshot body.pendingTime", ex.Message);
    }

    /// <summary>The mover's four flags (contact, on walkable, water contact plane, sliding normal) each round-trip on their own.</summary>
    [Theory]
    [InlineData(true, false, false, false)]
    [InlineData(false, true, false, false)]
    [InlineData(false, false, true, false)]
    [InlineData(false, false, false, true)]
    public void TheMoversFlags_EachRoundTripOnTheirOwn(bool contact, bool onWalkable, bool water, bool sliding)
    {
        var state = MoverState.OnFloor(TestGeometry.At(1, 2, 3), 3f);
        state.Contact = contact;
        state.OnWalkable = onWalkable;
        state.ContactPlaneIsWater = water;
        state.SlidingNormalValid = sliding;
        Snapshot.LoadMover(Snapshot.SaveMover(state, BodyState.Creature()), out var loaded, out _);
        Assert.Equal((contact, onWalkable, water, sliding),
            (loaded.Contact, loaded.OnWalkable, loaded.ContactPlaneIsWater, loaded.SlidingNormalValid));
    }

    private static byte[] Patch(byte[] data, int at, byte[] with)
    {
        var copy = (byte[])data.Clone();
        with.CopyTo(copy, at);
        return copy;
    }

    [Fact]
    public void Objects_OfALandblockGroup_RoundTrip_AndAFailedLoadLeavesTheWorldAsItWas()
    {
        var land = new StreamedLand();
        var source = land.Full();
        var setups = land.Things.Select(t => t.Setup).Distinct().ToList();
        uint group = StreamedLand.Landblock(1, 1);
        var bytes = Snapshot.SaveObjects(source, s => (uint)setups.IndexOf(s), lb => lb == group);
        var inGroup = land.Things.Where(t => t.Home == group).ToList();
        Assert.NotEmpty(inGroup);
        // The objects (49 bytes each), then each one's places in its cells (a count, then 8 bytes a cell).
        int places = inGroup.Sum(t => 1 + 8 * source.Objects.CellsOf(t.Id).Count);
        Assert.Equal(4 + 2 + 5 + 4 + inGroup.Count * 49 + 5 + places, bytes.Length);

        var target = new PhysicsWorld();
        target.LoadLandblock(StreamedLand.TerrainOf(1, 1));
        // One of the group's objects is already there: nothing is registered.
        target.Objects.Register(inGroup[^1].Id, inGroup[^1].Setup, inGroup[^1].Position);
        Assert.Throws<ArgumentException>(() => Snapshot.LoadObjects(bytes, target, k => setups[(int)k]));
        Assert.Equal(1, target.Objects.Count);
        target.Objects.Unregister(inGroup[^1].Id);

        Assert.Equal(inGroup.Count, Snapshot.LoadObjects(bytes, target, k => setups[(int)k]));
        foreach (var t in inGroup)
        {
            Assert.Equal(t.Position.Frame.Origin, target.Objects.PositionOf(t.Id).Frame.Origin);
            Assert.Equal(source.Objects.CellsOf(t.Id).Where(c => c >> 16 == group), target.Objects.CellsOf(t.Id));
        }
        var countTooLarge = Patch(bytes, 11, BitConverter.GetBytes(1_000_000u));
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadObjects(countTooLarge, new PhysicsWorld(), k => setups[(int)k]));
        Assert.StartsWith("snapshot objects.count", ex.Message);
    }

    [Fact]
    public void ObjectsRestored_TakeTheirPlacesInEachCellsList_AfterARemovalReorderedIt()
    {
        var setup = new PhysicsSetup { Spheres = [new AcDream.Core.Physics.Sphere(Vector3.Zero, 0.5f)] };
        var source = TestGeometry.FlatWorld();
        for (uint id = 1; id <= 4; id++)
            source.Objects.Register(id, setup, TestGeometry.At(100 + id, 100, 0.5f));
        // Retail's removal moves the cell's last object into the hole: 4, 2, 3.
        source.Objects.Unregister(1);
        uint cell = TestGeometry.At(101, 100, 0).CellId;
        static uint[] Order(PhysicsWorld w, uint cell) => w.Objects.RowsInCell(cell).ToArray().Select(r => r.EntityId).ToArray();
        Assert.Equal([4u, 2u, 3u], Order(source, cell));

        var bytes = Snapshot.SaveObjects(source, _ => 7u);
        var target = TestGeometry.FlatWorld();
        Snapshot.LoadObjects(bytes, target, _ => setup);
        Assert.Equal([4u, 2u, 3u], Order(target, cell));
    }

    [Fact]
    public void AnObjectsSnapshotCutBetweenItsSections_IsRefused_AndTheWorldIsUnchanged()
    {
        // Cut after the objects section, the snapshot would load with every object but not its places in the cells'
        // lists (the order a cell's objects are tested in): refused as cut short instead.
        var setup = new PhysicsSetup { Spheres = [new AcDream.Core.Physics.Sphere(Vector3.Zero, 0.5f)] };
        var source = TestGeometry.FlatWorld();
        for (uint id = 1; id <= 3; id++)
            source.Objects.Register(id, setup, TestGeometry.At(100 + id, 100, 0.5f));
        var bytes = Snapshot.SaveObjects(source, _ => 7u);
        int objectsEnd = 6 + 5 + BitConverter.ToInt32(bytes, 7);
        Assert.Equal(5, bytes[objectsEnd]); // the places' section follows
        var target = TestGeometry.FlatWorld();
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadObjects(bytes[..objectsEnd], target, _ => setup));
        Assert.StartsWith("snapshot cellOrder (byte", ex.Message);
        Assert.Equal(0, target.Objects.Count);
        Assert.Equal(3, Snapshot.LoadObjects(bytes, target, _ => setup));
    }

    [Fact]
    public void AnObjectListedInHundredsOfCells_GetsEveryPlaceBack()
    {
        // A BSP box 300 m across in the middle of a 3 x 3 landblock group is listed in some 324 land cells. In
        // one of the last of them, two small objects were registered before it and the first removed, so that
        // cell lists the box first (retail's removal moves the last entry into the hole): [box, B]. A restore
        // registers B first, so only the box's saved place puts it back in front (red when a count over 254 is
        // cut to 255).
        var source = new PhysicsWorld();
        var target = new PhysicsWorld();
        for (uint bx = 0xA8; bx <= 0xAA; bx++)
            for (uint by = 0xB3; by <= 0xB5; by++)
            {
                source.Cells.AddLandblock(Terrain.Flat(bx << 8 | by, 0f));
                target.Cells.AddLandblock(Terrain.Flat(bx << 8 | by, 0f));
            }
        var small = new PhysicsSetup { Spheres = [new AcDream.Core.Physics.Sphere(Vector3.Zero, 0.5f)] };
        var half = new Vector3(150f, 150f, 1f);
        var box = new PhysicsSetup { Parts = [new SetupPart(new PhysicsModel(BspShapes.Box(-half, half)), Frame.Identity)] };
        var corner = new Vector3(44f, 44f, 0.5f); // (236, 236) from the middle landblock's corner, in 0xA9B4's north-east neighbour
        uint cornerCell = LandDefs.LandCellAt(0xAAB5, corner);
        source.Objects.Register(1, small, new Position(cornerCell, corner));
        source.Objects.Register(2, small, new Position(cornerCell, corner + new Vector3(1f, 0, 0)));
        source.Objects.Register(3, box, new Position(LandDefs.LandCellAt(0xA9B4, new Vector3(96f, 96f, 2f)), new Vector3(96f, 96f, 2f)));
        source.Objects.Unregister(1);
        var cells = source.Objects.CellsOf(3);
        Assert.True(cells.Count > 255, $"the box is listed in {cells.Count} cells");
        Assert.True(cells.ToList().IndexOf(cornerCell) >= 255, $"the corner cell is place {cells.ToList().IndexOf(cornerCell)} of the box's list");
        static uint[] Order(PhysicsWorld w, uint cell) => w.Objects.RowsInCell(cell).ToArray().Select(r => r.EntityId).Distinct().ToArray();
        Assert.Equal([3u, 2u], Order(source, cornerCell));

        var bytes = Snapshot.SaveObjects(source, s => s == box ? 1u : 2u);
        Assert.Equal(2, Snapshot.LoadObjects(bytes, target, k => k == 1 ? box : small));
        Assert.Equal(cells, target.Objects.CellsOf(3));
        foreach (uint cell in cells)
            Assert.Equal(Order(source, cell), Order(target, cell));

        // The long count is checked against the bytes left before anything is read.
        var escape = new byte[] { 0xFF }.Concat(BitConverter.GetBytes((uint)cells.Count)).ToArray();
        int at = bytes.AsSpan().IndexOf(escape);
        Assert.True(at > 0);
        var tooMany = Patch(bytes, at + 1, BitConverter.GetBytes(1_000_000u));
        var ex = Assert.Throws<InvalidDataException>(() => Snapshot.LoadObjects(tooMany, new PhysicsWorld(), k => k == 1 ? box : small));
        Assert.Contains("cellOrder[", ex.Message);
        Assert.Contains("1000000 places do not fit", ex.Message);
    }
}
