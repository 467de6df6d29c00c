using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Reads a MoveTo file of the "ace-manager-parity" data (ACE's MoveToManager, StickyManager and InterpolationManager recorded quantum by
/// quantum on the ace-motion world and table; described in the reference data's README). The MoveTo calls are read from
/// the frames' recorded ACE calls; a MoveToObject's target updates from the recorded TargetInfo (a new lastUpdateTime).
/// Files of the position managers (sticky, interpolate) are read by <see cref="PositionManagerParityReader"/>. Errors name the JSON path. Load-time only.
/// </summary>
internal static class MoveToParityReader
{
    public static MoveToParityFile Read(JsonElement root, string name, string directory)
    {
        var o = new JsonObj(root, string.Empty);
        // Read by ParityReader (format, version) or words for a reader (the rest; "events" repeats the frames' calls).
        MotionParityReader.Informational(o, "format", "version", "ace", "name", "description", "scheduling", "events");
        var table = MotionParityReader.ReadTable(o, directory);
        double rate = MotionParityReader.ReadRate(o);
        var m = o.Obj("mover");
        var skills = RetailPlayerSkills(m, table);
        // The mover is the retail player (RetailPlayerSkills checks it); its ids, state bits and ACE's run rate
        // (which the skills decide here) are not compared.
        MotionParityReader.Informational(m, "id", "weenie", "state", "runRate");
        m.End();
        // The retail player (its spheres, step heights 0.6 and 0.04), Gravity as the README's mover.
        var mover = MoverDescription.Player().With(physicsState: PhysicsState.Gravity | PhysicsState.EdgeSlide);
        var s = o.Obj("start");
        uint cell = s.Id("cell");
        var origin = s.Vec3("origin");
        var orientation = JsonRead.Rotation(s.Req("orientation"), s.Child("orientation"));
        // The start is placed on the floor; ACE's heading, contact and clock at the start are not compared.
        MotionParityReader.Informational(s, "aceHeading", "contact", "time");
        s.End();
        RecordedWorld.CheckManagerObjects(o);
        var world = MotionParityReader.SharedWorld();
        if (world.Cells.Get(cell) is null || LandDefs.LandCellAt(0xA9B4, origin) != cell)
            throw new SceneFormatException(s.Child("cell"), $"0x{cell:X8} is not the landblock 0xA9B4 cell of {origin}.");
        var start = MoverState.OnFloor(new Position(cell, new Frame(origin, orientation)), 0f);

        var items = o.Array("frames");
        if (items.Count == 0 || items.Count > SceneLoader.MaxFramesPerMover)
            throw new SceneFormatException("frames", $"needs 1 to {SceneLoader.MaxFramesPerMover} frames, got {items.Count}.");
        var frames = new MoveToFrame[items.Count];
        double lastUpdate = double.NaN;
        var previousOrigin = origin;
        for (int i = 0; i < frames.Length; i++)
        {
            frames[i] = ReadFrame(items[i].Value, items[i].Path, previousOrigin, ref lastUpdate);
            previousOrigin = frames[i].Origin;
        }
        string description = o.String("description", string.Empty) ?? string.Empty;
        o.End();
        return new MoveToParityFile(name, description, world, mover, table, skills, start, 1.0 / rate, frames);
    }

    /// <summary>The file's mover, which must be the retail player with the file's table: its Run skill.</summary>
    internal static RetailSkills RetailPlayerSkills(JsonObj m, MotionTable table)
    {
        if (!m.String("setup").StartsWith("retail player", StringComparison.Ordinal))
            throw new SceneFormatException(m.Child("setup"), "only the retail player setup is known.");
        if (m.Id("motionTable") != table.Id)
            throw new SceneFormatException(m.Child("motionTable"), $"names 0x{m.Id("motionTable"):X8}, but the table file is 0x{table.Id:X8}.");
        try
        {
            return new RetailSkills(m.Int("runSkill", -1), 0, 0f);
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap("mover.runSkill", ex);
        }
    }

    private static MoveToFrame ReadFrame(JsonElement e, string path, Vector3 before, ref double lastUpdate)
    {
        var f = new JsonObj(e, path);
        var calls = new List<MoveToCall>();
        string? completed = null;
        foreach (var (value, at) in f.Array("commands"))
        {
            string text = JsonRead.String(value, at);
            if (text.StartsWith("WeenieObject.OnMoveComplete(", StringComparison.Ordinal))
                completed = text["WeenieObject.OnMoveComplete(".Length..].TrimEnd(')');
            else if (text.StartsWith("PhysicsObj.", StringComparison.Ordinal))
                calls.Add(ParseCall(text, at, before) with { Path = at });
        }
        Position? update = null, interpolated = null;
        if (f.Opt("targetInfo") is { ValueKind: JsonValueKind.Object } ti)
        {
            var t = new JsonObj(ti, f.Child("targetInfo"));
            double time = JsonRead.Double(t.Req("lastUpdateTime"), t.Child("lastUpdateTime"));
            if (!(time == lastUpdate))
            {
                lastUpdate = time;
                var p = t.Obj("targetPosition");
                update = new Position(p.Id("cell"), p.Vec3("origin"));
                EndPosition(p);
                var q = t.Obj("interpolatedPosition");
                interpolated = new Position(q.Id("cell"), q.Vec3("origin"));
                EndPosition(q);
            }
            // The target's id, radius, status, velocity and quantum: ACE's bookkeeping, not compared; an update
            // is known by its time (the positions are read only when it changes).
            MotionParityReader.Informational(t, "objectID", "quantum", "radius", "status", "velocity", "targetPosition", "interpolatedPosition");
            t.End();
        }
        var i = f.Obj("interpreted");
        var mt = f.Opt("moveTo") is { ValueKind: JsonValueKind.Object } mte ? new JsonObj(mte, f.Child("moveTo")) : (JsonObj?)null;
        var kind = MoveToKind.Invalid;
        uint command = 0, aux = 0;
        int fails = 0;
        if (mt is { } mv)
        {
            string type = mv.String("movementType");
            kind = Enum.TryParse<MoveToKind>(type, out var k) ? k
                : throw new SceneFormatException(mv.Child("movementType"), $"unknown movement type \"{type}\".");
            command = mv.Id("currentCommand");
            aux = mv.Id("auxCommand");
            fails = mv.Int("failProgressCount", 0);
            // The manager's inner state (distances, times, nodes, positions) is ACE's and not compared: the
            // mover's position, motion and the counts above show where it leads.
            MotionParityReader.Informational(mv, "currentTargetPosition", "distance", "holdKeyToApply", "initialized", "movingAway", "node",
                "originalDistance", "originalDistanceTime", "pending", "previousDistance", "previousDistanceTime", "previousHeading",
                "soughtPosition", "topLevelObjectID");
            mv.End();
        }
        var frame = new MoveToFrame([.. calls], update, interpolated, f.Vec3("origin"), f.Id("cell"), f.Float("aceHeading"), f.Bool("contact", false),
            f.Bool("onWalkable", false), i.Id("forwardCommand"), i.Float("forwardSpeed"), i.Id("turnCommand"), i.Float("turnSpeed"), kind, command, aux,
            fails, completed);
        // The sidestep is not part of a MoveTo; the rest is ACE's state beside what is compared (the frame's index
        // and times follow the file's rate; the sequence, velocity, orientation and the other managers' state).
        MotionParityReader.Informational(i, "sidestepCommand", "sidestepSpeed");
        i.End();
        MotionParityReader.Informational(f, "frame", "t", "time", "quantum", "quantumRan", "orientation", "velocity", "cachedVelocity", "sliding",
            "transientState", "isAnimating", "motionState", "interpolation", "sticky", "others");
        f.End();
        return frame;
    }

    /// <summary>A recorded position's heading is not compared (the target is a point).</summary>
    private static void EndPosition(JsonObj p)
    {
        MotionParityReader.Informational(p, "aceHeading");
        p.End();
    }

    // The ACE calls as the recording logs them:
    //   PhysicsObj.MoveToPosition((70, 75, 0), MovementParameters{CanRun, DistanceToObject 0.6, WalkRunThreshold 1, UseSpheres True, Speed 1}) -> ...
    //   PhysicsObj.TurnToHeading(DesiredHeading 135) -> ...
    //   PhysicsObj.MoveToObject(0x50000002, DistanceToObject 0.6, CanRun) -> ...
    // A position given to 4 decimals ("20 m ahead of the start of this call") is rebuilt from the recorded origin before the call.
    private static MoveToCall ParseCall(string text, string path, Vector3 before)
    {
        var c = CultureInfo.InvariantCulture;
        if (text.StartsWith("PhysicsObj.MoveToPosition((", StringComparison.Ordinal))
        {
            int close = text.IndexOf(')');
            if (close < "PhysicsObj.MoveToPosition((".Length)
                throw new SceneFormatException(path, $"unreadable position in \"{text}\".");
            var xyz = text["PhysicsObj.MoveToPosition((".Length..close].Split(',', StringSplitOptions.TrimEntries);
            if (xyz.Length != 3 || !float.TryParse(xyz[0], NumberStyles.Float, c, out float x) || !float.TryParse(xyz[1], NumberStyles.Float, c, out float y)
                || !float.TryParse(xyz[2], NumberStyles.Float, c, out float z))
                throw new SceneFormatException(path, $"unreadable position in \"{text}\".");
            var target = new Vector3(x, y, z);
            // Rounded in the log: the README's "20 m ahead" is the origin before the call + 20 m along +Y.
            var ahead = new Vector3(before.X, before.Y + 20f, 0f);
            if (Vector3.Distance(ahead, target) < 1e-3f)
                target = ahead;
            var p = Parameters(Between(text, "MovementParameters{", "}", path), path);
            return new MoveToCall(MoveToKind.MoveToPosition, new Position(LandDefs.LandCellAt(0xA9B4, target), target), p, 0);
        }
        if (text.StartsWith("PhysicsObj.TurnToHeading(DesiredHeading ", StringComparison.Ordinal))
        {
            string h = Between(text, "DesiredHeading ", ")", path);
            if (!float.TryParse(h, NumberStyles.Float, c, out float heading))
                throw new SceneFormatException(path, $"unreadable heading in \"{text}\".");
            return new MoveToCall(MoveToKind.TurnToHeading, default, MoveToParameters.Default with { DesiredHeading = heading }, 0);
        }
        if (text.StartsWith("PhysicsObj.MoveToObject(", StringComparison.Ordinal))
        {
            string args = Between(text, "PhysicsObj.MoveToObject(", ")", path);
            int comma = args.IndexOf(',');
            uint id = comma > 2 && uint.TryParse(args[2..comma], NumberStyles.AllowHexSpecifier, c, out uint v) ? v
                : throw new SceneFormatException(path, $"unreadable object id in \"{text}\".");
            return new MoveToCall(MoveToKind.MoveToObject, default, Parameters(args[(comma + 1)..], path), id);
        }
        throw new SceneFormatException(path, $"unknown call \"{text}\" (known: PhysicsObj.MoveToPosition, TurnToHeading, MoveToObject).");
    }

    /// <summary>ACE's default walk/run threshold (MovementParameters.cs:49-50; retail's is 15 m): what ACE used where a call does not name one.</summary>
    public const float AceDefaultWalkRunThreshold = 1f;

    // "CanRun, DistanceToObject 0.6, WalkRunThreshold 1, UseSpheres True, Speed 1": retail's defaults with these values,
    // and ACE's own threshold default where the call names none (as ACE ran it).
    private static MoveToParameters Parameters(string list, string path)
    {
        var p = MoveToParameters.Default with { WalkRunThreshold = AceDefaultWalkRunThreshold };
        foreach (string item in list.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries))
        {
            int space = item.IndexOf(' ');
            string key = space < 0 ? item : item[..space], value = space < 0 ? "" : item[(space + 1)..];
            float number = float.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out float n) ? n : float.NaN;
            p = key switch
            {
                "CanRun" => p with { Flags = p.Flags | MoveToFlags.CanRun },
                "DistanceToObject" when float.IsFinite(number) => p with { DistanceToObject = number },
                "WalkRunThreshold" when float.IsFinite(number) => p with { WalkRunThreshold = number },
                "Speed" when float.IsFinite(number) => p with { Speed = number },
                "UseSpheres" => value == "True" ? p with { Flags = p.Flags | MoveToFlags.UseSpheres } : p with { Flags = p.Flags & ~MoveToFlags.UseSpheres },
                _ => throw new SceneFormatException(path, $"unknown movement parameter \"{item}\"."),
            };
        }
        return p;
    }

    private static string Between(string text, string open, string close, string path)
    {
        int a = text.IndexOf(open, StringComparison.Ordinal);
        int b = a < 0 ? -1 : text.IndexOf(close, a + open.Length, StringComparison.Ordinal);
        return b < 0 ? throw new SceneFormatException(path, $"unreadable call \"{text}\".") : text[(a + open.Length)..b];
    }
}
