using DatReaderWriter;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.IO;
using DatReaderWriter.Options;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>
/// A temporary folder holding a portal and a cell DAT written by DatReaderWriter from objects a test gives (no
/// retail DAT file is used). Deleted on dispose.
/// </summary>
internal sealed class TempDats : IDisposable
{
    public TempDats(IEnumerable<DBObj>? portal = null, IEnumerable<DBObj>? cell = null)
    {
        Directory = Path.Combine(Path.GetTempPath(), "acdream-dat-" + Guid.NewGuid().ToString("N"));
        System.IO.Directory.CreateDirectory(Directory);
        Write(PortalPath, DatFileType.Portal, portal ?? []);
        Write(CellPath, DatFileType.Cell, cell ?? []);
    }

    public string Directory { get; }
    public string PortalPath => Path.Combine(Directory, DatFiles.PortalFileName);
    public string CellPath => Path.Combine(Directory, DatFiles.CellFileName);

    public DatFiles Open() => DatFiles.Open(Directory);

    /// <summary>Writes a DAT file of the given type holding the objects (each under its Id).</summary>
    public static void Write(string path, DatFileType type, IEnumerable<IDBObj> objects)
    {
        using var dat = new DatDatabase(o =>
        {
            o.FilePath = path;
            o.AccessType = DatAccessType.ReadWrite;
        });
        dat.BlockAllocator.InitNew(type, 0);
        foreach (var obj in objects)
        {
            var result = dat.TryWriteFile(obj);
            if (!result.Success)
                throw new InvalidOperationException($"writing 0x{obj.Id:X8} to {path}: {result.Error}");
        }
    }

    public void Dispose()
    {
        try { System.IO.Directory.Delete(Directory, recursive: true); } catch (IOException) { }
    }
}
