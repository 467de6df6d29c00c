using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// Reads a parity file (gzip JSON) into a <see cref="ParitySet"/>. Two formats:
/// "ace-oracle-trajectories" (ACE's results on a built-in scene: the header's <c>scene</c> supplies the
/// objects' setups, its <c>objects</c> their position, rotation and state; flat landblock; the retail
/// player walks approaches from the floor) and "ace-parity-real" (real cells: the header names a scene
/// file in <c>scenes/</c> beside the file; each mover starts in the full state its <c>start</c> gives,
/// read by the scene format's start-state reader). Errors are <see cref="SceneFormatException"/>s naming
/// the JSON path. Load-time only; allocates freely.
/// </summary>
internal static class ParityReader
{
    /// <summary>The format of ACE's results on the built-in scenes.</summary>
    public const string AceFormat = "ace-oracle-trajectories";

    /// <summary>The format of the real-cell files.</summary>
    public const string RealCellsFormat = "ace-parity-real";

    /// <summary>The managers' data (ACE's MoveToManager, StickyManager and InterpolationManager recorded quantum by quantum).</summary>
    public const string ManagersFormat = "ace-manager-parity";

    /// <summary>The managers' data's position-manager files (sticky, interpolate), read by <see cref="PositionManagerParityReader"/>; the rest are MoveTo files (<see cref="MoveToParityReader"/>).</summary>
    public static bool IsPositionManagerFile(string name) =>
        name.StartsWith("sticky", StringComparison.Ordinal) || name.StartsWith("interpolate", StringComparison.Ordinal);

    /// <summary>The most frames a parity file's runs may hold in all (an ACE file holds about 50 000), checked before any run's frames are read.</summary>
    public const int MaxFramesPerFile = 1_000_000;

    /// <summary>The ACE file whose every frame must match to the last bit.</summary>
    public const string BitIdenticalFile = "door.json.gz";

    /// <summary>Reads a file; a scene it names is looked up in <c>scenes/</c> beside it.</summary>
    public static ParitySet ReadFile(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        BoundedFile.CheckRegular(path, BoundedFile.MaxParityBytes, "parity file");
        using var file = File.OpenRead(path);
        using var gzip = new GZipStream(file, CompressionMode.Decompress);
        // JsonDocument reads the whole stream before parsing: the cap bounds what a small gzip can inflate to.
        using var inflated = new BoundedFile.CappedStream(gzip, BoundedFile.MaxParityInflatedBytes, "a parity file may inflate to at most that");
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(inflated, JsonRead.Options);
        }
        catch (JsonException ex)
        {
            throw new SceneFormatException(string.Empty, $"invalid JSON at line {(ex.LineNumber ?? 0) + 1}: {FirstSentence(ex.Message)}", ex);
        }
        catch (InvalidDataException ex)
        {
            throw new SceneFormatException(string.Empty, $"not a gzip file: {ex.Message}", ex);
        }
        using (doc)
            return Read(doc.RootElement, Path.GetFileName(path), Path.GetDirectoryName(Path.GetFullPath(path))!);
    }

    /// <summary>Reads a parsed file named <paramref name="name"/> whose scenes live under <paramref name="directory"/>/scenes.</summary>
    public static ParitySet Read(JsonElement root, string name, string directory)
    {
        var o = new JsonObj(root, string.Empty);
        string format = o.String("format");
        int version = o.Int("version", -1);
        if (format is not (AceFormat or RealCellsFormat or MotionParityReader.Format or ManagersFormat))
            throw new SceneFormatException("format", $"unknown parity format \"{format}\" (known: {AceFormat}, {RealCellsFormat}, {MotionParityReader.Format}, {ManagersFormat}).");
        if (version != 1)
            throw new SceneFormatException("version", $"unsupported {format} version {version} (this reader reads version 1).");
        if (format == ManagersFormat)
        {
            if (root.TryGetProperty("frames", out var mframes) && mframes.ValueKind == JsonValueKind.Array && mframes.GetArrayLength() > MaxFramesPerFile)
                throw new SceneFormatException("frames", $"the file holds more than {MaxFramesPerFile} frames.");
            // The position managers' files (sticky, interpolate) are read by their own reader (PositionManagerParityCheck).
            if (IsPositionManagerFile(name))
            {
                var positions = PositionManagerParityReader.Read(root, name, directory);
                return new ParitySet(name, positions.World, [], RequireBitIdentical: false, Positions: positions);
            }
            var moveTo = MoveToParityReader.Read(root, name, directory);
            return new ParitySet(name, moveTo.World, [], RequireBitIdentical: false, MoveTo: moveTo);
        }
        if (format == MotionParityReader.Format)
        {
            // One run: the frame cap applies to the file's own frame list.
            if (root.TryGetProperty("frames", out var frames) && frames.ValueKind == JsonValueKind.Array && frames.GetArrayLength() > MaxFramesPerFile)
                throw new SceneFormatException("frames", $"the file holds more than {MaxFramesPerFile} frames.");
            var motion = MotionParityReader.Read(root, name, directory);
            return new ParitySet(name, motion.World, [], RequireBitIdentical: false, motion);
        }
        CheckFrameTotal(root, format == AceFormat ? "approaches" : "movers");
        var set = format == AceFormat
            ? ReadAce(o, name)
            : ReadReal(o, name, directory);
        // Words for a reader: how the file was recorded, what its frame fields mean, ACE's corrections.
        MotionParityReader.Informational(o, "ace", "comparedWith", "frameFields", "approachRule", "ground", "frameRule", "startRule", "aceCorrections");
        o.End();
        return set;
    }

    /// <summary>Refuses a file whose runs hold more than <see cref="MaxFramesPerFile"/> frames in all, before any run is read (a malformed list is left to the reader's own errors).</summary>
    private static void CheckFrameTotal(JsonElement root, string runsField)
    {
        if (!root.TryGetProperty(runsField, out var runs) || runs.ValueKind != JsonValueKind.Array)
            return;
        long total = 0;
        int i = 0;
        foreach (var run in runs.EnumerateArray())
        {
            if (run.ValueKind == JsonValueKind.Object && run.TryGetProperty("frames", out var frames) && frames.ValueKind == JsonValueKind.Array)
                total += frames.GetArrayLength();
            if (total > MaxFramesPerFile)
                throw new SceneFormatException($"{runsField}[{i}].frames", $"the file's runs hold more than {MaxFramesPerFile} frames in all.");
            i++;
        }
    }

    private static string FirstSentence(string message)
    {
        int cut = message.IndexOf(" LineNumber:", StringComparison.Ordinal);
        return cut > 0 ? message[..cut].TrimEnd() : message;
    }

    // ---- ACE on a built-in scene ----

    private static ParitySet ReadAce(JsonObj o, string name)
    {
        string sceneName = o.String("scene");
        if (!SceneLibrary.Contains(sceneName))
            throw new SceneFormatException("scene", $"unknown built-in scene \"{sceneName}\" (built-in: {string.Join(", ", SceneLibrary.Names)}).");
        var scene = SceneLibrary.Load(sceneName);
        var world = scene.World;
        uint landblock = o.Id("landblock");
        foreach (var (value, path) in o.Array("objects"))
            PlaceObject(world, value, path, sceneName, landblock);

        var player = o.Obj("player");
        var mover = ReadPlayer(player);
        var runs = new List<ParityRun>();
        foreach (var (value, path) in o.Array("approaches"))
        {
            var a = new JsonObj(value, path);
            string runName = $"{a.String("side", "?")} heading {Number(a, "heading")} lateral {Number(a, "lateral")} speed {Number(a, "speed")} {Number(a, "hz")} Hz";
            var start = a.Vec3("start");
            var offset = a.Vec3("offset");
            uint cell = LandDefs.LandCellAt(landblock, start);
            if (cell == 0 || world.Cells.Get(cell) is null)
                throw new SceneFormatException(a.Child("start"), $"{start} is not in landblock 0x{landblock:X4} of scene \"{sceneName}\".");
            var state = MoverState.OnFloor(new Position(cell, start), 0f);
            var frames = ReadFrames(a.Req("frames"), a.Child("frames"), offset, contactPlane: false);
            a.End();
            runs.Add(new ParityRun(runName, mover, state, frames));
        }
        if (runs.Count == 0)
            throw new SceneFormatException("approaches", "a parity file needs at least one approach.");
        return new ParitySet(name, world, runs, string.Equals(name, BitIdenticalFile, StringComparison.Ordinal));
    }

    private static string Number(JsonObj o, string field) => o.Opt(field) is { } v ? v.GetRawText() : "?";

    // The header's rule: the built-in scene supplies the object's shapes; position, rotation and state come from here.
    private static void PlaceObject(PhysicsWorld world, JsonElement e, string path, string sceneName, uint landblock)
    {
        var o = new JsonObj(e, path);
        uint id = o.Id("id");
        var position = o.Vec3("position");
        var rotation = o.Rotation("rotation");
        var state = JsonRead.Flags<PhysicsState>(o.Req("state"), o.Child("state"));
        o.End();
        if (!world.Objects.Contains(id))
            throw new SceneFormatException(o.Child("id"), $"object 0x{id:X8} is not in built-in scene \"{sceneName}\".");
        uint cell = LandDefs.LandCellAt(landblock, position);
        if (cell == 0)
            throw new SceneFormatException(o.Child("position"), $"{position} is outside landblock 0x{landblock:X4}.");
        try
        {
            world.Objects.Replace(id, new Position(cell, new Frame(position, rotation)), state);
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap(path, ex);
        }
    }

    private static MoverDescription ReadPlayer(JsonObj p)
    {
        uint id = p.Id("id");
        var items = p.Array("spheres");
        if (items.Count is < 1 or > 2)
            throw new SceneFormatException(p.Child("spheres"), $"a mover has one or two spheres, got {items.Count}.");
        var spheres = new Sphere[items.Count];
        for (int i = 0; i < items.Count; i++)
        {
            var v = JsonRead.Numbers(items[i].Value, items[i].Path, 4, "a sphere [x, y, z, r]");
            spheres[i] = new Sphere(new Vector3(v[0], v[1], v[2]), v[3]);
        }
        float stepUp = p.Float("stepUp");
        float stepDown = p.Float("stepDown");
        var state = NamedFlags<PhysicsState>(p.Req("state"), p.Child("state"));
        var info = p.Bool("isPlayer", false) ? ObjectInfoState.IsPlayer : ObjectInfoState.None;
        // The header's rule places each approach's start on the floor (MoverState.OnFloor); the recorded start state says the same.
        MotionParityReader.Informational(p, "startState");
        p.End();
        try
        {
            return new MoverDescription(id, spheres, stepUp, stepDown, state, info);
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap("player", ex);
        }
    }

    // "Gravity|EdgeSlide" or "Gravity, EdgeSlide" or a hex string.
    private static TEnum NamedFlags<TEnum>(JsonElement e, string path) where TEnum : struct, Enum
    {
        string text = JsonRead.String(e, path);
        if (text.StartsWith("0x", StringComparison.OrdinalIgnoreCase))
            return JsonRead.Flags<TEnum>(e, path);
        ulong bits = 0;
        foreach (string part in text.Split(['|', ','], StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
            bits |= JsonRead.FlagBits<TEnum>(part, path);
        return (TEnum)Enum.ToObject(typeof(TEnum), bits);
    }

    // ---- real cells ----

    private static ParitySet ReadReal(JsonObj o, string name, string directory)
    {
        string sceneFile = o.String("scene");
        if (sceneFile.Contains('/') || sceneFile.Contains('\\') || sceneFile.Contains(".."))
            throw new SceneFormatException("scene", $"must be a file name in scenes/, got \"{sceneFile}\".");
        string scenePath = Path.Combine(directory, "scenes", sceneFile);
        if (!File.Exists(scenePath))
            throw new SceneFormatException("scene", $"scenes/{sceneFile} does not exist beside the file.");
        string text;
        try
        {
            text = BoundedFile.ReadText(scenePath, BoundedFile.MaxSceneBytes, "scene file");
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException("scene", $"scenes/{sceneFile} {ex.Detail}", ex);
        }
        if (o.String("sceneSha256", null) is { } sha && !string.Equals(sha, SceneLoader.Sha256Of(text), StringComparison.OrdinalIgnoreCase))
            throw new SceneFormatException("sceneSha256", $"scenes/{sceneFile} has changed (its SHA-256 is {SceneLoader.Sha256Of(text)}).");
        Scene scene;
        try
        {
            scene = SceneLoader.Load(text, Path.GetFileNameWithoutExtension(sceneFile));
        }
        catch (SceneFormatException ex)
        {
            throw new SceneFormatException($"scene (scenes/{sceneFile}) {ex.JsonPath}".TrimEnd(), ex.Detail, ex);
        }
        var byName = new Dictionary<string, SceneMover>(StringComparer.Ordinal);
        foreach (var m in scene.Movers)
            byName[m.Name] = m;

        var runs = new List<ParityRun>();
        foreach (var (value, path) in o.Array("movers"))
        {
            var m = new JsonObj(value, path);
            string moverName = m.String("name");
            // The scene's mover of this name is the mover (its description is the scene file's, checked by its SHA-256);
            // the file repeats it for a reader, and notes where a mover leaves the landblock.
            MotionParityReader.Informational(m, "id", "spheres", "state", "stateNames", "stepUp", "stepDown", "objectInfo", "leavesLandblockAtFrame");
            if (m.Has("excluded"))
                continue; // The file keeps only part of an excluded mover's frames (it leaves the loaded world).
            if (!byName.TryGetValue(moverName, out var sceneMover))
                throw new SceneFormatException(m.Child("name"), $"scene \"{sceneFile}\" has no mover \"{moverName}\".");
            var start = StartStateReader.Read(m.Req("start"), m.Child("start"), scene.World);
            var frames = ReadFrames(m.Req("frames"), m.Child("frames"), offset: null, contactPlane: true);
            m.End();
            runs.Add(new ParityRun(moverName, sceneMover.Description, start, frames));
        }
        if (runs.Count == 0)
            throw new SceneFormatException("movers", "a parity file needs at least one mover that is not excluded.");
        return new ParitySet(name, scene.World, runs, RequireBitIdentical: false);
    }

    // ---- frames ----

    // Frames are many (about 50,000 per ACE file), so they are read field by field without JsonObj;
    // paths are built only for an error.
    private static ParityFrame[] ReadFrames(JsonElement e, string path, Vector3? offset, bool contactPlane)
    {
        if (e.ValueKind != JsonValueKind.Array)
            throw new SceneFormatException(path, $"expected an array, got {JsonRead.Kind(e)}.");
        int length = e.GetArrayLength();
        if (length == 0)
            throw new SceneFormatException(path, "needs at least one frame.");
        if (length > SceneLoader.MaxFramesPerMover)
            throw new SceneFormatException(path, $"at most {SceneLoader.MaxFramesPerMover} frames.");
        var frames = new ParityFrame[length];
        int i = 0;
        foreach (var f in e.EnumerateArray())
        {
            string at = $"{path}[{i}]";
            if (f.ValueKind != JsonValueKind.Object)
                throw new SceneFormatException(at, $"expected an object, got {JsonRead.Kind(f)}.");
            var frameOffset = offset ?? JsonRead.Vec3(Req(f, at, "offset"), at + ".offset");
            bool contact = Bit(f, at, "c");
            bool hasPlane = false;
            Plane plane = default;
            uint planeCell = 0;
            if (contactPlane && contact)
            {
                var cp = JsonRead.Numbers(Req(f, at, "cp"), at + ".cp", 4, "a plane [nx, ny, nz, d]");
                plane = new Plane(cp[0], cp[1], cp[2], cp[3]);
                planeCell = JsonRead.Id(Req(f, at, "cpCell"), at + ".cpCell");
                hasPlane = true;
            }
            frames[i] = new ParityFrame(
                frameOffset,
                JsonRead.Vec3(Req(f, at, "pos"), at + ".pos"),
                JsonRead.Id(Req(f, at, "cell"), at + ".cell"),
                contact,
                Bit(f, at, "w"),
                Sliding(f, at),
                Bit(f, at, "ok"),
                Hits(f, at),
                hasPlane,
                plane,
                planeCell);
            i++;
        }
        return frames;
    }

    // The sliding normal is written only while sliding; only its presence is compared, but it must be a vector.
    private static bool Sliding(JsonElement f, string at)
    {
        if (!f.TryGetProperty("sl", out var sl) || sl.ValueKind == JsonValueKind.Null)
            return false;
        JsonRead.Vec3(sl, at + ".sl");
        return true;
    }

    private static JsonElement Req(JsonElement f, string at, string name) =>
        f.TryGetProperty(name, out var v) && v.ValueKind != JsonValueKind.Null ? v : throw new SceneFormatException($"{at}.{name}", "is required.");

    private static bool Bit(JsonElement f, string at, string name)
    {
        var v = Req(f, at, name);
        if (v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out int n) && n is 0 or 1)
            return n == 1;
        throw new SceneFormatException($"{at}.{name}", $"expected 0 or 1, got {JsonRead.Kind(v)}.");
    }

    private static uint[] Hits(JsonElement f, string at)
    {
        if (!f.TryGetProperty("hit", out var h) || h.ValueKind == JsonValueKind.Null)
            return [];
        var items = JsonRead.Array(h, at + ".hit");
        var ids = new uint[items.Count];
        for (int i = 0; i < ids.Length; i++)
            ids[i] = JsonRead.Id(items[i].Value, items[i].Path);
        return ids;
    }
}
