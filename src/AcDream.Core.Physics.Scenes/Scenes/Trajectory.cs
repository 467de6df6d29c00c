using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Text;
using System.Text.Json;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// A recorded run of a scene: a header (format version, the scene's SHA-256, the library version) and,
/// per mover, every frame's input and outputs. Written as JSON, one frame per line, floats round-trippable.
/// </summary>
public sealed class Trajectory
{
    /// <summary>The trajectory format version this library writes and reads.</summary>
    public const int FormatVersion = 1;

    /// <summary>Creates a trajectory.</summary>
    public Trajectory(string sceneName, string sceneSha256, string libraryVersion, IReadOnlyList<MoverTrajectory> movers)
    {
        SceneName = sceneName ?? throw new ArgumentNullException(nameof(sceneName));
        SceneSha256 = sceneSha256 ?? throw new ArgumentNullException(nameof(sceneSha256));
        LibraryVersion = libraryVersion ?? throw new ArgumentNullException(nameof(libraryVersion));
        Movers = movers ?? throw new ArgumentNullException(nameof(movers));
    }

    /// <summary>The scene's name.</summary>
    public string SceneName { get; }
    /// <summary>The SHA-256 of the scene text it was recorded from (see <see cref="SceneLoader.Sha256Of"/>).</summary>
    public string SceneSha256 { get; }
    /// <summary>The library's informational version that recorded it.</summary>
    public string LibraryVersion { get; }
    /// <summary>The movers, in scene order.</summary>
    public IReadOnlyList<MoverTrajectory> Movers { get; }

    /// <summary>How many frames in all.</summary>
    public int FrameCount
    {
        get
        {
            int n = 0;
            foreach (var m in Movers) n += m.Frames.Count;
            return n;
        }
    }

    /// <summary>Writes the trajectory as JSON text (LF line ends, one frame per line).</summary>
    public string ToJson()
    {
        var sb = new StringBuilder();
        sb.Append("{\n");
        sb.Append("  \"format\": \"acdream-trajectory\",\n");
        sb.Append("  \"version\": ").Append(FormatVersion).Append(",\n");
        sb.Append("  \"scene\": ").Append(Quote(SceneName)).Append(",\n");
        sb.Append("  \"sceneSha256\": ").Append(Quote(SceneSha256)).Append(",\n");
        sb.Append("  \"library\": ").Append(Quote(LibraryVersion)).Append(",\n");
        sb.Append("  \"movers\": [");
        for (int m = 0; m < Movers.Count; m++)
        {
            var mover = Movers[m];
            sb.Append(m == 0 ? "\n" : ",\n");
            sb.Append("    {\n      \"name\": ").Append(Quote(mover.Name)).Append(",\n      \"frames\": [");
            for (int f = 0; f < mover.Frames.Count; f++)
                sb.Append(f == 0 ? "\n        " : ",\n        ").Append(FrameJson(mover.Frames[f]));
            sb.Append("\n      ]\n    }");
        }
        sb.Append("\n  ]\n}\n");
        return sb.ToString();
    }

    private static readonly JsonSerializerOptions QuoteOptions = new() { Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    private static string Quote(string s) => JsonSerializer.Serialize(s, QuoteOptions);

    private static string FrameJson(TrajectoryFrame f)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer))
        {
            w.WriteStartObject();
            if (f.Step is { } step)
            {
                w.WriteStartObject("step");
                w.WriteNumber("dt", step.Elapsed);
                WriteVec(w, "velocity", step.DesiredVelocity);
                w.WriteNumber("jump", step.JumpVelocity);
                w.WriteEndObject();
            }
            else
            {
                w.WriteStartObject("target");
                w.WriteString("cell", Hex(f.Target.CellId));
                WriteVec(w, "origin", f.Target.Frame.Origin);
                var q = f.Target.Frame.Orientation;
                w.WriteStartArray("rotation");
                w.WriteNumberValue(q.W); w.WriteNumberValue(q.X); w.WriteNumberValue(q.Y); w.WriteNumberValue(q.Z);
                w.WriteEndArray();
                w.WriteEndObject();
            }
            WriteVec(w, "position", f.Position);
            w.WriteString("cell", Hex(f.Cell));
            w.WriteBoolean("contact", f.Contact);
            w.WriteBoolean("onWalkable", f.OnWalkable);
            w.WriteStartObject("contactPlane");
            w.WriteBoolean("valid", f.ContactPlaneValid);
            WriteVec(w, "normal", f.ContactPlane.Normal);
            w.WriteNumber("d", f.ContactPlane.D);
            w.WriteString("cell", Hex(f.ContactPlaneCell));
            w.WriteEndObject();
            WriteFlagged(w, "collisionNormal", f.CollisionNormalValid, f.CollisionNormal);
            WriteFlagged(w, "slidingNormal", f.SlidingNormalValid, f.SlidingNormal);
            w.WriteStartArray("collided");
            foreach (uint id in f.CollidedObjects) w.WriteStringValue(Hex(id));
            w.WriteEndArray();
            w.WriteBoolean("succeeded", f.Succeeded);
            if (f.Step is not null)
            {
                w.WriteStartObject("body");
                WriteVec(w, "velocity", f.Velocity);
                w.WriteNumber("quanta", f.Quanta);
                w.WriteEndObject();
            }
            if (f.Motion is { } motion)
                WriteMotion(w, motion);
            if (f.Hit is { } hit)
            {
                w.WriteStartObject("hit");
                w.WriteString("kind", hit.Kind.ToString());
                w.WriteString("object", Hex(hit.ObjectId));
                w.WriteNumber("quantum", hit.Quantum);
                w.WriteEndObject();
            }
            w.WriteEndObject();
        }
        return Encoding.UTF8.GetString(buffer.ToArray());
    }

    private static string Hex(uint id) => $"0x{id:X8}";

    private static void WriteMotion(Utf8JsonWriter w, TrajectoryMotion m)
    {
        w.WriteStartObject("motion");
        var q = m.Rotation;
        w.WriteStartArray("rotation");
        w.WriteNumberValue(q.W); w.WriteNumberValue(q.X); w.WriteNumberValue(q.Y); w.WriteNumberValue(q.Z);
        w.WriteEndArray();
        var i = m.Interpreted;
        w.WriteString("style", Hex(i.Style));
        WriteCommand(w, "forward", i.ForwardCommand, i.ForwardSpeed);
        WriteCommand(w, "sideStep", i.SideStepCommand, i.SideStepSpeed);
        WriteCommand(w, "turn", i.TurnCommand, i.TurnSpeed);
        w.WriteEndObject();
    }

    private static void WriteCommand(Utf8JsonWriter w, string name, uint command, float speed)
    {
        w.WriteStartObject(name);
        w.WriteString("command", Hex(command));
        w.WriteNumber("speed", speed);
        w.WriteEndObject();
    }

    private static TrajectoryMotion ReadMotion(JsonObj o)
    {
        var rotation = JsonRead.RawQuaternion(o.Req("rotation"), o.Child("rotation"));
        var i = new InterpretedMotionState { Style = o.Id("style") };
        (i.ForwardCommand, i.ForwardSpeed) = ReadCommand(o.Obj("forward"));
        (i.SideStepCommand, i.SideStepSpeed) = ReadCommand(o.Obj("sideStep"));
        (i.TurnCommand, i.TurnSpeed) = ReadCommand(o.Obj("turn"));
        o.End();
        return new TrajectoryMotion(rotation, i);
    }

    private static (uint, float) ReadCommand(JsonObj o)
    {
        uint command = o.Id("command");
        float speed = o.Float("speed");
        o.End();
        return (command, speed);
    }

    private static void WriteVec(Utf8JsonWriter w, string name, Vector3 v)
    {
        // Utf8JsonWriter writes floats in their shortest round-trippable form.
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X); w.WriteNumberValue(v.Y); w.WriteNumberValue(v.Z);
        w.WriteEndArray();
    }

    private static void WriteFlagged(Utf8JsonWriter w, string name, bool valid, Vector3 v)
    {
        w.WriteStartObject(name);
        w.WriteBoolean("valid", valid);
        WriteVec(w, "vector", v);
        w.WriteEndObject();
    }

    /// <summary>Reads a trajectory file from disk.</summary>
    /// <exception cref="SceneFormatException">The file is malformed (the message starts with the JSON path).</exception>
    public static Trajectory LoadFile(string path) => Parse(BoundedFile.ReadText(path, BoundedFile.MaxTrajectoryBytes, "trajectory file"));

    /// <summary>Reads a trajectory from its JSON text, strictly (unknown fields are errors).</summary>
    /// <exception cref="SceneFormatException">The text is malformed (the message starts with the JSON path).</exception>
    public static Trajectory Parse(string json)
    {
        ArgumentNullException.ThrowIfNull(json);
        using var doc = JsonRead.Parse(json);
        var o = new JsonObj(doc.RootElement, string.Empty);
        if (o.String("format") != "acdream-trajectory")
            throw new SceneFormatException("format", "expected \"acdream-trajectory\".");
        int version = JsonRead.Int(o.Req("version"), "version");
        if (version != FormatVersion)
            throw new SceneFormatException("version", $"unsupported trajectory format version {version} (this library reads version {FormatVersion}).");
        string scene = o.String("scene");
        string sha = o.String("sceneSha256");
        string library = o.String("library");
        var movers = new List<MoverTrajectory>();
        foreach (var (value, path) in o.Array("movers"))
        {
            var mo = new JsonObj(value, path);
            string name = mo.String("name");
            var frames = new List<TrajectoryFrame>();
            foreach (var (fv, fp) in mo.Array("frames"))
                frames.Add(ReadFrame(fv, fp));
            mo.End();
            movers.Add(new MoverTrajectory(name, frames));
        }
        o.End();
        return new Trajectory(scene, sha, library, movers);
    }

    private static TrajectoryFrame ReadFrame(JsonElement e, string path)
    {
        var o = new JsonObj(e, path);
        if (o.Has("step") == o.Has("target"))
            throw new SceneFormatException(path, "a frame needs exactly one of \"target\" (an offset mover) or \"step\" (a body mover).");
        Position target = default;
        SceneStep? step = null;
        if (o.Opt("target") is { } te)
        {
            var t = new JsonObj(te, o.Child("target"));
            target = new Position(t.Id("cell"), new Frame(t.Vec3("origin"), JsonRead.RawQuaternion(t.Req("rotation"), t.Child("rotation"))));
            t.End();
        }
        else
        {
            var so = o.Obj("step");
            step = new SceneStep(JsonRead.Double(so.Req("dt"), so.Child("dt")), so.Vec3("velocity"), so.Float("jump"));
            so.End();
        }
        Vector3 velocity = default;
        int quanta = 0;
        if (step is not null)
        {
            var bo = o.Obj("body");
            velocity = bo.Vec3("velocity");
            quanta = JsonRead.Int(bo.Req("quanta"), bo.Child("quanta"));
            bo.End();
        }
        TrajectoryMotion? motion = null;
        if (o.Opt("motion") is { } me)
        {
            if (step is null)
                throw new SceneFormatException(o.Child("motion"), "only a body frame (\"step\") has a motion record.");
            motion = ReadMotion(new JsonObj(me, o.Child("motion")));
        }
        TrajectoryHit? hit = null;
        if (o.Opt("hit") is { } he)
        {
            if (step is null)
                throw new SceneFormatException(o.Child("hit"), "only a body frame (\"step\") has a missile's hit.");
            hit = ReadHit(new JsonObj(he, o.Child("hit")));
        }
        var cp = o.Obj("contactPlane");
        bool cpValid = JsonRead.Bool(cp.Req("valid"), cp.Child("valid"));
        var plane = new Plane(cp.Vec3("normal"), cp.Float("d"));
        uint cpCell = cp.Id("cell");
        cp.End();
        var (cnValid, cn) = ReadFlagged(o.Obj("collisionNormal"));
        var (snValid, sn) = ReadFlagged(o.Obj("slidingNormal"));
        var ids = new List<uint>();
        foreach (var (value, p) in o.Array("collided"))
            ids.Add(JsonRead.Id(value, p));
        var frame = new TrajectoryFrame
        {
            Target = target,
            Step = step,
            Velocity = velocity,
            Quanta = quanta,
            Position = o.Vec3("position"),
            Cell = o.Id("cell"),
            Contact = JsonRead.Bool(o.Req("contact"), o.Child("contact")),
            OnWalkable = JsonRead.Bool(o.Req("onWalkable"), o.Child("onWalkable")),
            ContactPlaneValid = cpValid,
            ContactPlane = plane,
            ContactPlaneCell = cpCell,
            CollisionNormalValid = cnValid,
            CollisionNormal = cn,
            SlidingNormalValid = snValid,
            SlidingNormal = sn,
            CollidedObjects = ids,
            Succeeded = JsonRead.Bool(o.Req("succeeded"), o.Child("succeeded")),
            Motion = motion,
            Hit = hit,
        };
        o.End();
        return frame;
    }

    private static TrajectoryHit ReadHit(JsonObj o)
    {
        string kind = o.String("kind");
        var k = kind switch
        {
            "Object" => MissileHitKind.Object,
            "Environment" => MissileHitKind.Environment,
            _ => throw new SceneFormatException(o.Child("kind"), $"unknown hit kind \"{kind}\" (known: Object, Environment)."),
        };
        uint id = o.Id("object");
        int quantum = JsonRead.Int(o.Req("quantum"), o.Child("quantum"));
        if (quantum < 1)
            throw new SceneFormatException(o.Child("quantum"), $"must be 1 or more, got {quantum}.");
        o.End();
        return new TrajectoryHit(k, id, quantum);
    }

    private static (bool, Vector3) ReadFlagged(JsonObj o)
    {
        bool valid = JsonRead.Bool(o.Req("valid"), o.Child("valid"));
        var v = o.Vec3("vector");
        o.End();
        return (valid, v);
    }
}
