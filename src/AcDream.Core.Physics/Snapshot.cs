using System;
using System.Collections.Generic;
using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Snapshots;

namespace AcDream.Core.Physics;

/// <summary>
/// A compact binary form of what changes while a world runs: a mover's <see cref="MoverState"/> and
/// <see cref="BodyState"/>, and a world's objects (id, setup key, position, scale, state, flags). Geometry is
/// not in it: the landblocks, indoor cells, buildings and setups come from the host's data, as they did when
/// the world was built; a setup is written as the key the host gives it (a retail setup DID, say). Restoring
/// the same bytes into a world built from the same data and a new engine continues bit for bit.
/// </summary>
/// <remarks>
/// <para>Layout (little-endian): the magic "ACPS", a version (u16, <see cref="Version"/>), then sections, each a
/// tag (u8), a length (u32) and that many bytes. Tags: 1 mover state, 2 body state, 3 objects, 4 the motion
/// state of an <see cref="ObjectMotion"/> (CMotionInterp, MotionTableManager and CSequence; animations by id,
/// resolved in the same <see cref="MotionTable"/> on load), 5 the objects'
/// places in their cells' lists (the order retail tests a cell's objects in, which moves and removals change:
/// CObjCell::remove_shadow_object moves the last object into the hole): per object a count (u8; 255: a u32
/// count follows), then each cell id and place (u32 each). A reader skips sections whose tag it does not know,
/// so a newer writer's extra sections are read past; a missing section it needs is an error.</para>
/// <para>Reading never reads past the bytes given (at most <see cref="MaxBytes"/>), checks every float is finite
/// and every enum known, and reports a bad snapshot with an <see cref="InvalidDataException"/> naming the field and
/// its byte offset. Nothing is changed on failure.</para>
/// </remarks>
public static class Snapshot
{
    /// <summary>The format version this library writes and reads.</summary>
    public const ushort Version = 1;

    // In section 5, a count byte of this value is followed by the count as a u32.
    private const byte ManyCells = byte.MaxValue;

    /// <summary>The largest snapshot read, in bytes (64 MiB: about 1.3 million objects).</summary>
    public const int MaxBytes = 64 << 20;

    private const byte MoverTag = 1, BodyTag = 2, ObjectsTag = 3, MotionTag = 4, CellOrderTag = 5;
    private const int ObjectBytes = 4 + 4 + 32 + 4 + 4 + 1;
    private static ReadOnlySpan<byte> Magic => "ACPS"u8;

    /// <summary>A mover's state and its body's state.</summary>
    public static byte[] SaveMover(in MoverState state, in BodyState body) => WriteMover(state, body, null);

    /// <summary>Reads what <see cref="SaveMover(in MoverState, in BodyState)"/> wrote (a motion section, if any, is skipped).</summary>
    /// <exception cref="InvalidDataException">The bytes are not a snapshot of this version, are cut short, or hold a bad value.</exception>
    public static void LoadMover(ReadOnlySpan<byte> data, out MoverState state, out BodyState body)
    {
        var r = Open(data);
        bool haveMover = false, haveBody = false;
        state = default;
        body = default;
        while (r.Remaining > 0)
        {
            var section = NextSection(ref r, out byte tag);
            if (tag == MoverTag) { state = ReadMover(ref section); haveMover = true; }
            else if (tag == BodyTag) { body = ReadBody(ref section); haveBody = true; }
        }
        if (!haveMover || !haveBody)
            throw r.Fail(haveMover ? "body" : "mover", "section is missing");
    }

    /// <summary>
    /// A mover's state, its body's state and its motion layer's whole dynamic state (section 4): the
    /// interpreter's raw and interpreted states, the motion table manager's state and queue, and the animation
    /// sequence. Restored by <see cref="LoadMover(ReadOnlySpan{byte}, out MoverState, out BodyState, ObjectMotion)"/>.
    /// </summary>
    public static byte[] SaveMover(in MoverState state, in BodyState body, ObjectMotion motion)
    {
        ArgumentNullException.ThrowIfNull(motion);
        return WriteMover(state, body, motion);
    }

    // Sections 1 and 2, and 4 when there is a motion layer.
    private static byte[] WriteMover(in MoverState state, in BodyState body, ObjectMotion? motion)
    {
        var w = Begin();
        Span<int> sections = stackalloc int[motion is null ? 2 : 3];
        sections[0] = w.BeginSection(MoverTag);
        WriteMover(w, state);
        sections[1] = w.BeginSection(BodyTag);
        WriteBody(w, body);
        if (motion is not null)
        {
            sections[2] = w.BeginSection(MotionTag);
            MotionSection.Write(w, motion);
        }
        return w.Finish(sections);
    }

    /// <summary>
    /// Reads what <see cref="SaveMover(in MoverState, in BodyState, ObjectMotion)"/> wrote, putting the motion state
    /// into <paramref name="motion"/>, which must be built from the same <see cref="MotionTable"/> (the animations
    /// are found by id). All is read and checked before <paramref name="motion"/> changes: on failure it is unchanged.
    /// </summary>
    /// <exception cref="InvalidDataException">As the other overload; or the motion section is missing, names another
    /// table or an animation not in it, holds a count past its cap, a bad index, frame or value.</exception>
    public static void LoadMover(ReadOnlySpan<byte> data, out MoverState state, out BodyState body, ObjectMotion motion)
    {
        ArgumentNullException.ThrowIfNull(motion);
        LoadMover(data, out state, out body);
        var r = Open(data);
        while (r.Remaining > 0)
        {
            var section = NextSection(ref r, out byte tag);
            if (tag == MotionTag)
            {
                MotionSection.Read(ref section, motion);
                return;
            }
        }
        throw r.Fail("motion", "section is missing");
    }

    /// <summary>
    /// A world's objects, in the registry's order, each with the key <paramref name="setupKey"/> gives its
    /// setup; only those standing in a landblock <paramref name="inGroup"/> accepts, when given (the landblock
    /// group a host hands over).
    /// </summary>
    /// <exception cref="InvalidOperationException">An object was not registered from a <see cref="PhysicsSetup"/>.</exception>
    public static byte[] SaveObjects(PhysicsWorld world, Func<PhysicsSetup, uint> setupKey, Func<uint, bool>? inGroup = null)
    {
        ArgumentNullException.ThrowIfNull(world);
        ArgumentNullException.ThrowIfNull(setupKey);
        var w = Begin();
        Span<int> sections = stackalloc int[2];
        sections[0] = w.BeginSection(ObjectsTag);
        int count = 0;
        foreach (var o in world.Objects.Records)
            if (Saved(o))
                count++;
        w.U32((uint)count);
        foreach (var o in world.Objects.Records)
        {
            if (!Saved(o))
                continue;
            var setup = o.Setup ?? throw new InvalidOperationException($"object 0x{o.Id:X8}: was not registered from a setup, so it has no setup key.");
            w.U32(o.Id);
            w.U32(setupKey(setup));
            w.Position(o.Position);
            w.F32(o.Scale);
            w.U32((uint)o.State);
            w.Byte((byte)o.Flags);
        }
        // Each object's place in each of its cells' lists, in the same order.
        sections[1] = w.BeginSection(CellOrderTag);
        foreach (var o in world.Objects.Records)
        {
            if (!Saved(o))
                continue;
            // The count in one byte; 255 says a u32 count follows (an object as large as a few hundred metres is
            // listed in more than 254 land cells, and every place must come back for the test order to).
            int n = o.Cells.Count;
            if (n < ManyCells)
            {
                w.Byte((byte)n);
            }
            else
            {
                w.Byte(ManyCells);
                w.U32((uint)n);
            }
            for (int k = 0; k < n; k++)
            {
                w.U32(o.Cells[k]);
                w.U32((uint)o.Slots[k]);
            }
        }
        return w.Finish(sections);

        // An object is saved when it stands in a landblock of the group (every object without a group).
        bool Saved(World.ShadowObjectRegistry.Record o) => inGroup is null || inGroup(o.Position.CellId >> 16);
    }

    /// <summary>
    /// Registers the objects <see cref="SaveObjects"/> wrote into <paramref name="world"/> (its cells must be
    /// loaded), in the order written, each with the setup <paramref name="setupOf"/> returns for its key; then
    /// puts them back in their places in each cell's list (the saved places, among the places they took).
    /// All or nothing: a bad snapshot, an id already registered or a position the world refuses throws, and
    /// the objects this call registered are removed again. Returns how many were registered.
    /// </summary>
    /// <exception cref="InvalidDataException">The bytes are not an objects snapshot of this version, or hold a bad value.</exception>
    /// <exception cref="ArgumentException">The world refuses an object (named in the message).</exception>
    public static int LoadObjects(ReadOnlySpan<byte> data, PhysicsWorld world, Func<uint, PhysicsSetup> setupOf)
    {
        ArgumentNullException.ThrowIfNull(world);
        ArgumentNullException.ThrowIfNull(setupOf);
        var r = Open(data);
        List<(uint Id, uint Key, Position Position, float Scale, PhysicsState State, ShadowFlags Flags)>? objects = null;
        Dictionary<uint, List<(uint Id, uint Rank)>>? order = null;
        while (r.Remaining > 0)
        {
            var section = NextSection(ref r, out byte tag);
            if (tag == CellOrderTag)
            {
                if (objects is null)
                    throw section.Fail("cellOrder", "comes before the objects section");
                order = new();
                for (int i = 0; i < objects.Count; i++)
                {
                    long n = section.U8($"cellOrder[{i}].count");
                    if (n == ManyCells)
                    {
                        n = section.U32($"cellOrder[{i}].count");
                        if (n > section.Remaining / 8)
                            throw section.Fail($"cellOrder[{i}].count", $"{n} places do not fit in the {section.Remaining} bytes left");
                    }
                    for (int k = 0; k < n; k++)
                    {
                        uint cell = section.U32($"cellOrder[{i}][{k}].cell");
                        uint place = section.U32($"cellOrder[{i}][{k}].place");
                        if (!order.TryGetValue(cell, out var list))
                            order.Add(cell, list = new());
                        list.Add((objects[i].Id, place));
                    }
                }
                continue;
            }
            if (tag != ObjectsTag)
                continue;
            uint count = section.U32("objects.count");
            if (count > section.Remaining / ObjectBytes)
                throw section.Fail("objects.count", $"{count} objects do not fit in the {section.Remaining} bytes left");
            objects = new((int)count);
            for (int i = 0; i < count; i++)
            {
                string f = $"objects[{i}]";
                uint id = section.U32(f + ".id");
                uint key = section.U32(f + ".setup");
                var position = section.Position(f + ".position");
                float scale = section.F32(f + ".scale");
                var state = (PhysicsState)section.U32(f + ".state");
                var flags = (ShadowFlags)section.U8(f + ".flags");
                objects.Add((id, key, position, scale, state, flags));
            }
        }
        if (objects is null)
            throw r.Fail("objects", "section is missing");
        // Every writer writes the places (section 5) after the objects: without them the objects would load in the
        // wrong order in their cells' lists, silently changing which is tested first. A snapshot cut there is refused.
        if (order is null)
            throw r.Fail("cellOrder", "section is missing (the snapshot is cut short after its objects)");
        int done = 0;
        try
        {
            foreach (var o in objects)
            {
                var setup = setupOf(o.Key) ?? throw new ArgumentException($"object 0x{o.Id:X8}.setup: no setup for key 0x{o.Key:X8}.", nameof(setupOf));
                world.Objects.Register(o.Id, setup, o.Position, o.Scale, o.State, o.Flags);
                done++;
            }
        }
        catch
        {
            for (int i = 0; i < done; i++)
                world.Objects.Unregister(objects[i].Id);
            throw;
        }
        if (order is not null)
            foreach (var (cell, ranks) in order)
                world.Objects.RestoreOrder(cell, ranks);
        return done;
    }

    private static SnapshotWriter Begin()
    {
        var w = new SnapshotWriter();
        foreach (byte b in Magic)
            w.Byte(b);
        w.U16(Version);
        return w;
    }

    private static SnapshotReader Open(ReadOnlySpan<byte> data)
    {
        if (data.Length > MaxBytes)
            throw new InvalidDataException($"snapshot: {data.Length} bytes is more than the {MaxBytes} read.");
        var r = new SnapshotReader(data);
        for (int i = 0; i < Magic.Length; i++)
            if (r.U8("magic") != Magic[i])
                throw new InvalidDataException("snapshot magic (byte 0): not a snapshot (expected \"ACPS\").");
        ushort version = r.U16("version");
        if (version != Version)
            throw r.Fail("version", $"{version} is not the version this library reads ({Version})");
        return r;
    }

    private static SnapshotReader NextSection(ref SnapshotReader r, out byte tag)
    {
        tag = r.U8("section.tag");
        uint length = r.U32("section.length");
        if (length > r.Remaining)
            throw r.Fail("section.length", $"{length} bytes, {r.Remaining} left");
        return r.Section((int)length, "section");
    }

    private static void WriteMover(SnapshotWriter w, in MoverState s)
    {
        w.Position(s.Position);
        w.Byte((byte)((s.Contact ? 1 : 0) | (s.OnWalkable ? 2 : 0) | (s.ContactPlaneIsWater ? 4 : 0) | (s.SlidingNormalValid ? 8 : 0)));
        w.Vec(s.ContactPlane.Normal);
        w.F32(s.ContactPlane.D);
        w.U32(s.ContactPlaneCellId);
        w.Vec(s.SlidingNormal);
        w.Byte((byte)s.Ground);
        w.U32(s.GroundObjectId);
    }

    private static MoverState ReadMover(ref SnapshotReader r)
    {
        var s = new MoverState { Position = r.Position("mover.position") };
        byte flags = r.U8("mover.flags");
        if (flags > 15)
            throw r.Fail("mover.flags", $"unknown bits 0x{flags:X2}");
        s.Contact = (flags & 1) != 0;
        s.OnWalkable = (flags & 2) != 0;
        s.ContactPlaneIsWater = (flags & 4) != 0;
        s.SlidingNormalValid = (flags & 8) != 0;
        s.ContactPlane = new System.Numerics.Plane(r.Vec("mover.contactPlane.normal"), r.F32("mover.contactPlane.d"));
        s.ContactPlaneCellId = r.U32("mover.contactPlaneCell");
        s.SlidingNormal = r.Vec("mover.slidingNormal");
        byte ground = r.U8("mover.ground");
        if (ground > (byte)GroundKind.StationaryFall)
            throw r.Fail("mover.ground", $"unknown kind {ground}");
        s.Ground = (GroundKind)ground;
        s.GroundObjectId = r.U32("mover.groundObject");
        return s;
    }

    private static void WriteBody(SnapshotWriter w, in BodyState b)
    {
        w.Vec(b.Velocity);
        w.Vec(b.Omega);
        w.F32(b.Friction);
        w.F32(b.Elasticity);
        w.Byte(b.HasMotionInterpreter ? (byte)1 : (byte)0);
        w.Vec(b.Acceleration);
        w.U32((uint)b.StationaryFall);
        w.F64(b.PendingTime);
        w.Position(b.QuantumStart);
    }

    private static BodyState ReadBody(ref SnapshotReader r)
    {
        var b = new BodyState
        {
            Velocity = r.Vec("body.velocity"),
            Omega = r.Vec("body.omega"),
            Friction = r.F32("body.friction"),
            Elasticity = r.F32("body.elasticity"),
        };
        byte interp = r.U8("body.motionInterpreter");
        if (interp > 1)
            throw r.Fail("body.motionInterpreter", $"must be 0 or 1, got {interp}");
        b.HasMotionInterpreter = interp == 1;
        b.Acceleration = r.Vec("body.acceleration");
        uint fall = r.U32("body.stationaryFall");
        if (fall > 3)
            throw r.Fail("body.stationaryFall", $"must be 0..3, got {fall}");
        b.StationaryFall = (int)fall;
        double pending = r.F64("body.pendingTime");
        if (pending < 0 || pending > PhysicsConstants.HugeQuantum)
            throw r.Fail("body.pendingTime", $"must be 0..{PhysicsConstants.HugeQuantum}, got {pending}");
        b.PendingTime = pending;
        b.QuantumStart = r.Position("body.quantumStart");
        return b;
    }
}
