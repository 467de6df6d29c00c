using System.Threading;
using DatReaderWriter;
using DatReaderWriter.Lib.IO;
using DatReaderWriter.Lib.IO.DatBTree;
using DatReaderWriter.Options;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using AcDream.Core.Physics.Scenes;
using DrwAnimation = DatReaderWriter.DBObjs.Animation;
using DrwMotionTable = DatReaderWriter.DBObjs.MotionTable;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>The DAT source layer: opening the two files, typed reads by id, its refusals, and the shared cache.</summary>
public class DatFilesTests
{
    private static LandBlock Land(uint id, byte height)
    {
        var land = new LandBlock { Id = id };
        for (int i = 0; i < 81; i++)
            land.Height[i] = (byte)(height + i);
        return land;
    }

    private static TempDats Dats() =>
        new(MotionTableWriter.Objects(MotionTables.Humanoid()), [Land(0xA9B4FFFF, 10)]);

    [Fact]
    public void ReadsEachFilesObjectsByIdAndType()
    {
        using var dats = Dats();
        using var files = dats.Open();
        var land = files.ReadCell<LandBlock>(0xA9B4FFFF);
        Assert.Equal(0xA9B4FFFFu, land.Id);
        Assert.Equal(Enumerable.Range(10, 81).Select(i => (byte)i), land.Height);
        var humanoid = MotionTables.Humanoid();
        var table = files.ReadPortal<DrwMotionTable>(humanoid.Id);
        Assert.Equal(humanoid.Cycles.Count, table.Cycles.Count);
        Assert.True(files.PortalContains(humanoid.Id));
        Assert.False(files.PortalContains(0x09000999));
        Assert.True(files.CellContains(0xA9B4FFFF));
    }

    [Fact]
    public void AMissingFile_IsNamed()
    {
        using var dats = Dats();
        File.Delete(dats.CellPath);
        var ex = Assert.Throws<DatReadException>(() => dats.Open());
        Assert.Equal("client_cell_1.dat", ex.File);
        Assert.Null(ex.ObjectId);
        Assert.Contains("does not exist", ex.Message);
    }

    [Fact]
    public void ACellDatGivenAsThePortalDat_IsRefusedByItsHeader()
    {
        using var dats = Dats();
        var ex = Assert.Throws<DatReadException>(() => new DatFiles(dats.CellPath, dats.CellPath));
        Assert.Equal("client_cell_1.dat", ex.File);
        Assert.Contains("is a cell DAT file, expected a portal DAT file", ex.Message);
        var other = Assert.Throws<DatReadException>(() => new DatFiles(dats.PortalPath, dats.PortalPath));
        Assert.Contains("is a portal DAT file, expected a cell DAT file", other.Message);
    }

    [Fact]
    public void AFileThatIsNotADat_IsRefusedBeforeItsIndexIsRead()
    {
        using var dats = Dats();
        File.WriteAllBytes(dats.PortalPath, Enumerable.Range(0, 4096).Select(i => (byte)(i * 7)).ToArray());
        var ex = Assert.Throws<DatReadException>(() => dats.Open());
        Assert.Equal("client_portal.dat", ex.File);
        Assert.Contains("is not a DAT file (magic", ex.Message);
        File.WriteAllText(dats.PortalPath, "short");
        Assert.Contains("shorter than its 400-byte header", Assert.Throws<DatReadException>(() => dats.Open()).Message);
    }

    [Fact]
    public void AnAbsentId_IsNamedWithItsFile()
    {
        using var dats = Dats();
        using var files = dats.Open();
        var ex = Assert.Throws<DatReadException>(() => files.ReadCell<LandBlock>(0xA9B5FFFF));
        Assert.Equal("client_cell_1.dat 0xA9B5FFFF: is absent (expected a LandBlock).", ex.Message);
        Assert.Equal(0xA9B5FFFFu, ex.ObjectId);
    }

    [Fact]
    public void AnIdOfAnotherType_IsRefusedRatherThanMisread()
    {
        using var dats = Dats();
        using var files = dats.Open();
        uint tableId = MotionTables.Humanoid().Id;
        // DatReaderWriter would unpack the table's bytes as an animation; the id's range says what it is.
        var ex = Assert.Throws<DatReadException>(() => files.ReadPortal<DrwAnimation>(tableId));
        Assert.Equal($"client_portal.dat 0x{tableId:X8}: is a MotionTable, not a Animation.", ex.Message);
        var cell = Assert.Throws<DatReadException>(() => files.ReadCell<LandBlockInfo>(0xA9B4FFFF));
        Assert.Contains("is a LandBlock, not a LandBlockInfo", cell.Message);
        // A cell object asked of the portal file is the caller's mistake.
        Assert.Throws<ArgumentException>(() => files.ReadPortal<LandBlock>(0xA9B4FFFF));
    }

    [Fact]
    public void AnUnreadableObject_IsNamed()
    {
        // An animation stored with 3 part frames under a frame count of 1000: the reader runs off its end.
        var bad = new DrwAnimation { Id = 0x03000001, NumParts = 1 };
        for (int i = 0; i < 3; i++)
            bad.PartFrames.Add(new AnimationFrame(1) { Frames = [new DatReaderWriter.Types.Frame { Orientation = Quaternion.Identity }] });
        using var dats = new TempDats([bad]);
        using (var stream = new FileStream(dats.PortalPath, FileMode.Open, FileAccess.ReadWrite))
        {
            // Find the object's frame count (flags 0, parts 1, frames 3) and make it 1000.
            var bytes = new byte[stream.Length];
            stream.ReadExactly(bytes);
            byte[] pattern = [0, 0, 0, 0, 1, 0, 0, 0, 3, 0, 0, 0];
            int at = bytes.AsSpan().IndexOf(pattern);
            Assert.True(at > 0);
            stream.Position = at + 8;
            stream.Write(BitConverter.GetBytes(1000));
        }
        using var files = dats.Open();
        var ex = Assert.Throws<DatReadException>(() => files.ReadPortal<DrwAnimation>(0x03000001));
        Assert.StartsWith("client_portal.dat 0x03000001: cannot be read as a Animation", ex.Message);
    }

    [Fact]
    public void TheFilesAreReadOnlyAndTwoInstancesReadThemAtOnce()
    {
        using var dats = Dats();
        byte[] before = File.ReadAllBytes(dats.PortalPath);
        using (var a = dats.Open())
        using (var b = dats.Open())
        {
            Assert.Equal(a.ReadCell<LandBlock>(0xA9B4FFFF).Height, b.ReadCell<LandBlock>(0xA9B4FFFF).Height);
            DatMotionTables.Load(a, MotionTables.Humanoid().Id);
        }
        Assert.Equal(before, File.ReadAllBytes(dats.PortalPath));
    }

    [Fact]
    public void TheCache_ConvertsEachIdOnce_AcrossThreads()
    {
        var cache = new ConvertedObjects();
        int conversions = 0;
        using var start = new Barrier(8);
        var results = new object[8];
        var threads = Enumerable.Range(0, 8).Select(t => new Thread(() =>
        {
            start.SignalAndWait();
            results[t] = cache.GetOrAdd(7u, id =>
            {
                Interlocked.Increment(ref conversions);
                Thread.Sleep(50);                          // every other thread arrives while this one converts
                return new object();
            });
        })).ToList();
        threads.ForEach(t => t.Start());
        threads.ForEach(t => t.Join());
        Assert.Equal(1, conversions);
        Assert.All(results, r => Assert.Same(results[0], r));
        Assert.Equal(1, cache.Count);
    }

    [Fact]
    public void TheCache_KeepsNoFailedConversion()
    {
        var cache = new ConvertedObjects();
        Assert.Throws<InvalidDataException>(() => cache.GetOrAdd<string>(5u, _ => throw new InvalidDataException("bad")));
        Assert.Equal(0, cache.Count);
        Assert.Equal("good", cache.GetOrAdd(5u, _ => "good"));
        Assert.True(cache.Contains<string>(5u));
        Assert.False(cache.Contains<object>(5u));                 // keyed by type too: a GfxObj model and a one-part setup of the same id
    }

    [Fact]
    public void AThreadWaitingOnAFailedConversion_ConvertsAgain_AndItsResultIsKept()
    {
        var cache = new ConvertedObjects();
        using var converting = new ManualResetEventSlim();
        Exception? failure = null;
        var first = new Thread(() =>
        {
            try
            {
                cache.GetOrAdd<string>(9u, _ =>
                {
                    converting.Set();
                    Thread.Sleep(100);                     // the second thread asks meanwhile and waits
                    throw new InvalidDataException("bad");
                });
            }
            catch (Exception ex)
            {
                failure = ex;
            }
        });
        first.Start();
        converting.Wait();
        string second = cache.GetOrAdd(9u, _ => "good");
        first.Join();
        Assert.IsType<InvalidDataException>(failure);
        Assert.Equal("good", second);
        Assert.Equal("good", cache.GetOrAdd<string>(9u, _ => throw new InvalidOperationException("converted twice")));
        Assert.Equal(1, cache.Count);
    }
}

/// <summary>
/// A compressed object (its index entry's IsCompressed flag) gives its inflated size in its first four bytes, and
/// DatReaderWriter allocates that many bytes before inflating: a damaged size is refused before the read, naming
/// the file and object, instead of an allocation of up to 4 GB (an OutOfMemoryException, or the memory taken).
/// </summary>
public class CompressedObjectTests
{
    private const uint Land = 0xA9B4FFFF;

    [Theory]
    [InlineData(0x7FFF_FFF0u)]
    [InlineData(0xFFFF_FFF0u)]
    [InlineData(DatFile.MaxObjectBytes + 1u)]
    public void AnInflatedSizeAboveTheCap_IsRefusedNamingTheObject(uint inflated)
    {
        using var dats = Write();
        SetInflatedSize(dats.CellPath, inflated);
        using var files = dats.Open();

        var ex = Assert.Throws<DatReadException>(() => files.ReadCell<LandBlock>(Land));

        Assert.Equal($"client_cell_1.dat 0x{Land:X8}: inflates to {inflated} bytes, more than the {DatFile.MaxObjectBytes} read.", ex.Message);
    }

    [Fact]
    public void ACompressedObjectWithinTheCap_IsRead()
    {
        using var dats = Write();
        using var files = dats.Open();
        Assert.Equal(WorldWriter.Land(0xA9B4).Height, files.ReadCell<LandBlock>(Land).Height);
    }

    // A LandBlock written compressed (its heights repeat, so it compresses), checked to be stored so.
    private static TempDats Write()
    {
        var dats = new TempDats();
        using var dat = new DatDatabase(o => { o.FilePath = dats.CellPath; o.AccessType = DatAccessType.ReadWrite; });
        var written = dat.TryWriteCompressed(WorldWriter.Land(0xA9B4));
        Assert.True(written.Success, written.Error);
        Assert.True(dat.Tree.TryGetFile(Land, out var entry) && entry.Flags.HasFlag(DatBTreeFileFlags.IsCompressed));
        return dats;
    }

    // The object's first payload bytes follow its first block's 4-byte link to the next block.
    private static void SetInflatedSize(string path, uint inflated)
    {
        int offset;
        using (var dat = new DatDatabase(o => { o.FilePath = path; o.AccessType = DatAccessType.Read; }))
        {
            Assert.True(dat.Tree.TryGetFile(Land, out var entry));
            offset = entry.Offset + 4;
        }
        using var stream = new FileStream(path, FileMode.Open, FileAccess.ReadWrite);
        stream.Position = offset;
        Span<byte> size = stackalloc byte[4];
        System.Buffers.Binary.BinaryPrimitives.WriteUInt32LittleEndian(size, inflated);
        stream.Write(size);
    }
}
