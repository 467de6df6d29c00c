using System;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Reads the position managers' files of the manager parity data (StickyManager and InterpolationManager recorded
/// quantum by quantum; described in the reference data's README): the calls from the frames' recorded events
/// ("@InterpolateTo(x, y, z)", "PhysicsObj.stick_to_object(id)"), the target from the frames' first other object.
/// A y of 192 m or more is the north landblock 0xA9B5 (the 150 m update). Errors name the JSON path. Load-time only.
/// </summary>
internal static class PositionManagerParityReader
{
    private const uint Block = 0xA9B4, NorthBlock = 0xA9B5;

    public static PositionManagerParityFile Read(JsonElement root, string name, string directory)
    {
        var o = new JsonObj(root, string.Empty);
        // Read by ParityReader (format, version) or words for a reader (the rest; "events" repeats the frames' calls).
        MotionParityReader.Informational(o, "format", "version", "ace", "name", "description", "scheduling", "events");
        var table = MotionParityReader.ReadTable(o, directory);
        double rate = MotionParityReader.ReadRate(o);
        var m = o.Obj("mover");
        var skills = MoveToParityReader.RetailPlayerSkills(m, table);
        uint id = m.Has("id") ? m.Id("id") : 0x50000001u;
        var mover = MoverDescription.Player(objectId: id, stepDownHeight: 0.04f);
        MotionParityReader.Informational(m, "weenie", "state", "runRate");
        m.End();
        var s = o.Obj("start");
        var origin = s.Vec3("origin");
        var start = MoverState.OnFloor(At(origin, s.Child("origin")), 0f);
        // The start is placed on the floor; ACE's cell, heading, orientation, contact and clock are not compared.
        MotionParityReader.Informational(s, "cell", "aceHeading", "orientation", "contact", "time");
        s.End();
        var targetStart = new Position(0, Vector3.Zero);
        foreach (var (value, at) in o.Array("objects", optional: true))
        {
            var other = new JsonObj(value, at);
            if (other.String("role", null) == "target")
                targetStart = At(other.Vec3("start"), other.Child("start"));
        }
        var items = o.Array("frames");
        if (items.Count == 0 || items.Count > SceneLoader.MaxFramesPerMover)
            throw new SceneFormatException("frames", $"needs 1 to {SceneLoader.MaxFramesPerMover} frames, got {items.Count}.");
        var frames = new PositionFrame[items.Count];
        for (int i = 0; i < frames.Length; i++)
            frames[i] = ReadFrame(items[i].Value, items[i].Path);
        if (targetStart.CellId == 0 && Array.Exists(frames, x => x.StickTo != 0))
            throw new SceneFormatException("objects", "a stick_to_object needs an object with the role \"target\" (its start).");
        RecordedWorld.CheckManagerObjects(o);
        var world = MotionParityReader.SharedWorld();
        o.End();
        return new PositionManagerParityFile(name, world, mover, table, skills, start, targetStart, 1.0 / rate, frames);
    }

    private static PositionFrame ReadFrame(JsonElement e, string path)
    {
        var f = new JsonObj(e, path);
        Position? interpolateTo = null;
        uint stickTo = 0;
        bool threw = false;
        var c = CultureInfo.InvariantCulture;
        foreach (var (value, at) in f.Array("commands"))
        {
            string text = JsonRead.String(value, at);
            if (text.StartsWith("@InterpolateTo(", StringComparison.Ordinal))
            {
                int close = text.IndexOf(')');
                var xyz = close < 0 ? [] : text["@InterpolateTo(".Length..close].Split(',', StringSplitOptions.TrimEntries);
                if (xyz.Length != 3 || !float.TryParse(xyz[0], NumberStyles.Float, c, out float x) || !float.TryParse(xyz[1], NumberStyles.Float, c, out float y)
                    || !float.TryParse(xyz[2], NumberStyles.Float, c, out float z) || !float.IsFinite(x) || !float.IsFinite(y) || !float.IsFinite(z))
                    throw new SceneFormatException(at, $"unreadable position in \"{text}\".");
                interpolateTo = At(new Vector3(x, y, z), at);
            }
            else if (text.StartsWith("PhysicsObj.stick_to_object(", StringComparison.Ordinal))
            {
                int close = text.IndexOf(')');
                string arg = close < 0 ? "" : text["PhysicsObj.stick_to_object(".Length..close];
                stickTo = arg.StartsWith("0x", StringComparison.Ordinal) && uint.TryParse(arg[2..], NumberStyles.AllowHexSpecifier, c, out uint v) && v != 0 ? v
                    : throw new SceneFormatException(at, $"unreadable object id in \"{text}\".");
            }
            else if (text.Contains("UpdateObjectInternal threw", StringComparison.Ordinal))
                threw = true;
        }
        Position? target = null;
        var others = f.Array("others", optional: true);
        if (others.Count > 0)
        {
            var other = new JsonObj(others[0].Value, others[0].Path);
            target = new Position(other.Id("cell"), other.Vec3("origin"));
        }
        bool stuck = f.Opt("sticky") is { ValueKind: JsonValueKind.Object } st && new JsonObj(st, f.Child("sticky")).Id("targetID") != 0;
        var frame = new PositionFrame(interpolateTo, stickTo, target, f.Vec3("origin"), f.Id("cell"), f.Float("aceHeading"), threw, stuck);
        // Compared: the position, cell, heading, the target's place and whether the mover sticks; the rest is ACE's
        // state beside them (the frame's index and times follow the file's rate).
        MotionParityReader.Informational(f, "frame", "t", "time", "quantum", "quantumRan", "orientation", "velocity", "cachedVelocity", "sliding",
            "transientState", "isAnimating", "contact", "onWalkable", "interpreted", "motionState", "moveTo", "targetInfo", "interpolation");
        f.End();
        return frame;
    }

    // The recorded positions run on north across the landblock edge (y 192 m and more is 0xA9B5).
    private static Position At(Vector3 p, string path)
    {
        if (!(p.X >= 0f && p.X < 192f && p.Y >= 0f && p.Y < 384f))
            throw new SceneFormatException(path, $"{p} is outside landblocks 0xA9B4 and 0xA9B5.");
        uint block = p.Y >= 192f ? NorthBlock : Block;
        var local = p.Y >= 192f ? p with { Y = p.Y - 192f } : p;
        return new Position(LandDefs.LandCellAt(block, local), local);
    }
}
