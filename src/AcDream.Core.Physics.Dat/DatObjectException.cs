using System;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// A DAT object the adapter refuses: a polygon our <see cref="Polygon"/> rejects, a BSP tree with an
/// out-of-range or cyclic child, a count beyond the runtime's limits, a reference to an id that is missing.
/// The message names the object ("GfxObj 0x01000A2B: physicsPolygons[17]: …") and, once known, the DAT file.
/// Nothing is built from a refused object.
/// </summary>
public sealed class DatObjectException : FormatException
{
    /// <summary>Creates the exception for object <paramref name="objectId"/>.</summary>
    /// <param name="objectId">The DAT object's id (for a land cell or landblock, the cell DAT id).</param>
    /// <param name="detail">What is wrong, starting with the field's path inside the object.</param>
    /// <param name="inner">The runtime's own exception, when it refused the converted value.</param>
    public DatObjectException(uint objectId, string detail, Exception? inner = null)
        : this(objectId, detail, null, inner) { }

    private DatObjectException(uint objectId, string detail, string? file, Exception? inner)
        : base(Compose(objectId, detail, file), inner)
    {
        ObjectId = objectId;
        Detail = detail ?? string.Empty;
        File = file;
    }

    /// <summary>The DAT object's id.</summary>
    public uint ObjectId { get; }

    /// <summary>What is wrong, without the object's name.</summary>
    public string Detail { get; }

    /// <summary>The DAT file the object was read from, when the reader named it (see <see cref="InFile"/>).</summary>
    public string? File { get; }

    /// <summary>The same refusal naming the DAT file it came from.</summary>
    /// <param name="file">The file's path or name.</param>
    public DatObjectException InFile(string file) => new(ObjectId, Detail, file, InnerException);

    /// <summary>The retail kind of a DAT id, by its range: 0x01 GfxObj, 0x02 Setup, 0x0D Environment, 0x13 Region; in the cell DAT, xxxxFFFF LandBlock, xxxxFFFE LandBlockInfo, else EnvCell.</summary>
    internal static string KindOf(uint id) => (id >> 24) switch
    {
        0x01 => "GfxObj",
        0x02 => "Setup",
        0x0D => "Environment",
        0x13 => "Region",
        _ => (id & 0xFFFF) switch
        {
            0xFFFF => "LandBlock",
            0xFFFE => "LandBlockInfo",
            _ => "EnvCell",
        },
    };

    private static string Compose(uint objectId, string? detail, string? file) =>
        (file is null ? string.Empty : file + ": ") + $"{KindOf(objectId)} 0x{objectId:X8}: {detail}";
}
