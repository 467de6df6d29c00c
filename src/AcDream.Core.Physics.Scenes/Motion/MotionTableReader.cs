using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Reads a motion table written in the scene format's JSON ("format": "ace-motion-table", version 1: the shape
/// of the ACE motion reference data's table.json, described in docs/scene-format.md). Every error is a
/// <see cref="SceneFormatException"/> naming the JSON path. Caps: <see cref="MaxTextLength"/> characters,
/// <see cref="MotionTable.MaxEntries"/> entries, <see cref="MotionTable.MaxFrames"/> frames per animation.
/// </summary>
public static class MotionTableReader
{
    /// <summary>The format name.</summary>
    public const string Format = "ace-motion-table";

    /// <summary>The longest text read, in characters.</summary>
    public const int MaxTextLength = 16 * 1024 * 1024;

    /// <summary>Parses a motion table's JSON text.</summary>
    /// <exception cref="SceneFormatException">The text is malformed or the table is invalid; the message names the JSON path.</exception>
    public static MotionTable Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (text.Length > MaxTextLength)
            throw new SceneFormatException(string.Empty, $"a motion table is at most {MaxTextLength} characters, got {text.Length}.");
        using var doc = JsonRead.Parse(text);
        return Read(doc.RootElement, string.Empty);
    }

    internal static MotionTable Read(JsonElement e, string path)
    {
        var o = new JsonObj(e, path);
        if (o.String("format", Format) != Format)
            throw new SceneFormatException(o.Child("format"), $"expected \"{Format}\", got \"{o.String("format")}\".");
        int version = o.Int("version", 1);
        if (version != 1)
            throw new SceneFormatException(o.Child("version"), $"unsupported version {version} (this reader reads version 1).");
        uint id = o.Id("id");
        uint defaultStyle = o.Id("defaultStyle");

        var styleDefaults = new Dictionary<uint, uint>();
        var sd = o.Obj("styleDefaults");
        foreach (var (name, value) in sd.Fields())
            styleDefaults[Key(name, sd.Child(name))] = JsonRead.Id(value, sd.Child(name));

        // The table's one count of entries (MotionTable.MaxEntries): animations, cycles, modifiers and every link, read
        // up to the cap and no further.
        int entries = 0;
        var animations = new List<Animation>();
        var an = o.Obj("animations");
        foreach (var (name, value) in an.Fields())
        {
            Count(ref entries, an.Child(name));
            animations.Add(ReadAnimation(Key(name, an.Child(name)), value, an.Child(name)));
        }

        var cycles = ReadMotions(o.Obj("cycles"), ref entries);
        var modifiers = ReadMotions(o.Obj("modifiers"), ref entries);
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>();
        var ln = o.Obj("links");
        foreach (var (name, value) in ln.Fields())
            links[Key(name, ln.Child(name))] = ReadMotions(new JsonObj(value, ln.Child(name)), ref entries);
        try
        {
            return new MotionTable(id, defaultStyle, styleDefaults, cycles, modifiers, links, animations);
        }
        catch (ArgumentException ex)
        {
            // The table names the field (e.g. "cycles[0x003D0005].anims[0].framerate"); prefix this object's path.
            throw new SceneFormatException(path, SceneFormatException.Wrap(string.Empty, ex).Detail, ex);
        }
    }

    private static Dictionary<uint, MotionData> ReadMotions(JsonObj o, ref int entries)
    {
        var motions = new Dictionary<uint, MotionData>();
        foreach (var (name, value) in o.Fields())
        {
            string at = o.Child(name);
            Count(ref entries, at);
            motions[Key(name, at)] = ReadMotion(value, at);
        }
        return motions;
    }

    private static void Count(ref int entries, string at)
    {
        if (++entries > MotionTable.MaxEntries)
            throw new SceneFormatException(at, $"a motion table holds at most {MotionTable.MaxEntries} entries (animations, cycles, modifiers and links together).");
    }

    private static MotionData ReadMotion(JsonElement e, string path)
    {
        var o = new JsonObj(e, path);
        int bitfield = o.Int("bitfield", 0);
        if (bitfield is < 0 or > 255)
            throw new SceneFormatException(o.Child("bitfield"), $"must be a byte (0 to 255), got {bitfield}.");
        int flags = o.Int("flags", 0);
        if (flags is < 0 or > 3)
            throw new SceneFormatException(o.Child("flags"), $"must be 0 to 3 (1 HasVelocity, 2 HasOmega), got {flags}.");
        var items = o.Array("anims");
        if (items.Count > MotionTable.MaxAnimsPerMotion)
            throw new SceneFormatException(o.Child("anims"), $"at most {MotionTable.MaxAnimsPerMotion} animations, got {items.Count}.");
        var anims = new AnimData[items.Count];
        for (int i = 0; i < anims.Length; i++)
        {
            var a = new JsonObj(items[i].Value, items[i].Path);
            anims[i] = new AnimData(a.Id("animId"), a.Int("lowFrame", 0), a.Int("highFrame", -1), a.Float("framerate"));
            a.End();
        }
        var velocity = o.Has("velocity") ? o.Vec3("velocity") : Vector3.Zero;
        var omega = o.Has("omega") ? o.Vec3("omega") : Vector3.Zero;
        o.End();
        return new MotionData((byte)bitfield, (MotionDataFlags)flags, anims, velocity, omega);
    }

    private static Animation ReadAnimation(uint id, JsonElement e, string path)
    {
        var o = new JsonObj(e, path);
        int frames = o.Int("numFrames", 0);
        if (frames is <= 0 or > MotionTable.MaxFrames)
            throw new SceneFormatException(o.Child("numFrames"), $"must be 1 to {MotionTable.MaxFrames}, got {frames}.");
        o.Int("flags", 0);
        o.Int("numParts", 1);
        o.Opt("partFrames");
        var items = o.Array("posFrames", optional: true);
        if (items.Count != 0 && items.Count != frames)
            throw new SceneFormatException(o.Child("posFrames"), $"none or one per frame ({frames}), got {items.Count}.");
        var roots = new RootFrame[items.Count];
        for (int i = 0; i < roots.Length; i++)
        {
            var f = new JsonObj(items[i].Value, items[i].Path);
            roots[i] = new RootFrame(f.Vec3("origin"), JsonRead.RawQuaternion(f.Req("orientation"), f.Child("orientation")));
            f.End();
        }
        o.End();
        return new Animation(id, frames, roots);
    }

    private static uint Key(string name, string path) => JsonRead.Id(name, path);
}
