using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text.Json;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Reads an "ace-motion-parity" file (ACE's motion layer recorded quantum by quantum on the synthetic humanoid
/// table; described in the reference data's README): the table file it names beside it, the mover (the retail
/// player's spheres with the file's step heights, state, friction and elasticity), the skills, the start, and
/// per frame the calls made and the state after. The world is built from the file's "world" object, element by
/// element (<see cref="RecordedWorld"/>: an element it does not know is refused, never ignored). Errors are
/// <see cref="SceneFormatException"/>s naming the JSON path. Load-time only.
/// </summary>
internal static class MotionParityReader
{
    public const string Format = "ace-motion-parity";

    /// <summary>The largest table file read, bytes.</summary>
    public const int MaxTableBytes = 4 * 1024 * 1024;

    /// <summary>The most calls one frame may make.</summary>
    public const int MaxCallsPerFrame = 16;

    public static MotionParityFile Read(JsonElement root, string name, string directory)
    {
        var o = new JsonObj(root, string.Empty);
        // Read by ParityReader (format, version) or words for a reader (the rest; "events" repeats the frames' calls).
        Informational(o, "format", "version", "ace", "name", "description", "scheduling", "events");
        var table = ReadTable(o, directory);
        double rate = ReadRate(o);

        var m = o.Obj("mover");
        string setup = m.String("setup");
        if (!setup.StartsWith("retail player", StringComparison.Ordinal))
            throw new SceneFormatException(m.Child("setup"), $"only the retail player setup is known, got \"{setup}\".");
        var state = (PhysicsState)JsonRead.Int(m.Req("stateBits"), m.Child("stateBits"));
        if (m.Id("motionTable") != table.Id)
            throw new SceneFormatException(m.Child("motionTable"), $"names 0x{m.Id("motionTable"):X8}, but {o.String("table")} is 0x{table.Id:X8}.");
        MoverDescription mover;
        try
        {
            // The retail player's spheres and id, with the file's step heights, state and scale.
            mover = MoverDescription.Player().With(stepUpHeight: m.Float("stepUpHeight"), stepDownHeight: m.Float("stepDownHeight"),
                physicsState: state, scale: m.Float("scale", 1f));
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap("mover", ex);
        }
        Informational(m, "state");
        var body = BodyState.Creature();
        body.SetElasticity(m.Float("elasticity"));
        body.Friction = m.Float("friction");
        if (!(body.Friction >= 0f && body.Friction <= 1f))
            throw new SceneFormatException(m.Child("friction"), $"must be 0 to 1, got {body.Friction}.");
        m.End();

        var k = o.Obj("skills");
        RetailSkills skills;
        try
        {
            skills = new RetailSkills(k.Int("run", -1), k.Int("jump", -1), k.Float("burden", 0f));
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap("skills", ex);
        }
        if (k.Opt("runRate") is { } rr && MathF.Abs(JsonRead.Float(rr, k.Child("runRate")) - RetailSkills.RunRate(skills.RunSkill, skills.Burden)) > 1e-5f)
            throw new SceneFormatException(k.Child("runRate"), $"disagrees with the retail run rate {RetailSkills.RunRate(skills.RunSkill, skills.Burden)} at Run {skills.RunSkill}.");
        // The stamina is the recording's (every jump's cost is logged with the call).
        Informational(k, "stamina");
        k.End();

        var s = o.Obj("start");
        uint cell = s.Id("cell");
        var origin = s.Vec3("origin");
        var orientation = JsonRead.Rotation(s.Req("orientation"), s.Child("orientation"));
        var world = RecordedWorld.FromMotionFile(o.Obj("world"));
        if (world.Cells.Get(cell) is null || LandDefs.LandCellAt(0xA9B4, origin) != cell)
            throw new SceneFormatException(s.Child("cell"), $"0x{cell:X8} is not the landblock 0xA9B4 cell of {origin}.");
        var start = MoverState.OnFloor(new Position(cell, new Frame(origin, orientation)), 0f);
        // The heading repeats the orientation; the contact sentence and retailHoldKey describe what the calls and the
        // placement do.
        Informational(s, "headingDeg", "contact", "retailHoldKey");
        s.End();

        var items = o.Array("frames");
        if (items.Count == 0 || items.Count > SceneLoader.MaxFramesPerMover)
            throw new SceneFormatException("frames", $"needs 1 to {SceneLoader.MaxFramesPerMover} frames, got {items.Count}.");
        var frames = new MotionParityFrame[items.Count];
        for (int i = 0; i < frames.Length; i++)
            frames[i] = ReadFrame(items[i].Value, items[i].Path);
        o.End();
        return new MotionParityFile(name, world, mover, table, skills, start, body, 1.0 / rate, frames);
    }

    /// <summary>
    /// The motion table file a parity file names beside it ("table"): a plain file name of a regular file of at most
    /// <see cref="MaxTableBytes"/>, read through the bounded reader (a FIFO or a device is refused unopened).
    /// </summary>
    internal static MotionTable ReadTable(JsonObj o, string directory)
    {
        string tableFile = o.String("table");
        if (tableFile.Contains('/') || tableFile.Contains('\\') || tableFile.Contains(".."))
            throw new SceneFormatException("table", $"must be a file name beside the file, got \"{tableFile}\".");
        string tablePath = Path.Combine(directory, tableFile);
        if (!File.Exists(tablePath))
            throw new SceneFormatException("table", $"{tableFile} does not exist beside the file.");
        string text;
        try
        {
            text = BoundedFile.ReadText(tablePath, MaxTableBytes, "motion table file");
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException("table", $"{tableFile} {ex.Detail}", ex);
        }
        try
        {
            return MotionTableReader.Parse(text);
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException($"table ({tableFile}) {ex.JsonPath}".TrimEnd(), ex.Detail, ex);
        }
    }

    /// <summary>The file's frame rate ("rateHz"), 1 to 1000.</summary>
    internal static double ReadRate(JsonObj o)
    {
        double rate = JsonRead.Double(o.Req("rateHz"), "rateHz");
        if (!(rate >= 1.0 && rate <= 1000.0))
            throw new SceneFormatException("rateHz", $"must be 1 to 1000, got {rate}.");
        return rate;
    }

    private static MotionParityFrame ReadFrame(JsonElement e, string path)
    {
        var f = new JsonObj(e, path);
        var callItems = f.Array("commands");
        if (callItems.Count > MaxCallsPerFrame)
            throw new SceneFormatException(f.Child("commands"), $"at most {MaxCallsPerFrame} calls a frame, got {callItems.Count}.");
        var calls = new List<MotionCall>();
        foreach (var (value, at) in callItems)
            ParseCall(JsonRead.String(value, at), at, calls);
        var i = f.Obj("interpreted");
        var interpreted = new InterpretedMotionState
        {
            Style = i.Id("style"),
            ForwardCommand = i.Id("forwardCommand"),
            ForwardSpeed = i.Float("forwardSpeed"),
            SideStepCommand = i.Id("sidestepCommand"),
            SideStepSpeed = i.Float("sidestepSpeed"),
            TurnCommand = i.Id("turnCommand"),
            TurnSpeed = i.Float("turnSpeed"),
        };
        i.End();
        MotionSequenceState? sequence = f.Has("motionState") && f.Has("sequence") ? ReadSequence(f.Obj("motionState"), f.Obj("sequence")) : null;
        if (sequence is null && (f.Has("motionState") || f.Has("sequence")))
            throw new SceneFormatException(f.Child(f.Has("sequence") ? "motionState" : "sequence"), "is required beside the other (the motion state and the sequence are compared together).");
        // Not compared: the frame's index and time (the schedule is the file's rate), the quantum's length (the
        // schedule's), the orientation, the physics velocity and the transient bits (contact and walkable are).
        Informational(f, "frame", "t", "quantum", "orientation", "velocity", "sliding", "transientState");
        var frame = new MotionParityFrame([.. calls], f.Bool("quantumRan", true), f.Vec3("origin"), f.Id("cell"), f.Bool("contact", false),
            f.Bool("onWalkable", false), interpreted, sequence);
        f.End();
        return frame;
    }

    private static MotionSequenceState ReadSequence(JsonObj m, JsonObj q)
    {
        var mods = m.Array("modifiers", optional: true);
        if (mods.Count > MaxCallsPerFrame)
            throw new SceneFormatException(m.Child("modifiers"), $"at most {MaxCallsPerFrame} modifiers.");
        var modifiers = new MotionAndSpeed[mods.Count];
        for (int i = 0; i < modifiers.Length; i++)
        {
            var o = new JsonObj(mods[i].Value, mods[i].Path);
            modifiers[i] = new MotionAndSpeed(o.Id("id"), o.Float("speed"));
            o.End();
        }
        var items = q.Array("anims", optional: true);
        if (items.Count > MaxCallsPerFrame)
            throw new SceneFormatException(q.Child("anims"), $"at most {MaxCallsPerFrame} animations.");
        var anims = new (uint, float)[items.Count];
        int firstCyclic = -1;
        for (int i = 0; i < anims.Length; i++)
        {
            // "0x03000F02@30*": the animation, its framerate, and * on the first cyclic one.
            string text = JsonRead.String(items[i].Value, items[i].Path);
            bool cyclic = text.EndsWith('*');
            int at = text.IndexOf('@');
            if (at < 0 || !float.TryParse(text[(at + 1)..].TrimEnd('*'), NumberStyles.Float, CultureInfo.InvariantCulture, out float rate))
                throw new SceneFormatException(items[i].Path, $"expected \"id@framerate\", got \"{text}\".");
            anims[i] = (Hex(text[..at], items[i].Path, text), rate);
            if (cyclic && firstCyclic < 0)
                firstCyclic = i;
        }
        var state = new MotionSequenceState(m.Id("style"), m.Id("substate"), m.Float("substateMod"), modifiers, q.Vec3("velocity"), q.Vec3("omega"),
            q.Id("currAnim"), q.Float("currFramerate"), JsonRead.Double(q.Req("frameNumber"), q.Child("frameNumber")), anims, firstCyclic);
        m.End();
        q.End();
        return state;
    }

    /// <summary>Fields a reader accepts without comparing them (descriptions, and state the check does not compare); each is named at its call.</summary>
    internal static void Informational(JsonObj o, params string[] names)
    {
        foreach (string name in names)
            o.Opt(name);
    }

    // The calls as the recording logs them:
    //   "RawState.CurrentHoldKey = Run"
    //   "DoMotion(0x45000005, speed 1, hold Run) -> None"
    //   "StopMotion(0x45000005, hold Run) -> None"
    //   "PhysicsObj.StopCompletely(false) -> None"
    //   "charge_jump() -> 0; jump(extent 0.5, stamina 4) -> None"
    private static void ParseCall(string text, string path, List<MotionCall> calls)
    {
        if (text == "RawState.CurrentHoldKey = Run")
        {
            calls.Add(new MotionCall(MotionCallKind.HoldRun, 0, 1f, HoldKey.Run, 0f, 0, "None"));
            return;
        }
        string expected = "None";
        int arrow = text.LastIndexOf(" -> ", StringComparison.Ordinal);
        if (arrow >= 0)
            expected = text[(arrow + 4)..].Trim();
        if (text.StartsWith("DoMotion(", StringComparison.Ordinal) || text.StartsWith("StopMotion(", StringComparison.Ordinal))
        {
            bool stop = text[0] == 'S';
            int open = text.IndexOf('('), close = text.IndexOf(')');
            if (close < open)
                throw new SceneFormatException(path, $"unreadable call \"{text}\".");
            var args = text[(open + 1)..close].Split(',', StringSplitOptions.TrimEntries);
            uint motion = Hex(args[0], path, text);
            float speed = 1f;
            var hold = HoldKey.Invalid;
            for (int a = 1; a < args.Length; a++)
            {
                if (args[a].StartsWith("speed ", StringComparison.Ordinal) && float.TryParse(args[a][6..], NumberStyles.Float, CultureInfo.InvariantCulture, out float sp) && float.IsFinite(sp))
                    speed = sp;
                else if (args[a] == "hold Run")
                    hold = HoldKey.Run;
                else if (args[a] == "hold None")
                    hold = HoldKey.None;
                else
                    throw new SceneFormatException(path, $"unknown argument \"{args[a]}\" in \"{text}\".");
            }
            calls.Add(new MotionCall(stop ? MotionCallKind.StopMotion : MotionCallKind.DoMotion, motion, speed, hold, 0f, 0, expected));
            return;
        }
        if (text == "PhysicsObj.StopCompletely(false)" || text.StartsWith("PhysicsObj.StopCompletely(false) -> ", StringComparison.Ordinal))
        {
            // ACE's PhysicsObj.StopCompletely → MovementManager.PerformMovement(StopCompletely) → MotionInterp.StopCompletely.
            calls.Add(new MotionCall(MotionCallKind.StopCompletely, 0, 1f, HoldKey.Invalid, 0f, 0, expected));
            return;
        }
        if (text.StartsWith("charge_jump()", StringComparison.Ordinal))
        {
            int j = text.IndexOf("jump(extent ", StringComparison.Ordinal);
            int comma = j < 0 ? -1 : text.IndexOf(", stamina ", j, StringComparison.Ordinal);
            int close = comma < 0 ? -1 : text.IndexOf(')', comma);
            if (close < 0
                || !float.TryParse(text[(j + 12)..comma], NumberStyles.Float, CultureInfo.InvariantCulture, out float extent) || !float.IsFinite(extent)
                || !int.TryParse(text[(comma + 10)..close], NumberStyles.Integer, CultureInfo.InvariantCulture, out int stamina))
                throw new SceneFormatException(path, $"unreadable jump \"{text}\".");
            calls.Add(new MotionCall(MotionCallKind.Jump, 0, 1f, HoldKey.Invalid, extent, stamina, expected));
            return;
        }
        throw new SceneFormatException(path, $"unknown call \"{text}\" (known: RawState.CurrentHoldKey = Run, DoMotion(...), StopMotion(...), PhysicsObj.StopCompletely(false), charge_jump(); jump(...)).");
    }

    private static uint Hex(string s, string path, string text) =>
        s.StartsWith("0x", StringComparison.OrdinalIgnoreCase) && uint.TryParse(s[2..], NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint v)
            ? v
            : throw new SceneFormatException(path, $"expected a hex motion id in \"{text}\".");

    /// <summary>The world of the manager parity files (MoveToParityReader, PositionManagerParityReader): the recorded door, platform and tree.</summary>
    internal static PhysicsWorld SharedWorld() => RecordedWorld.Managers();
}
