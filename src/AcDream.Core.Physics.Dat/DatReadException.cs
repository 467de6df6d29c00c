using System;
using System.IO;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// A DAT file or an object in it that cannot be used: the file is missing, unreadable, not a DAT file or the wrong
/// one of the two; an object is absent, of another type than asked, unreadable, or holds what the runtime rejects.
/// The message names the file and, when there is one, the object id.
/// </summary>
public sealed class DatReadException : IOException
{
    /// <summary>Creates the exception.</summary>
    /// <param name="file">The DAT file's name (e.g. client_cell_1.dat).</param>
    /// <param name="objectId">The object's id, or null for the file itself.</param>
    /// <param name="detail">What is wrong.</param>
    /// <param name="inner">The cause, when there is one.</param>
    public DatReadException(string file, uint? objectId, string detail, Exception? inner = null)
        : base(objectId is { } id ? $"{file} 0x{id:X8}: {detail}" : $"{file}: {detail}", inner)
    {
        File = file;
        ObjectId = objectId;
        Detail = detail;
    }

    /// <summary>The DAT file's name.</summary>
    public string File { get; }
    /// <summary>The object's id, or null when the file itself is at fault.</summary>
    public uint? ObjectId { get; }
    /// <summary>What is wrong, without the file and id.</summary>
    public string Detail { get; }
}
