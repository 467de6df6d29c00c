using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Motion;
using AnimationFlags = DatReaderWriter.Enums.AnimationFlags;
using DrwAnimation = DatReaderWriter.DBObjs.Animation;
using DrwMotionData = DatReaderWriter.Types.MotionData;
using DrwMotionTable = DatReaderWriter.DBObjs.MotionTable;

namespace AcDream.Core.Physics.Dat;

/// <summary>
/// Motion tables from the portal DAT: a <c>MotionTable</c> (0x09…, retail <c>CMotionTable</c>) and the
/// <c>Animation</c>s (0x03…, retail <c>CAnimation</c>) its motions play become the runtime's
/// <see cref="MotionTable"/>. Every key is kept as stored (the DAT's signed keys reinterpreted as the unsigned ids
/// the runtime looks up), every animation list in its order, every float as its bits. Of an animation only its
/// frame count and root frames (PosFrames) are physics; part frames and hooks are left out (docs/dat-mapping.md).
/// </summary>
public static class DatMotionTables
{
    /// <summary>The most animations one table may reference (the runtime's entry cap).</summary>
    public const int MaxAnimations = MotionTable.MaxEntries;

    /// <summary>An animation's physics: its id, its frame count (one per part-frame set) and, when it has them, its root frames.</summary>
    /// <exception cref="ArgumentException">Root frames whose count is not the frame count (a damaged object).</exception>
    public static Animation ToAnimation(DrwAnimation animation)
    {
        ArgumentNullException.ThrowIfNull(animation);
        int frames = animation.PartFrames.Count;
        var roots = new RootFrame[(animation.Flags & AnimationFlags.PosFrames) != 0 ? animation.PosFrames.Count : 0];
        if (roots.Length != 0 && roots.Length != frames)
            throw new ArgumentException($"posFrames: none or one per frame ({frames}), got {roots.Length}.", nameof(animation));
        for (int i = 0; i < roots.Length; i++)
        {
            // DatReaderWriter reads the stored (w, x, y, z) into System.Numerics' (x, y, z, w): the quaternion as stored.
            var frame = animation.PosFrames[i] ?? throw new ArgumentException($"posFrames[{i}]: is null.", nameof(animation));
            roots[i] = new RootFrame(frame.Origin, frame.Orientation);
        }
        return new Animation(animation.Id, frames, roots);
    }

    /// <summary>Every animation id a table's motions play, each once, in the order first met (cycles, modifiers, links).</summary>
    public static IReadOnlyList<uint> AnimationIds(DrwMotionTable table)
    {
        ArgumentNullException.ThrowIfNull(table);
        var seen = new HashSet<uint>();
        var ids = new List<uint>();
        void Add(DrwMotionData? data)
        {
            if (data is null)
                return;
            foreach (var anim in data.Anims)
                if (anim?.AnimId is { } id && seen.Add(id.DataId))
                    ids.Add(id.DataId);
        }
        foreach (var (_, data) in table.Cycles) Add(data);
        foreach (var (_, data) in table.Modifiers) Add(data);
        foreach (var (_, inner) in table.Links)
            if (inner is not null)
                foreach (var (_, data) in inner.MotionData) Add(data);
        return ids;
    }

    /// <summary>The runtime's table from a DAT table and the animations it plays (already converted).</summary>
    /// <exception cref="ArgumentException">The table is one the runtime refuses (a style default without its cycle, a
    /// missing animation, a frame range outside its animation, a bad framerate or vector); the message names the field.</exception>
    public static MotionTable ToMotionTable(DrwMotionTable table, IEnumerable<Animation> animations)
    {
        ArgumentNullException.ThrowIfNull(table);
        ArgumentNullException.ThrowIfNull(animations);
        var styleDefaults = new Dictionary<uint, uint>();
        foreach (var (style, substate) in table.StyleDefaults)
            styleDefaults[(uint)style] = (uint)substate;
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>();
        foreach (var (outer, inner) in table.Links)
            links[unchecked((uint)outer)] = Motions(inner?.MotionData ?? throw new ArgumentException($"links[0x{outer:X8}]: is null.", nameof(table)),
                $"links[0x{outer:X8}]");
        return new MotionTable(table.Id, (uint)table.DefaultStyle, styleDefaults, Motions(table.Cycles, "cycles"),
            Motions(table.Modifiers, "modifiers"), links, animations);
    }

    /// <summary>
    /// Reads a motion table and every animation it plays from the portal DAT and converts them, once per id: later
    /// calls (from any thread, any world) return the same table from <see cref="DatFiles.Converted"/>.
    /// </summary>
    /// <exception cref="DatReadException">The table or one of its animations is absent, of another type, unreadable,
    /// or refused by the runtime; the message names the portal DAT and the object's id.</exception>
    public static MotionTable Load(DatFiles files, uint id)
    {
        ArgumentNullException.ThrowIfNull(files);
        return files.Converted.GetOrAdd(id, tableId =>
        {
            var table = files.ReadPortal<DrwMotionTable>(tableId);
            var ids = AnimationIds(table);
            if (ids.Count > MaxAnimations)
                throw new DatReadException(files.PortalName, tableId, $"plays {ids.Count} animations, more than the {MaxAnimations} a table may.");
            var animations = new List<Animation>(ids.Count);
            foreach (uint animationId in ids)
            {
                if (!files.PortalContains(animationId))
                    throw new DatReadException(files.PortalName, tableId, $"plays animation 0x{animationId:X8}, which is absent.");
                try
                {
                    animations.Add(ToAnimation(files.ReadPortal<DrwAnimation>(animationId)));
                }
                catch (ArgumentException ex)
                {
                    throw new DatReadException(files.PortalName, animationId, ex.Message, ex);
                }
            }
            try
            {
                return ToMotionTable(table, animations);
            }
            catch (ArgumentException ex)
            {
                throw new DatReadException(files.PortalName, tableId, ex.Message, ex);
            }
        });
    }

    private static Dictionary<uint, MotionData> Motions(Dictionary<int, DrwMotionData> source, string field)
    {
        var motions = new Dictionary<uint, MotionData>(source.Count);
        foreach (var (key, data) in source)
        {
            string at = $"{field}[0x{unchecked((uint)key):X8}]";
            if (data is null)
                throw new ArgumentException($"{at}: is null.", field);
            if (data.Anims.Count > MotionTable.MaxAnimsPerMotion)
                throw new ArgumentException($"{at}.anims: at most {MotionTable.MaxAnimsPerMotion} animations, got {data.Anims.Count}.", field);
            var anims = new AnimData[data.Anims.Count];
            for (int i = 0; i < anims.Length; i++)
            {
                var a = data.Anims[i] ?? throw new ArgumentException($"{at}.anims[{i}]: is null.", field);
                anims[i] = new AnimData(a.AnimId?.DataId ?? 0, a.LowFrame, a.HighFrame, a.Framerate);
            }
            // The DAT stores a vector only under its flag; DatReaderWriter leaves the other zero, as the runtime wants.
            if ((byte)data.Flags > 3)
                throw new ArgumentException($"{at}.flags: must be 0 to 3 (1 HasVelocity, 2 HasOmega), got {(byte)data.Flags}.", field);
            var flags = (MotionDataFlags)(byte)data.Flags;
            var velocity = (flags & MotionDataFlags.HasVelocity) != 0 ? data.Velocity : default;
            var omega = (flags & MotionDataFlags.HasOmega) != 0 ? data.Omega : default;
            motions[unchecked((uint)key)] = new MotionData(data.Bitfield, flags, anims, velocity, omega);
        }
        return motions;
    }
}
