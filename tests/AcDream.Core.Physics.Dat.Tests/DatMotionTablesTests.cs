using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Motion;
using AcDream.Core.Physics.Motion;
using AnimationFlags = DatReaderWriter.Enums.AnimationFlags;
using DatReaderWriter.Types;
using DrwAnimation = DatReaderWriter.DBObjs.Animation;
using DrwMotionTable = DatReaderWriter.DBObjs.MotionTable;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>Motion tables and animations read from a written portal DAT and converted.</summary>
public class DatMotionTablesTests
{
    [Fact]
    public void TheHumanoid_RoundTripsThroughADat_ToTheBit()
    {
        var humanoid = MotionTables.Humanoid();
        using var dats = new TempDats(MotionTableWriter.Objects(humanoid));
        using var files = dats.Open();
        var read = DatMotionTables.Load(files, humanoid.Id);
        MotionTableAssert.Same(humanoid, read);
    }

    [Fact]
    public void ALoadedTable_IsConvertedOnceAndShared()
    {
        var humanoid = MotionTables.Humanoid();
        using var dats = new TempDats(MotionTableWriter.Objects(humanoid));
        using var files = dats.Open();
        Assert.Same(DatMotionTables.Load(files, humanoid.Id), DatMotionTables.Load(files, humanoid.Id));
        Assert.True(files.Converted.Contains<MotionTable>(humanoid.Id));
    }

    [Fact]
    public void RootFrames_AreThePosFramesAsStored_AndOnlyUnderTheirFlag()
    {
        var q = Quaternion.Normalize(new Quaternion(0.1f, -0.2f, 0.3f, 0.9f));
        var with = new DrwAnimation { Id = 0x03000010, NumParts = 2, Flags = AnimationFlags.PosFrames };
        var without = new DrwAnimation { Id = 0x03000011, NumParts = 2 };
        for (int i = 0; i < 3; i++)
        {
            with.PosFrames.Add(new DatReaderWriter.Types.Frame { Origin = new Vector3(0.1f * i, 1f / 3f, -i), Orientation = q });
            with.PartFrames.Add(new AnimationFrame(2));
            without.PartFrames.Add(new AnimationFrame(2));
        }
        var a = DatMotionTables.ToAnimation(with);
        Assert.Equal(0x03000010u, a.Id);
        Assert.Equal(3, a.FrameCount);
        Assert.Equal(with.PosFrames.Select(f => new RootFrame(f.Origin, f.Orientation)), a.RootFrames.ToArray());
        Assert.Equal(q, a.RootFrames[2].Orientation);                     // (x, y, z, w) kept, not re-normalised or re-ordered
        var b = DatMotionTables.ToAnimation(without);
        Assert.Equal(3, b.FrameCount);
        Assert.Equal(0, b.RootFrames.Length);
    }

    [Fact]
    public void NegativeDatKeys_AreTheUnsignedIdsTheRuntimeLooksUp()
    {
        // A link to a style (0x8000003D) is stored under a negative 32-bit key; the runtime looks it up unsigned.
        var table = new DrwMotionTable { Id = 0x09000001, DefaultStyle = (DatReaderWriter.Enums.MotionCommand)0x8000003D };
        table.StyleDefaults[(DatReaderWriter.Enums.MotionCommand)0x8000003D] = (DatReaderWriter.Enums.MotionCommand)0x41000003;
        var cycle = new DatReaderWriter.Types.MotionData { Anims = [new DatReaderWriter.Types.AnimData { AnimId = 0x03000001, HighFrame = -1, Framerate = 30f }] };
        table.Cycles[0x003D0003] = cycle;
        var link = new MotionCommandData();
        link.MotionData[unchecked((int)0x8000003Du)] = cycle;
        table.Links[0x003D0003] = link;
        var anim = new DrwAnimation { Id = 0x03000001, PartFrames = [new AnimationFrame(0)] };
        var converted = DatMotionTables.ToMotionTable(table, [DatMotionTables.ToAnimation(anim)]);
        Assert.NotNull(converted.LinksFrom(0x003D0003)!.GetValueOrDefault(0x8000003Du));
        Assert.Equal(0x41000003u, converted.StyleDefaults[0x8000003D]);
        Assert.Equal([0x03000001u], DatMotionTables.AnimationIds(table));
    }

    [Fact]
    public void AnAbsentAnimation_IsNamedWithTheTable()
    {
        var humanoid = MotionTables.Humanoid();
        uint missing = humanoid.Animations.Keys.Max();
        using var dats = new TempDats(MotionTableWriter.Objects(humanoid).Where(o => o.Id != missing));
        using var files = dats.Open();
        var ex = Assert.Throws<DatReadException>(() => DatMotionTables.Load(files, humanoid.Id));
        Assert.Equal($"client_portal.dat 0x{humanoid.Id:X8}: plays animation 0x{missing:X8}, which is absent.", ex.Message);
        Assert.False(files.Converted.Contains<MotionTable>(humanoid.Id));
    }

    [Fact]
    public void ATableTheRuntimeRefuses_IsNamedWithItsFileIdAndField()
    {
        var humanoid = MotionTables.Humanoid();
        var table = MotionTableWriter.Table(humanoid);
        var (key, data) = table.Cycles.First();
        data.Anims[0].Framerate = 0f;                                       // retail never plays a still framerate
        using var dats = new TempDats([table, .. humanoid.Animations.Values.Select(MotionTableWriter.Animation)]);
        using var files = dats.Open();
        var ex = Assert.Throws<DatReadException>(() => DatMotionTables.Load(files, humanoid.Id));
        Assert.Equal(humanoid.Id, ex.ObjectId);
        Assert.Contains($"cycles[0x{unchecked((uint)key):X8}].anims[0].framerate", ex.Message);
        Assert.StartsWith("client_portal.dat", ex.Message);
    }

    [Fact]
    public void FlagsBeyondVelocityAndOmega_AreRefused()
    {
        var humanoid = MotionTables.Humanoid();
        var table = MotionTableWriter.Table(humanoid);
        table.Cycles.First().Value.Flags = (DatReaderWriter.Enums.MotionDataFlags)4;
        var ex = Assert.Throws<ArgumentException>(() => DatMotionTables.ToMotionTable(table, humanoid.Animations.Values));
        Assert.Contains(".flags: must be 0 to 3", ex.Message);
    }
}
