using DatReaderWriter;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.IO;
using DatReaderWriter.Options;

namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>A portal and a cell DAT file written into a temporary folder with DatReaderWriter, then opened read-only.</summary>
internal sealed class WrittenDats : IDisposable
{
    private WrittenDats(string folder, DatDatabase portal, DatDatabase cell)
    {
        Folder = folder;
        Portal = portal;
        Cell = cell;
    }

    public string Folder { get; }
    public DatDatabase Portal { get; }
    public DatDatabase Cell { get; }

    /// <summary>Writes the objects (portal ones: GfxObj, Setup, Environment; cell ones: the rest) and opens both files to read.</summary>
    public static WrittenDats Write(IEnumerable<IDBObj> portalObjects, IEnumerable<IDBObj> cellObjects)
    {
        string folder = Path.Combine(Path.GetTempPath(), "acdream-dat-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        string portal = Path.Combine(folder, "client_portal.dat"), cell = Path.Combine(folder, "client_cell_1.dat");
        TempDats.Write(portal, DatFileType.Portal, portalObjects);
        TempDats.Write(cell, DatFileType.Cell, cellObjects);
        return new WrittenDats(folder, Open(portal), Open(cell));
    }

    private static DatDatabase Open(string path) => new(o =>
    {
        o.FilePath = path;
        o.FileCachingStrategy = FileCachingStrategy.Never;
    });

    public T Get<T>(DatDatabase dat, uint id) where T : IDBObj =>
        dat.TryGet<T>(id, out var value) ? value : throw new InvalidOperationException($"0x{id:X8} is not in the DAT as a {typeof(T).Name}.");

    public void Dispose()
    {
        Portal.Dispose();
        Cell.Dispose();
        try { Directory.Delete(Folder, recursive: true); } catch (IOException) { }
    }
}
