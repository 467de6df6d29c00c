using System;
using System.Collections.Generic;
using System.Reflection;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.Attributes;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// The object type an id has in a DAT file, as DatReaderWriter's <c>DatDatabase.TypeFromId</c> gives it, answered
/// from its types' own <see cref="DBObjTypeAttribute"/>s without the call where the answer is unambiguous. The call
/// walks every type's attribute through LINQ on each read (about 0.3-0.5 µs and 400 bytes a read, 16 reads a
/// landblock); this answers from a few small arrays made once. Its rules are DatReaderWriter 2.1.4's: in a cell
/// file an exact id, else a mask on the low 16 bits, else an EnvCell; in a portal file an exact id, else a range.
/// Where two types would match (an order DatReaderWriter's dictionary decides), or for any other file, it answers
/// null and the caller asks DatReaderWriter (tests check both agree over every kind's ids and their edges).
/// </summary>
internal static class DatObjectKinds
{
    private sealed record Kinds((uint Id, DBObjType Type)[] Exact, (uint Mask, DBObjType Type)[] Masks, (uint First, uint Last, DBObjType Type)[] Ranges);

    private static readonly Kinds Cell = Of(DatFileType.Cell), Portal = Of(DatFileType.Portal);
    private static readonly DBObjType EnvCellType = typeof(DatReaderWriter.DBObjs.EnvCell).GetCustomAttribute<DBObjTypeAttribute>(true)?.DBObjType ?? DBObjType.Unknown;

    /// <summary>The type of <paramref name="id"/> in a file of type <paramref name="file"/>, or null when the caller must ask DatReaderWriter.</summary>
    public static DBObjType? Of(DatFileType file, uint id)
    {
        if (file is not (DatFileType.Cell or DatFileType.Portal))
            return null;
        var kinds = file == DatFileType.Cell ? Cell : Portal;
        int found = 0;
        DBObjType type = DBObjType.Unknown;
        foreach (var (exact, t) in kinds.Exact)
            if (exact == id) { found++; type = t; }
        if (found > 0)
            return found == 1 ? type : null;
        if (file == DatFileType.Cell)
        {
            foreach (var (mask, t) in kinds.Masks)
                if ((id & 0xFFFF) == mask) { found++; type = t; }
            return found switch { 0 => EnvCellType, 1 => type, _ => null };
        }
        foreach (var (first, last, t) in kinds.Ranges)
            if (id >= first && id <= last) { found++; type = t; }
        return found switch { 0 => DBObjType.Unknown, 1 => type, _ => null };
    }

    // The attributes of DatReaderWriter's object types of one file, sorted as its three lookups sort them.
    private static Kinds Of(DatFileType file)
    {
        var exact = new List<(uint, DBObjType)>();
        var masks = new List<(uint, DBObjType)>();
        var ranges = new List<(uint, uint, DBObjType)>();
        foreach (var type in typeof(DBObj).Assembly.GetTypes())
        {
            if (!type.IsSubclassOf(typeof(DBObj)) || type.GetCustomAttributes(typeof(DBObjTypeAttribute), true) is not [DBObjTypeAttribute a, ..])
                continue;
            if (a.DatFileType != file)
                continue;
            if (a.FirstId != 0 && a.FirstId == a.LastId)
                exact.Add((a.FirstId, a.DBObjType));
            if (a.MaskId != 0)
                masks.Add((a.MaskId, a.DBObjType));
            if (a.LastId != 0 && a.FirstId != a.LastId)
                ranges.Add((a.FirstId, a.LastId, a.DBObjType));
        }
        return new Kinds(exact.ToArray(), masks.ToArray(), ranges.ToArray());
    }
}
