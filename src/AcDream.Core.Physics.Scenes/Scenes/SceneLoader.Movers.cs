using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

// The scene loader's movers: each mover's description, start state, body, and its frames of motion (steps or offsets).
public static partial class SceneLoader
{
    private sealed partial class Reader
    {
        private SceneMover ReadMover(JsonElement e, string path, List<SceneMover> earlier)
        {
            var o = new JsonObj(e, path);
            string name = o.String("name");
            uint id = o.Opt("id") is { } idValue ? JsonRead.Id(idValue, o.Child("id")) : 0x5000_0001;
            if (o.Has("setup") == o.Has("spheres"))
                throw o.Missing(path, "a mover needs exactly one of \"setup\" (its spheres and step heights) or \"spheres\".", "setup", "spheres");
            Sphere[] spheres;
            float stepUp, stepDown;
            if (o.Opt("setup") is { } s)
            {
                var setup = Setup(s, o.Child("setup"));
                spheres = [.. setup.Spheres];
                if (spheres.Length is < 1 or > 2)
                    throw new SceneFormatException(o.Child("setup"), $"a mover's setup needs one or two spheres, \"{s.GetString()}\" has {spheres.Length}.");
                stepUp = o.Float("stepUpHeight", setup.StepUpHeight);
                stepDown = o.Float("stepDownHeight", setup.StepDownHeight);
            }
            else
            {
                var items = o.Array("spheres");
                if (items.Count is < 1 or > 2)
                    throw new SceneFormatException(o.Child("spheres"), $"a mover has one or two spheres, got {items.Count}.");
                spheres = new Sphere[items.Count];
                for (int i = 0; i < items.Count; i++)
                    spheres[i] = ReadSphere(items[i].Value, items[i].Path);
                stepUp = o.Float("stepUpHeight");
                stepDown = o.Float("stepDownHeight");
            }
            Checked(o.Child("stepUpHeight"), () => Guard.NonNegative(stepUp, o.Child("stepUpHeight")));
            Checked(o.Child("stepDownHeight"), () => Guard.NonNegative(stepDown, o.Child("stepDownHeight")));
            var state = o.Opt("state") is { } st ? JsonRead.Flags<PhysicsState>(st, o.Child("state")) : PhysicsState.Gravity;
            var info = o.Opt("objectInfo") is { } oi ? JsonRead.Flags<ObjectInfoState>(oi, o.Child("objectInfo")) : ObjectInfoState.None;
            if ((info & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
                throw new SceneFormatException(o.Child("objectInfo"), "Contact and OnWalkable are per-frame state; use \"floorZ\" or \"airborne\".");
            float scale = o.Float("scale", 1f);
            Checked(o.Child("scale"), () => Guard.Positive(scale, o.Child("scale")));
            uint target = o.Opt("target") is { } tv ? JsonRead.Id(tv, o.Child("target")) : 0;
            var start = ReadStart(o, path);
            if ((o.Has("motion") ? 1 : 0) + (o.Has("steps") ? 1 : 0) + (o.Has("commands") ? 1 : 0) != 1)
                throw new SceneFormatException(path, "a mover needs exactly one of \"motion\" (per-frame offsets), \"steps\" (a body moved by time, velocity and jumps) or \"commands\" (a body moved by motion commands through a motion table).");
            if (o.Has("body") && !o.Has("steps") && !o.Has("commands"))
                throw new SceneFormatException(o.Child("body"), "only a mover with \"steps\" or \"commands\" has a body.");
            foreach (string field in MotionOnlyFields)
                if (o.Has(field) && !o.Has("commands"))
                    throw new SceneFormatException(o.Child(field), "only a mover with \"commands\" has this field.");
            Vector3[] motion = [];
            SceneStep[] steps = [];
            SceneMotion? commands = null;
            var body = BodyState.Creature();
            var itemStarts = new List<int>();
            if (o.Opt("steps") is { } st2)
                steps = ReadSteps(st2, o.Child("steps"), itemStarts);
            else if (o.Has("commands"))
                (steps, commands) = ReadCommands(o, itemStarts, start, id, earlier);
            else
                motion = ReadMotion(o.Req("motion"), o.Child("motion"), itemStarts);
            if (o.Opt("body") is { } b)
                body = ReadBody(b, o.Child("body"));
            o.End();
            var description = Checked(path, () => new MoverDescription(id, spheres, stepUp, stepDown, state, info, scale, target));
            var mover = new SceneMover(name, description, start, motion, steps, body, path, [.. itemStarts], commands);
            if (target != 0 && !mover.IsMissile)
                throw new SceneFormatException(o.Child("target"), "only a missile (a mover with \"steps\" and the Missile state) has a target.");
            if (mover.IsMissile)
                CheckMissile(o, mover);
            return mover;
        }

        /// <summary>
        /// A missile starts airborne (retail launches it in the air; <see cref="Missile"/> drops any contact) and is
        /// moved by its velocity alone: its steps give no desired motion and no jump.
        /// </summary>
        private static void CheckMissile(JsonObj o, SceneMover mover)
        {
            if (!o.Has("airborne"))
                throw new SceneFormatException(o.Child(o.Has("floorZ") ? "floorZ" : "start"), "a missile starts in the air: give \"airborne\": true.");
            var steps = mover.Steps;
            for (int f = 0; f < steps.Length; f++)
                if (steps[f].DesiredVelocity != Vector3.Zero || steps[f].JumpVelocity != 0f)
                    throw new SceneFormatException(mover.FramePath(f), "a missile's steps give no \"velocity\" or \"jump\": it moves by its body's velocity (give the launch velocity in \"body\").");
        }

        private static readonly string[] MotionOnlyFields = ["motionTable", "skills", "frames", "hz", "dt"];

        /// <summary>
        /// The mover's state before its first frame: exactly one of "floorZ" (standing on a horizontal floor),
        /// "airborne": true (no contact), or "start" (a full recorded state: placement, contact and walkable
        /// flags, a contact plane of any slope with its cell, a carried sliding normal; StartStateReader).
        /// </summary>
        private MoverState ReadStart(JsonObj o, string path)
        {
            bool floor = o.Has("floorZ"), airborne = o.Bool("airborne", false), full = o.Has("start");
            if ((floor ? 1 : 0) + (airborne ? 1 : 0) + (full ? 1 : 0) != 1)
                throw o.Missing(path, "a mover needs exactly one of \"floorZ\" (standing on a floor at that height), \"airborne\": true, or \"start\" (a full start state).", "floorZ", "airborne", "start");
            if (full)
            {
                foreach (string placement in new[] { "position", "cell", "rotation" })
                    if (o.Has(placement))
                        throw new SceneFormatException(o.Child(placement), "a mover with \"start\" gives its placement inside \"start\".");
                return StartStateReader.Read(o.Req("start"), o.Child("start"), _world);
            }
            var position = ReadPlacement(o);
            return floor
                ? MoverState.OnFloor(position, JsonRead.Float(o.Req("floorZ"), o.Child("floorZ")))
                : MoverState.Airborne(position);
        }

        /// <summary>A body's start: velocity, omega, friction, elasticity (retail defaults) and whether it has a motion interpreter (default true).</summary>
        private static BodyState ReadBody(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            var body = BodyState.Creature();
            body.Velocity = o.Opt("velocity") is { } v ? Speed(v, o.Child("velocity")) : Vector3.Zero;
            body.Omega = o.Opt("omega") is { } w ? Speed(w, o.Child("omega")) : Vector3.Zero;
            body.Friction = Fraction(o, "friction", PhysicsConstants.DefaultFriction);
            body.Elasticity = Fraction(o, "elasticity", PhysicsConstants.DefaultElasticity);
            body.HasMotionInterpreter = o.Bool("motionInterpreter", true);
            o.End();
            return body;
        }

        private static Vector3 Speed(JsonElement e, string path)
        {
            var v = JsonRead.Vec3(e, path);
            float max = BodyGuard.MaxSpeed;
            if (!(MathF.Abs(v.X) <= max && MathF.Abs(v.Y) <= max && MathF.Abs(v.Z) <= max))
                throw new SceneFormatException(path, $"must be within ±{max} per second on each axis, got {v}.");
            return v;
        }

        private static float Fraction(JsonObj o, string name, float fallback)
        {
            float f = o.Float(name, fallback);
            if (!(f >= 0f && f <= 1f))
                throw new SceneFormatException(o.Child(name), $"must be a number from 0 to 1, got {f}.");
            return f;
        }

        /// <summary>
        /// A body mover's frames: each <c>{ "dt": seconds | "hz": frames per second, "velocity": [..], "jump": m/s, "count": n }</c>
        /// (velocity and jump default to zero, count to 1).
        /// </summary>
        private static SceneStep[] ReadSteps(JsonElement e, string path, List<int> itemStarts)
        {
            var frames = new List<SceneStep>();
            foreach (var (value, p) in JsonRead.Array(e, path))
            {
                itemStarts.Add(frames.Count);
                var o = new JsonObj(value, p);
                if (o.Has("dt") == o.Has("hz"))
                    throw new SceneFormatException(p, "a step needs exactly one of \"dt\" (seconds) or \"hz\" (frames per second).");
                double dt;
                if (o.Opt("dt") is { } d)
                {
                    dt = JsonRead.Double(d, o.Child("dt"));
                    if (!(dt >= 0))
                        throw new SceneFormatException(o.Child("dt"), $"must be zero or more seconds, got {dt}.");
                }
                else
                {
                    double hz = JsonRead.Double(o.Req("hz"), o.Child("hz"));
                    if (!(hz > 0))
                        throw new SceneFormatException(o.Child("hz"), $"must be more than zero frames per second, got {hz}.");
                    dt = 1.0 / hz;
                }
                var velocity = o.Opt("velocity") is { } v ? Speed(v, o.Child("velocity")) : Vector3.Zero;
                float jump = o.Float("jump", 0f);
                if (!(jump >= 0f && jump <= BodyGuard.MaxSpeed))
                    throw new SceneFormatException(o.Child("jump"), $"must be a vertical speed of zero or more m/s, got {jump}.");
                int count = o.Int("count", 1);
                o.End();
                CheckCount(o, count, frames.Count);
                for (int i = 0; i < count; i++)
                    frames.Add(new SceneStep(dt, velocity, jump));
            }
            if (frames.Count == 0)
                throw new SceneFormatException(path, "a mover needs at least one step.");
            return [.. frames];
        }

        /// <summary>A motion or step item's repeat count: at least 1, and within the per-mover frame limit.</summary>
        private static void CheckCount(JsonObj o, int count, int framesSoFar)
        {
            if (count < 1)
                throw new SceneFormatException(o.Child("count"), $"must be 1 or more, got {count}.");
            if ((long)framesSoFar + count > MaxFramesPerMover)
                throw new SceneFormatException(o.Child("count"), $"a mover may walk at most {MaxFramesPerMover} frames.");
        }

        private static Vector3[] ReadMotion(JsonElement e, string path, List<int> itemStarts)
        {
            var frames = new List<Vector3>();
            foreach (var (value, p) in JsonRead.Array(e, path))
            {
                itemStarts.Add(frames.Count);
                if (value.ValueKind == JsonValueKind.Array)
                {
                    frames.Add(JsonRead.Vec3(value, p));
                }
                else
                {
                    var o = new JsonObj(value, p);
                    var offset = o.Vec3("offset");
                    int count = o.Int("count", 1);
                    o.End();
                    CheckCount(o, count, frames.Count);
                    for (int i = 0; i < count; i++)
                        frames.Add(offset);
                }
                if (frames.Count > MaxFramesPerMover)
                    throw new SceneFormatException(p, $"a mover may walk at most {MaxFramesPerMover} frames.");
            }
            if (frames.Count == 0)
                throw new SceneFormatException(path, "a mover needs at least one frame of motion.");
            return [.. frames];
        }
    }
}
