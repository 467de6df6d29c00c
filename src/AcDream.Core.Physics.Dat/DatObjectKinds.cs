using System;
using System.Reflection;
using DatReaderWriter.Enums;
using DatReaderWriter.Lib.Attributes;
using DatReaderWriter.Types;
using Obj = DatReaderWriter.DBObjs;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// The object type an id has in a DAT file, as DatReaderWriter's <c>DatDatabase.TypeFromId</c> gives it, answered
/// from its types' <see cref="DBObjTypeAttribute"/>s without the call where the answer is unambiguous, and each
/// type's own file and object type (what a read checks before it unpacks). The call walks every type's attribute
/// through LINQ on each read (about 0.3-0.5 µs and 400 bytes a read); this answers from a few small arrays. Its
/// rules are DatReaderWriter 2.1.4's: in a cell file an exact id, else a mask on the low 16 bits, else an EnvCell;
/// in a portal file an exact id, else a range. Where two types would match (an order DatReaderWriter's dictionary
/// decides), or for any other file, it answers null and the caller asks DatReaderWriter (tests check both agree
/// over every kind's ids and their edges).
/// </summary>
/// <remarks>
/// The attributes of the DatReaderWriter version this package references are written out below
/// (<see cref="Written"/>; a test checks them against the attributes themselves). Reading them by reflection
/// instead loads every one of DatReaderWriter's ~400 types and parses 53 attributes, which made a process's first
/// landblock load 10-18 ms slower on the 2-core test machine (docs/performance.md, "The first load in a process");
/// the table's types cost about 2 ms to load. Under any other DatReaderWriter version they are read by reflection
/// (<see cref="FromAttributes"/>), as before.
/// </remarks>
internal static class DatObjectKinds
{
    /// <summary>One DatReaderWriter object type and its attribute's values.</summary>
    internal readonly record struct Kind(Type Type, DatFileType File, DBObjType ObjectType, uint FirstId, uint LastId, uint MaskId)
    {
        public bool IsExact => FirstId != 0 && FirstId == LastId;
        public bool IsMask => MaskId != 0;
        public bool IsRange => LastId != 0 && FirstId != LastId;
    }

    /// <summary>Whether the loaded DatReaderWriter is the version <see cref="Written"/> was taken from (<see cref="DatPackage.ReaderVersion"/>).</summary>
    internal static readonly bool UsesWrittenTable = IsReferencedVersion(typeof(DBObj).Assembly.GetName().Version);

    /// <summary>Every DBObj type that carries the attribute (the table, or the attributes read by reflection).</summary>
    internal static readonly Kind[] All = UsesWrittenTable ? Written() : FromAttributes();

    private static readonly Kind[] CellExact = Select(DatFileType.Cell, Rule.Exact), CellMasks = Select(DatFileType.Cell, Rule.Mask);
    private static readonly Kind[] PortalExact = Select(DatFileType.Portal, Rule.Exact), PortalRanges = Select(DatFileType.Portal, Rule.Range);
    private static readonly DBObjType EnvCellType = OfType(typeof(Obj.EnvCell))?.ObjectType ?? DBObjType.Unknown;

    /// <summary>The type of <paramref name="id"/> in a file of type <paramref name="file"/>, or null when the caller must ask DatReaderWriter.</summary>
    public static DBObjType? Of(DatFileType file, uint id)
    {
        if (file is not (DatFileType.Cell or DatFileType.Portal))
            return null;
        int found = 0;
        DBObjType type = DBObjType.Unknown;
        // Indexed loops over the arrays: no span or enumerator of Kind for the first load to compile.
        var exact = file == DatFileType.Cell ? CellExact : PortalExact;
        for (int i = 0; i < exact.Length; i++)
            if (exact[i].FirstId == id) { found++; type = exact[i].ObjectType; }
        if (found > 0)
            return found == 1 ? type : null;
        if (file == DatFileType.Cell)
        {
            for (int i = 0; i < CellMasks.Length; i++)
                if ((id & 0xFFFF) == CellMasks[i].MaskId) { found++; type = CellMasks[i].ObjectType; }
            return found switch { 0 => EnvCellType, 1 => type, _ => null };
        }
        for (int i = 0; i < PortalRanges.Length; i++)
            if (id >= PortalRanges[i].FirstId && id <= PortalRanges[i].LastId) { found++; type = PortalRanges[i].ObjectType; }
        return found switch { 0 => DBObjType.Unknown, 1 => type, _ => null };
    }

    /// <summary>
    /// The file and object type of a DBObj type, as its own <see cref="DBObjTypeAttribute"/> says (DatReaderWriter does
    /// not let it be inherited): from the table for DatReaderWriter's own types, else read from the type; null when
    /// it has none.
    /// </summary>
    public static Kind? OfType(Type type)
    {
        for (int i = 0; i < All.Length; i++)
            if (All[i].Type == type)
                return All[i];
        return type.GetCustomAttribute<DBObjTypeAttribute>() is { } a ? ToKind(type, a) : null;
    }

    private static bool IsReferencedVersion(Version? loaded)
    {
        var referenced = Version.Parse(DatPackage.ReaderVersion);
        return loaded is not null && loaded.Major == referenced.Major && loaded.Minor == referenced.Minor && loaded.Build == referenced.Build;
    }

    private enum Rule { Exact, Mask, Range }

    // The kinds of one file that one of DatReaderWriter's three lookups looks at.
    private static Kind[] Select(DatFileType file, Rule rule)
    {
        int count = 0;
        for (int i = 0; i < All.Length; i++)
            if (All[i].File == file && Matches(All[i], rule))
                count++;
        var selected = new Kind[count];
        count = 0;
        for (int i = 0; i < All.Length; i++)
            if (All[i].File == file && Matches(All[i], rule))
                selected[count++] = All[i];
        return selected;
    }

    private static bool Matches(in Kind k, Rule rule) => rule switch
    {
        Rule.Exact => k.IsExact,
        Rule.Mask => k.IsMask,
        _ => k.IsRange,
    };

    private static Kind ToKind(Type type, DBObjTypeAttribute a) => new(type, a.DatFileType, a.DBObjType, a.FirstId, a.LastId, a.MaskId);

    /// <summary>The attributes of every DBObj type of DatReaderWriter's assembly, read by reflection (any version).</summary>
    internal static Kind[] FromAttributes()
    {
        var kinds = new System.Collections.Generic.List<Kind>();
        foreach (var type in typeof(DBObj).Assembly.GetTypes())
            if (type.IsSubclassOf(typeof(DBObj)) && type.GetCustomAttributes(typeof(DBObjTypeAttribute), true) is [DBObjTypeAttribute a, ..])
                kinds.Add(ToKind(type, a));
        return kinds.ToArray();
    }

    /// <summary>DatReaderWriter 2.1.4's DBObj types and their attributes' values, sorted by type name.</summary>
    internal static Kind[] Written() =>
    [
        new(typeof(Obj.ActionMap), DatFileType.Portal, DBObjType.DBProperties, 0x26000000, 0x2600FFFF, 0),
        new(typeof(Obj.Animation), DatFileType.Portal, DBObjType.Animation, 0x03000000, 0x0300FFFF, 0x03000000),
        new(typeof(Obj.BadDataTable), DatFileType.Portal, DBObjType.BadDataTable, 0x0E00001A, 0x0E00001A, 0),
        new(typeof(Obj.CharGen), DatFileType.Portal, DBObjType.CharGen, 0x0E000002, 0x0E000002, 0),
        new(typeof(Obj.ChatPoseTable), DatFileType.Portal, DBObjType.ChatPoseTable, 0x0E000007, 0x0E000007, 0),
        new(typeof(Obj.ClothingTable), DatFileType.Portal, DBObjType.ClothingTable, 0x10000000, 0x1000FFFF, 0),
        new(typeof(Obj.CombatTable), DatFileType.Portal, DBObjType.CombatTable, 0x30000000, 0x3000FFFF, 0),
        new(typeof(Obj.ContractTable), DatFileType.Portal, DBObjType.ContractTable, 0x0E00001D, 0x0E00001D, 0),
        new(typeof(Obj.DBProperties), DatFileType.Portal, DBObjType.DBProperties, 0x78000000, 0x7FFFFFFF, 0),
        new(typeof(Obj.DualEnumIDMap), DatFileType.Portal, DBObjType.DualEnumIDMap, 0x27000000, 0x27FFFFFF, 0),
        new(typeof(Obj.EnumIDMap), DatFileType.Portal, DBObjType.EnumIDMap, 0x25000000, 0x25FFFFFF, 0),
        new(typeof(Obj.EnumMapper), DatFileType.Portal, DBObjType.EnumMapper, 0x22000000, 0x22FFFFFF, 0),
        new(typeof(Obj.EnvCell), DatFileType.Cell, DBObjType.EnvCell, 0, 0, 0),
        new(typeof(Obj.Environment), DatFileType.Portal, DBObjType.Environment, 0x0D000000, 0x0D00FFFF, 0x0D000000),
        new(typeof(Obj.ExperienceTable), DatFileType.Portal, DBObjType.ExperienceTable, 0x0E000018, 0x0E000018, 0),
        new(typeof(Obj.Font), DatFileType.Portal, DBObjType.Font, 0x40000000, 0x40000FFF, 0),
        new(typeof(Obj.GfxObj), DatFileType.Portal, DBObjType.GfxObj, 0x01000000, 0x0100FFFF, 0x01000000),
        new(typeof(Obj.GfxObjDegradeInfo), DatFileType.Portal, DBObjType.GfxObjDegradeInfo, 0x11000000, 0x1100FFFF, 0),
        new(typeof(Obj.Iteration), DatFileType.Undefined, DBObjType.Iteration, 0xFFFF0001, 0xFFFF0001, 0),
        new(typeof(Obj.LandBlock), DatFileType.Cell, DBObjType.LandBlock, 0, 0, 0x0000FFFF),
        new(typeof(Obj.LandBlockInfo), DatFileType.Cell, DBObjType.LandBlockInfo, 0, 0, 0x0000FFFE),
        new(typeof(Obj.LanguageInfo), DatFileType.Local, DBObjType.LanguageInfo, 0x41000000, 0x41FFFFFF, 0),
        new(typeof(Obj.LanguageString), DatFileType.Portal, DBObjType.LanguageString, 0x31000000, 0x3100FFFF, 0),
        new(typeof(Obj.LayoutDesc), DatFileType.Local, DBObjType.LayoutDesc, 0x21000000, 0x21FFFFFF, 0),
        new(typeof(Obj.MasterInputMap), DatFileType.Portal, DBObjType.MasterInputMap, 0x14000000, 0x1400FFFF, 0),
        new(typeof(Obj.MasterProperty), DatFileType.Portal, DBObjType.MasterProperty, 0x39000000, 0x39FFFFFF, 0),
        new(typeof(Obj.MaterialInstance), DatFileType.Portal, DBObjType.MaterialInstance, 0x18000000, 0x18FFFFFF, 0),
        new(typeof(Obj.MaterialModifier), DatFileType.Portal, DBObjType.MaterialModifier, 0x17000000, 0x17FFFFFF, 0),
        new(typeof(Obj.MotionTable), DatFileType.Portal, DBObjType.MotionTable, 0x09000000, 0x0900FFFF, 0x09000000),
        new(typeof(Obj.NameFilterTable), DatFileType.Portal, DBObjType.NameFilterTable, 0x0E000020, 0x0E000020, 0),
        new(typeof(Obj.ObjectHierarchy), DatFileType.Portal, DBObjType.ObjectHierarchy, 0x0E00000D, 0x0E00000D, 0),
        new(typeof(Obj.PalSet), DatFileType.Portal, DBObjType.PalSet, 0x0F000000, 0x0F00FFFF, 0),
        new(typeof(Obj.Palette), DatFileType.Portal, DBObjType.Palette, 0x04000000, 0x0400FFFF, 0x04000000),
        new(typeof(Obj.ParticleEmitter), DatFileType.Portal, DBObjType.ParticleEmitter, 0x32000000, 0x3200FFFF, 0),
        new(typeof(Obj.PhysicsScript), DatFileType.Portal, DBObjType.PhysicsScript, 0x33000000, 0x3300FFFF, 0),
        new(typeof(Obj.PhysicsScriptTable), DatFileType.Portal, DBObjType.PhysicsScriptTable, 0x34000000, 0x3400FFFF, 0),
        new(typeof(Obj.QualityFilter), DatFileType.Portal, DBObjType.QualityFilter, 0x0E010000, 0x0E01FFFF, 0),
        new(typeof(Obj.Region), DatFileType.Portal, DBObjType.Region, 0x13000000, 0x1300FFFF, 0),
        new(typeof(Obj.RenderMaterial), DatFileType.Portal, DBObjType.RenderMaterial, 0x16000000, 0x16FFFFFF, 0),
        new(typeof(Obj.RenderSurface), DatFileType.Portal, DBObjType.RenderSurface, 0x06000000, 0x07FFFFFF, 0x06000000),
        new(typeof(Obj.RenderTexture), DatFileType.Portal, DBObjType.RenderTexture, 0x15000000, 0x15FFFFFF, 0),
        new(typeof(Obj.Scene), DatFileType.Portal, DBObjType.Scene, 0x12000000, 0x1200FFFF, 0),
        new(typeof(Obj.Setup), DatFileType.Portal, DBObjType.Setup, 0x02000000, 0x0200FFFF, 0),
        new(typeof(Obj.SkillTable), DatFileType.Portal, DBObjType.SkillTable, 0x0E000004, 0x0E000004, 0),
        new(typeof(Obj.SoundTable), DatFileType.Portal, DBObjType.SoundTable, 0x20000000, 0x2000FFFF, 0),
        new(typeof(Obj.SpellComponentTable), DatFileType.Portal, DBObjType.SpellComponentTable, 0x0E00000F, 0x0E00000F, 0),
        new(typeof(Obj.SpellTable), DatFileType.Portal, DBObjType.SpellTable, 0x0E00000E, 0x0E00000E, 0),
        new(typeof(Obj.StringTable), DatFileType.Local, DBObjType.StringTable, 0x23000000, 0x24FFFFFF, 0),
        new(typeof(Obj.Surface), DatFileType.Portal, DBObjType.Surface, 0x08000000, 0x0800FFFF, 0x08000000),
        new(typeof(Obj.SurfaceTexture), DatFileType.Portal, DBObjType.SurfaceTexture, 0x05000000, 0x05FFFFFF, 0x05000000),
        new(typeof(Obj.TabooTable), DatFileType.Portal, DBObjType.TabooTable, 0x0E00001E, 0x0E00001E, 0),
        new(typeof(Obj.VitalTable), DatFileType.Portal, DBObjType.VitalTable, 0x0E000003, 0x0E000003, 0),
        new(typeof(Obj.Wave), DatFileType.Portal, DBObjType.Wave, 0x0A000000, 0x0A00FFFF, 0x0A000000),
    ];
}
