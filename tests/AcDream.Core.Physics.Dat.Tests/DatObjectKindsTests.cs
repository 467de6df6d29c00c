using System.Reflection;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.Attributes;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// The type of a DAT id as a read checks it: the adapter's answer (without DatReaderWriter's per-read LINQ walk)
/// is DatReaderWriter's own <c>TypeFromId</c> wherever it gives one, over every object type's ids and their edges,
/// and it does give one for every type a landblock load reads.
/// </summary>
public class DatObjectKindsTests
{
    // Every id worth asking about in a file: each type's exact id, range ends and the ids just outside them, masks
    // under a few landblocks, and a spread of ids across the whole 32-bit space.
    private static IEnumerable<uint> Probes(DatFileType file)
    {
        foreach (var type in typeof(DBObj).Assembly.GetTypes())
        {
            if (!type.IsSubclassOf(typeof(DBObj)) || type.GetCustomAttribute<DBObjTypeAttribute>(true) is not { } a || a.DatFileType != file)
                continue;
            foreach (uint id in new[] { a.FirstId, a.LastId })
            {
                yield return id;
                yield return id - 1;
                yield return id + 1;
            }
            if (a.MaskId != 0)
                foreach (uint block in new uint[] { 0x0000, 0x8040, 0xA9B4, 0xFEFE, 0xFFFF })
                    yield return block << 16 | a.MaskId;
        }
        for (uint id = 0; id < 0xFFFF_F000; id += 0x000F_F0F1)
            yield return id;
        foreach (uint low in new uint[] { 0x0000, 0x0001, 0x0040, 0x00FF, 0x0100, 0x0143, 0xFFFD, 0xFFFE, 0xFFFF })
            yield return 0xA9B4_0000 | low;
    }

    [Theory]
    [InlineData(DatFileType.Cell)]
    [InlineData(DatFileType.Portal)]
    public void TheAdaptersAnswer_IsDatReaderWritersOwn(DatFileType file)
    {
        using var dats = new TempDats();
        using var files = dats.Open();
        var dat = file == DatFileType.Cell ? files.Cell : files.Portal;
        int answered = 0;
        foreach (uint id in Probes(file))
        {
            var ours = DatObjectKinds.Of(file, id);
            if (ours is null)
                continue;
            answered++;
            var theirs = dat.TypeFromIdAsReaderSays(id);
            Assert.True(ours == theirs, $"{file} id 0x{id:X8}: the adapter says {ours}, DatReaderWriter says {theirs}.");
        }
        Assert.True(answered > 100, $"{file}: only {answered} ids answered without DatReaderWriter.");
    }

    [Theory]
    [InlineData(DatFileType.Cell, 0xA9B4FFFFu, DBObjType.LandBlock)]
    [InlineData(DatFileType.Cell, 0xA9B4FFFEu, DBObjType.LandBlockInfo)]
    [InlineData(DatFileType.Cell, 0xA9B40143u, DBObjType.EnvCell)]
    [InlineData(DatFileType.Portal, 0x01000A2Bu, DBObjType.GfxObj)]
    [InlineData(DatFileType.Portal, 0x020001B5u, DBObjType.Setup)]
    [InlineData(DatFileType.Portal, 0x0D00021Cu, DBObjType.Environment)]
    [InlineData(DatFileType.Portal, 0x13000000u, DBObjType.Region)]
    public void EveryTypeALoadReads_IsAnsweredWithoutDatReaderWriter(DatFileType file, uint id, DBObjType expected) =>
        Assert.Equal(expected, DatObjectKinds.Of(file, id));

    [Fact]
    public void TheWrittenTable_IsTheReferencedDatReaderWritersAttributes()
    {
        // The table is used only under the version it was taken from; this test runs against that version.
        Assert.True(DatObjectKinds.UsesWrittenTable, $"DatReaderWriter {typeof(DBObj).Assembly.GetName().Version} is loaded, the table is {DatPackage.ReaderVersion}'s.");
        var written = DatObjectKinds.Written();
        var read = DatObjectKinds.FromAttributes();
        var missing = read.Except(written).Select(k => $"{k.Type.Name} {k.File} {k.ObjectType} 0x{k.FirstId:X8}-0x{k.LastId:X8} mask 0x{k.MaskId:X8}").ToList();
        var extra = written.Except(read).Select(k => $"{k.Type.Name} {k.File} {k.ObjectType} 0x{k.FirstId:X8}-0x{k.LastId:X8} mask 0x{k.MaskId:X8}").ToList();
        Assert.True(missing.Count == 0 && extra.Count == 0,
            $"the written table differs from the attributes: not written {string.Join("; ", missing)}; written but not so {string.Join("; ", extra)}");
        Assert.Equal(written.Length, written.Select(k => k.Type).Distinct().Count());
    }

    // A type outside DatReaderWriter's assembly: answered from its own attribute, by reflection. DatReaderWriter's
    // attribute is not inherited, so a class derived from GfxObj has none, and a read of it is refused as before.
    private sealed class DerivedGfxObj : GfxObj { }

    [Fact]
    public void ATypeOutsideTheTable_IsAnsweredByItsOwnAttribute()
    {
        Assert.Null(typeof(DerivedGfxObj).GetCustomAttribute<DBObjTypeAttribute>());
        Assert.Null(DatObjectKinds.OfType(typeof(DerivedGfxObj)));
        var gfxObj = DatObjectKinds.OfType(typeof(GfxObj));
        Assert.Equal((DatFileType.Portal, DBObjType.GfxObj, 0x0100_0000u, 0x0100_FFFFu), (gfxObj!.Value.File, gfxObj.Value.ObjectType, gfxObj.Value.FirstId, gfxObj.Value.LastId));
    }
}
