using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Scenes;

// The scene loader's motion commands: a motion mover's table, skills and per-frame commands (motions, hold keys, jumps, MoveTo, the position managers' calls).
public static partial class SceneLoader
{
    private sealed partial class Reader
    {
        /// <summary>
        /// A motion mover: "motionTable" ("humanoid" or a table in MotionTableReader's shape), "skills" ({ "run", "jump",
        /// "burden" } with retail's formulas, defaults Run 200, Jump 200, burden 0; or "none"), "frames" and one of "hz" or
        /// "dt" (every frame's elapsed time), and "commands", each at a "frame" or a "time" (seconds, rounded to the
        /// nearest frame) with exactly one of "do", "stop" (a motion name or id, with "speed" and "hold"),
        /// "stopCompletely": true, "holdKey" ("None" or "Run") or "jump" (an extent, with "stamina"); or for the position
        /// managers "interpolateTo" ([x, y, z] landblock-local, with "landblock" (default the mover's) and "keepHeading"),
        /// "rotation" (the reported orientation, default the identity)), "stickTo" (the name of an earlier mover, with "radius" and
        /// "height") or "unstick": true.
        /// </summary>
        private static (SceneStep[] Steps, SceneMotion Motion) ReadCommands(JsonObj o, List<int> itemStarts, in MoverState start, uint id,
            List<SceneMover> earlier)
        {
            MotionTable table;
            var te = o.Req("motionTable");
            if (te.ValueKind == JsonValueKind.String)
            {
                string builtIn = te.GetString()!;
                table = builtIn == "humanoid"
                    ? MotionTables.Humanoid()
                    : throw new SceneFormatException(o.Child("motionTable"), $"unknown built-in motion table \"{builtIn}\" (built-in: humanoid; or give the table inline).");
            }
            else
            {
                table = MotionTableReader.Read(te, o.Child("motionTable"));
            }
            RetailSkills? skills = new(200, 200);
            if (o.Opt("skills") is { } sk)
            {
                if (sk.ValueKind == JsonValueKind.String && sk.GetString() == "none")
                {
                    skills = null;
                }
                else
                {
                    var so = new JsonObj(sk, o.Child("skills"));
                    int run = so.Int("run", 200), jump = so.Int("jump", 200);
                    float burden = so.Float("burden", 0f);
                    so.End();
                    skills = Checked(so.Path, () => new RetailSkills(run, jump, burden));
                }
            }
            int frames = o.Int("frames", -1);
            if (!o.Has("frames"))
                throw new SceneFormatException(o.Child("frames"), "is required: how many frames the mover is stepped.");
            if (frames < 1 || frames > MaxFramesPerMover)
                throw new SceneFormatException(o.Child("frames"), $"must be 1 to {MaxFramesPerMover}, got {frames}.");
            if (o.Has("dt") == o.Has("hz"))
                throw new SceneFormatException(o.Path, "a mover with \"commands\" needs exactly one of \"dt\" (seconds a frame) or \"hz\" (frames per second).");
            double dt;
            if (o.Opt("dt") is { } d)
            {
                dt = JsonRead.Double(d, o.Child("dt"));
                if (!(dt >= 0) || !(dt <= 1e6))
                    throw new SceneFormatException(o.Child("dt"), $"must be zero or more seconds (at most 1e6), got {dt}.");
            }
            else
            {
                double hz = JsonRead.Double(o.Req("hz"), o.Child("hz"));
                if (!(hz > 0) || !(hz <= 1e6))
                    throw new SceneFormatException(o.Child("hz"), $"must be more than zero frames per second (at most 1e6), got {hz}.");
                dt = 1.0 / hz;
            }
            var commands = new List<SceneCommand>();
            foreach (var (value, p) in o.Array("commands"))
            {
                if (commands.Count >= MaxFramesPerMover)
                    throw new SceneFormatException(p, $"a mover may give at most {MaxFramesPerMover} commands.");
                var c = ReadCommand(value, p, frames, dt, table, start, id, earlier);
                if (commands.Count > 0 && c.Frame < commands[^1].Frame)
                    throw new SceneFormatException(p, $"commands must be in time order: frame {c.Frame} comes after frame {commands[^1].Frame}.");
                commands.Add(c);
            }
            itemStarts.Add(0);
            var steps = new SceneStep[frames];
            Array.Fill(steps, new SceneStep(dt, Vector3.Zero, 0f));
            return (steps, new SceneMotion(table, skills, [.. commands]));
        }

        private static readonly string[] CommandKinds = ["do", "stop", "stopCompletely", "holdKey", "jump", "moveTo", "interpolateTo", "stickTo", "unstick"];

        private static SceneCommand ReadCommand(JsonElement e, string path, int frames, double dt, MotionTable table, in MoverState start, uint id,
            List<SceneMover> earlier)
        {
            var o = new JsonObj(e, path);
            if (o.Has("frame") == o.Has("time"))
                throw new SceneFormatException(path, "a command needs exactly one of \"frame\" (the frame before whose step it is given) or \"time\" (seconds from the start).");
            int frame;
            if (o.Has("frame"))
            {
                frame = o.Int("frame", 0);
            }
            else
            {
                double time = JsonRead.Double(o.Req("time"), o.Child("time"));
                double at = dt > 0 ? Math.Round(time / dt, MidpointRounding.AwayFromZero) : (time == 0 ? 0 : double.PositiveInfinity);
                if (!(time >= 0) || !(at < frames))
                    throw new SceneFormatException(o.Child("time"), $"must be from 0 to the last frame's start ({(frames - 1) * dt} s), got {time}.");
                frame = (int)at;
            }
            if (frame < 0 || frame >= frames)
                throw new SceneFormatException(o.Child("frame"), $"must be a frame from 0 to {frames - 1}, got {frame}.");
            string? kind = null;
            foreach (string k in CommandKinds)
                if (o.Has(k))
                {
                    if (kind is not null)
                        throw new SceneFormatException(o.Child(k), $"a command does one thing: \"{kind}\" and \"{k}\" are both given.");
                    kind = k;
                }
            if (kind is null)
                throw new SceneFormatException(path, "a command needs one of \"do\", \"stop\" (a motion), \"stopCompletely\": true, \"holdKey\", \"jump\" (an extent), \"moveTo\" (a point), \"interpolateTo\", \"stickTo\" or \"unstick\": true.");
            if (kind is not ("do" or "stop"))
                foreach (string field in new[] { "speed", "hold" })
                    if (o.Has(field))
                        throw new SceneFormatException(o.Child(field), $"only \"do\" and \"stop\" take \"{field}\".");
            if (kind != "jump" && o.Has("stamina"))
                throw new SceneFormatException(o.Child("stamina"), "only \"jump\" takes \"stamina\".");
            foreach (var (field, owner) in ManagerFields)
                if (o.Has(field) && kind != owner)
                    throw new SceneFormatException(o.Child(field), $"only \"{owner}\" takes \"{field}\".");
            SceneCommand command;
            switch (kind)
            {
                case "do":
                case "stop":
                {
                    uint motion = ReadMotionId(o.Req(kind), o.Child(kind), table);
                    float speed = o.Float("speed", 1f);
                    if (!float.IsFinite(speed) || MathF.Abs(speed) > 100f)
                        throw new SceneFormatException(o.Child("speed"), $"must be finite and within ±100, got {speed}.");
                    var hold = o.Opt("hold") is { } h ? ReadHoldKey(h, o.Child("hold")) : HoldKey.Invalid;
                    command = new SceneCommand(frame, kind == "do" ? SceneCommandKind.Do : SceneCommandKind.Stop, motion, speed, hold, 0f, false, path);
                    break;
                }
                case "stopCompletely":
                    if (!JsonRead.Bool(o.Req(kind), o.Child(kind)))
                        throw new SceneFormatException(o.Child(kind), "must be true (leave the field out for no command).");
                    command = new SceneCommand(frame, SceneCommandKind.StopCompletely, 0, 1f, HoldKey.Invalid, 0f, false, path);
                    break;
                case "holdKey":
                    command = new SceneCommand(frame, SceneCommandKind.SetHoldKey, 0, 1f, ReadHoldKey(o.Req(kind), o.Child(kind)), 0f, false, path);
                    break;
                case "moveTo":
                {
                    // Retail's MoveToManager::MoveToPosition with retail's MovementParameters, the distance and the
                    // walk/run threshold optionally named.
                    var target = o.Vec3("moveTo");
                    float distance = o.Float("distanceToObject", 0.6f), threshold = o.Float("walkRunThreshold", 15f);
                    if (!(distance >= 0f && distance <= 1000f))
                        throw new SceneFormatException(o.Child("distanceToObject"), $"must be 0 to 1000 m, got {distance}.");
                    if (!(threshold >= 0f && threshold <= 1000f))
                        throw new SceneFormatException(o.Child("walkRunThreshold"), $"must be 0 to 1000 m, got {threshold}.");
                    var parameters = MoveToParameters.Default with { DistanceToObject = distance, WalkRunThreshold = threshold };
                    // "giveUp": true opts in to the server's cancel of a move that makes no progress
                    // (MoveToProgressRule.GiveUp); without it the client's rule (CountOnly) only counts the failures.
                    var rule = o.Bool("giveUp", false) ? MoveToProgressRule.GiveUp : MoveToProgressRule.CountOnly;
                    command = new SceneCommand(frame, SceneCommandKind.MoveTo, 0, 1f, HoldKey.Invalid, 0f, false, path, target, parameters, ProgressRule: rule);
                    break;
                }
                case "interpolateTo":
                {
                    var origin = JsonRead.Vec3(o.Req(kind), o.Child(kind));
                    uint block = o.Opt("landblock") is { } lb ? JsonRead.Id(lb, o.Child("landblock")) : start.Position.CellId >> 16;
                    if (block > 0xFFFF || !LandDefs.IsValidLandblock(block))
                        throw new SceneFormatException(o.Child("landblock"), $"0x{block:X} is not a landblock id in the retail world.");
                    if (!(origin.X >= 0f && origin.X < PhysicsConstants.LandblockLength && origin.Y >= 0f && origin.Y < PhysicsConstants.LandblockLength))
                        throw new SceneFormatException(o.Child(kind), $"x and y must be landblock-local, 0 to 192 (use \"landblock\" for another one), got {origin}.");
                    var position = new Position(LandDefs.LandCellAt(block, origin), new Frame(origin, o.Rotation("rotation")));
                    command = new SceneCommand(frame, SceneCommandKind.InterpolateTo, 0, 1f, HoldKey.Invalid, 0f, false, path, Position: position, KeepHeading: o.Bool("keepHeading", false));
                    break;
                }
                case "stickTo":
                {
                    string name = JsonRead.String(o.Req(kind), o.Child(kind));
                    int index = earlier.FindIndex(m => m.Name == name);
                    if (index < 0)
                        throw new SceneFormatException(o.Child(kind), $"\"{name}\" is not a mover given before this one (a mover sticks to an earlier mover, whose frames it follows).");
                    if (earlier[index].Description.ObjectId == id)
                        throw new SceneFormatException(o.Child(kind), $"\"{name}\" has this mover's id 0x{id:X8}: give the movers different \"id\"s.");
                    float radius = o.Float("radius"), height = o.Float("height", 0f);
                    if (!(radius >= 0f && radius <= 100f) || !(height >= 0f && height <= 100f))
                        throw new SceneFormatException(o.Child("radius"), $"radius and height must be 0 to 100 m, got {radius} and {height}.");
                    command = new SceneCommand(frame, SceneCommandKind.StickTo, 0, 1f, HoldKey.Invalid, 0f, false, path, TargetMover: index, Radius: radius, Height: height);
                    break;
                }
                case "unstick":
                    if (!JsonRead.Bool(o.Req(kind), o.Child(kind)))
                        throw new SceneFormatException(o.Child(kind), "must be true (leave the field out for no command).");
                    command = new SceneCommand(frame, SceneCommandKind.UnStick, 0, 1f, HoldKey.Invalid, 0f, false, path);
                    break;
                default:
                {
                    float extent = o.Float("jump");
                    if (!(extent >= 0f && extent <= 1f))
                        throw new SceneFormatException(o.Child("jump"), $"must be an extent from 0 to 1, got {extent}.");
                    command = new SceneCommand(frame, SceneCommandKind.Jump, 0, 1f, HoldKey.Invalid, extent, o.Bool("stamina", true), path);
                    break;
                }
            }
            o.End();
            return command;
        }

        private static readonly (string Field, string Owner)[] ManagerFields =
            [("distanceToObject", "moveTo"), ("walkRunThreshold", "moveTo"), ("giveUp", "moveTo"), ("landblock", "interpolateTo"), ("keepHeading", "interpolateTo"), ("rotation", "interpolateTo"), ("radius", "stickTo"), ("height", "stickTo")];

        private static HoldKey ReadHoldKey(JsonElement e, string path)
        {
            string key = JsonRead.String(e, path);
            return key switch
            {
                "None" => HoldKey.None,
                "Run" => HoldKey.Run,
                _ => throw new SceneFormatException(path, $"expected \"None\" or \"Run\", got \"{key}\"."),
            };
        }

        /// <summary>A motion command by name (MotionCommandNames) or id, known to the table or mapped by the interpreter.</summary>
        private static uint ReadMotionId(JsonElement e, string path, MotionTable table)
        {
            uint id;
            if (e.ValueKind == JsonValueKind.String && !e.GetString()!.StartsWith("0x", StringComparison.OrdinalIgnoreCase))
            {
                string name = e.GetString()!;
                if (!MotionCommandNames.TryId(name, out id))
                    throw new SceneFormatException(path, $"unknown motion command \"{name}\" (known: {MotionCommandNames.List}; or a hex id).");
            }
            else
            {
                id = JsonRead.Id(e, path);
            }
            if (!(id is MotionCommand.WalkBackwards or MotionCommand.TurnLeft or MotionCommand.SideStepLeft) && !table.Knows(id))
                throw new SceneFormatException(path, $"command {MotionCommandNames.Name(id)} (0x{id:X8}) is not in motion table 0x{table.Id:X8} and is not one the interpreter maps.");
            return id;
        }
    }
}
