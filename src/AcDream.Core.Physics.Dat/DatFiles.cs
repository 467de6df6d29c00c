using System;
using System.IO;
using System.Threading;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// The two retail DAT files a physics world needs, open read-only and shared with other readers (a game client
/// may hold them too): <c>client_portal.dat</c> (models, setups, environments, the region, motion tables,
/// animations) and <c>client_cell_1.dat</c> (landblocks, their objects and buildings, indoor cells). Typed reads
/// by id, from any thread; the objects converted from them are kept in <see cref="Converted"/> and shared by
/// every world made from this instance. Dispose it after the last world that reads it.
/// </summary>
public sealed class DatFiles : IDisposable
{
    /// <summary>The portal DAT's file name.</summary>
    public const string PortalFileName = "client_portal.dat";
    /// <summary>The cell DAT's file name (the first, and in retail the only, cell file).</summary>
    public const string CellFileName = "client_cell_1.dat";

    private readonly DatFile _portal;
    private readonly DatFile _cell;

    /// <summary>Opens the two files.</summary>
    /// <param name="portalPath">The portal DAT.</param>
    /// <param name="cellPath">The cell DAT.</param>
    /// <exception cref="DatReadException">A file is missing, unreadable, not a DAT file, or the other one of the two; the message names it.</exception>
    public DatFiles(string portalPath, string cellPath)
    {
        ArgumentNullException.ThrowIfNull(portalPath);
        ArgumentNullException.ThrowIfNull(cellPath);
        _portal = DatFile.Open(portalPath, DatFileType.Portal);
        try
        {
            _cell = DatFile.Open(cellPath, DatFileType.Cell);
        }
        catch
        {
            _portal.Dispose();
            throw;
        }
    }

    /// <summary>Opens <see cref="PortalFileName"/> and <see cref="CellFileName"/> in a folder (a client's install folder).</summary>
    /// <exception cref="DatReadException">A file is missing, unreadable, not a DAT file, or the other one of the two.</exception>
    public static DatFiles Open(string directory)
    {
        ArgumentNullException.ThrowIfNull(directory);
        return new DatFiles(Path.Combine(directory, PortalFileName), Path.Combine(directory, CellFileName));
    }

    /// <summary>The portal DAT's path.</summary>
    public string PortalPath => _portal.Path;
    /// <summary>The cell DAT's path.</summary>
    public string CellPath => _cell.Path;
    /// <summary>The portal DAT's file name, as messages name it.</summary>
    public string PortalName => _portal.Name;
    /// <summary>The cell DAT's file name, as messages name it.</summary>
    public string CellName => _cell.Name;

    /// <summary>The portal DAT itself (tests watch its reads).</summary>
    internal DatFile Portal => _portal;
    /// <summary>The cell DAT itself (tests ask it what DatReaderWriter says of an id).</summary>
    internal DatFile Cell => _cell;

    /// <summary>The objects converted from these files, shared by every world made from them.</summary>
    public ConvertedObjects Converted { get; } = new();

    // The Region's LandDefs (the height table every landblock's terrain goes through): one per portal DAT, read on
    // the first landblock and kept for the files' lifetime, as retail reads its Region once at start-up. Not part of
    // Converted, whose Clear() forgets a landblock's models: this is a constant of the whole world.
    private DatReaderWriter.Types.LandDefs? _landDefs;

    /// <summary>
    /// The Region's (portal DAT <see cref="DatWorld.RegionId"/>) <c>LandDefs</c>, read once per opened files and kept
    /// until they are closed: a constant of the whole world, not a landblock's, so <see cref="ConvertedObjects.Clear"/>
    /// does not forget it. A failed read is not kept (the next call reads again and fails the same way).
    /// Any thread; two first calls at once may both read, and one result is kept.
    /// </summary>
    /// <exception cref="DatReadException">The Region is absent, of another type or unreadable.</exception>
    /// <exception cref="DatObjectException">The Region has no LandDefs (the message names its id; the file is added by the caller).</exception>
    internal DatReaderWriter.Types.LandDefs RegionLandDefs()
    {
        var cached = Volatile.Read(ref _landDefs);
        if (cached is not null)
            return cached;
        var read = _portal.Read<DatReaderWriter.DBObjs.Region>(DatWorld.RegionId).LandDefs
            ?? throw new DatObjectException(DatWorld.RegionId, "landDefs: the region has none.");
        return Interlocked.CompareExchange(ref _landDefs, read, null) ?? read;
    }

    /// <summary>Reads a portal DAT object (a GfxObj, Setup, Environment, Region, MotionTable, Animation, …).</summary>
    /// <exception cref="DatReadException">It is absent, of another type, too large or unreadable; the message names the file and id.</exception>
    public T ReadPortal<T>(uint id) where T : DBObj => _portal.Read<T>(id);

    /// <summary>Reads a cell DAT object (a LandBlock, LandBlockInfo or EnvCell).</summary>
    /// <exception cref="DatReadException">It is absent, of another type, too large or unreadable; the message names the file and id.</exception>
    public T ReadCell<T>(uint id) where T : DBObj => _cell.Read<T>(id);

    /// <summary>Whether the portal DAT holds an object with this id.</summary>
    public bool PortalContains(uint id) => _portal.Contains(id);
    /// <summary>Whether the cell DAT holds an object with this id.</summary>
    public bool CellContains(uint id) => _cell.Contains(id);

    /// <summary>Closes both files.</summary>
    public void Dispose()
    {
        _portal.Dispose();
        _cell.Dispose();
    }
}
