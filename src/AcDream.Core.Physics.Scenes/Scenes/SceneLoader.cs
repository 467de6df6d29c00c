using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using AcDream.Core.Physics.Body;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Validation;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Reads scene files (JSON, format version 1, described in docs/scene-format.md) into a <see cref="Scene"/>.
/// Everything is validated; any problem is a <see cref="SceneFormatException"/> whose message starts with
/// the JSON path of the bad value. Loading allocates freely and is never on the engine's per-frame path.
/// </summary>
public static class SceneLoader
{
    /// <summary>The scene format version this loader reads.</summary>
    public const int FormatVersion = 1;

    /// <summary>The most frames one mover may request (a guard against typos such as a count of 1e9).</summary>
    public const int MaxFramesPerMover = 100_000;

    /// <summary>Loads a scene file from disk.</summary>
    /// <param name="path">The file.</param>
    /// <exception cref="SceneFormatException">The file is malformed.</exception>
    /// <exception cref="IOException">The file cannot be read.</exception>
    public static Scene LoadFile(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        return Load(BoundedFile.ReadText(path, BoundedFile.MaxSceneBytes, "scene file"), Path.GetFileNameWithoutExtension(path));
    }

    /// <summary>Loads a scene from its JSON text.</summary>
    /// <param name="json">The scene text.</param>
    /// <param name="defaultName">The name used when the scene has no "name" field.</param>
    /// <exception cref="SceneFormatException">The text is malformed.</exception>
    public static Scene Load(string json, string defaultName = "scene")
    {
        ArgumentNullException.ThrowIfNull(json);
        using var doc = JsonRead.Parse(json);
        return new Reader(defaultName, Sha256Of(json)).Read(doc.RootElement);
    }

    /// <summary>The SHA-256 (lower-case hex) of a scene text, with CRLF line ends read as LF so checkouts on any platform agree.</summary>
    public static string Sha256Of(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var bytes = Encoding.UTF8.GetBytes(text.Replace("\r\n", "\n", StringComparison.Ordinal));
        return Convert.ToHexStringLower(SHA256.HashData(bytes));
    }

    private sealed class Reader(string defaultName, string sha)
    {
        private readonly Dictionary<string, PhysicsModel> _models = new(StringComparer.Ordinal);
        private readonly Dictionary<string, PhysicsSetup> _setups = new(StringComparer.Ordinal);
        private readonly List<uint> _landblocks = new();
        private readonly PhysicsWorld _world = new();

        public Scene Read(JsonElement root)
        {
            var o = new JsonObj(root, string.Empty);
            int version = o.Int("version", -1);
            if (!o.Has("version"))
                throw new SceneFormatException("version", "is required (this loader reads version 1).");
            if (version != FormatVersion)
                throw new SceneFormatException("version", $"unsupported scene format version {version} (this loader reads version {FormatVersion}).");
            string name = o.String("name", null) ?? defaultName;
            string description = o.String("description", null) ?? string.Empty;

            if (o.Opt("models") is { } models)
                foreach (var (key, value) in new JsonObj(models, "models").Fields())
                    _models.Add(key, ReadModel(value, $"models.{key}"));
            if (o.Opt("setups") is { } setups)
                foreach (var (key, value) in new JsonObj(setups, "setups").Fields())
                    _setups.Add(key, ReadSetup(value, $"setups.{key}"));
            foreach (var (value, path) in o.Array("landblocks"))
                ReadLandblock(value, path);
            if (_landblocks.Count == 0)
                throw new SceneFormatException("landblocks", "a scene needs at least one landblock.");
            var envCells = o.Array("envCells", optional: true);
            var pendingPortals = new List<(CellPortal Portal, string Path)>();
            var cells = new List<EnvCell>();
            foreach (var (value, path) in envCells)
                ReadEnvCell(value, path, pendingPortals, cells);
            foreach (var (portal, path) in pendingPortals)
                if (!portal.LeadsOutside && _world.Cells.Get(portal.OtherCellId) is null && !cells.Exists(c => c.Id == portal.OtherCellId))
                    throw new SceneFormatException(path, $"unknown cell 0x{portal.OtherCellId:X8}.");
            Checked("envCells", () => _world.Cells.AddEnvCells(cells));
            foreach (var (value, path) in o.Array("buildings", optional: true))
                ReadBuilding(value, path);
            foreach (var (value, path) in o.Array("objects", optional: true))
                ReadObject(value, path);
            var movers = new List<SceneMover>();
            var names = new HashSet<string>(StringComparer.Ordinal);
            long totalFrames = 0;
            foreach (var (value, path) in o.Array("movers"))
            {
                var mover = ReadMover(value, path, movers);
                if (!names.Add(mover.Name))
                    throw new SceneFormatException(path + ".name", $"mover name \"{mover.Name}\" is used twice.");
                totalFrames += mover.FrameCount;
                if (totalFrames > InputLimits.MaxSceneFrames)
                    throw new SceneFormatException(path + (mover.IsMotion ? ".frames" : mover.IsBody ? ".steps" : ".motion"), $"the scene's movers walk more than {InputLimits.MaxSceneFrames} frames in all (InputLimits.MaxSceneFrames, movers × frames).");
                movers.Add(mover);
            }
            if (movers.Count == 0)
                throw new SceneFormatException("movers", "a scene needs at least one mover.");
            o.End();
            return new Scene(name, description, sha, _world, movers);
        }

        private static T Checked<T>(string path, Func<T> build)
        {
            try
            {
                return build();
            }
            catch (ArgumentException ex)
            {
                throw SceneFormatException.Wrap(path, ex);
            }
            catch (InvalidOperationException ex)
            {
                throw new SceneFormatException(path, ex.Message, ex);
            }
        }

        private static void Checked(string path, Action action) => Checked(path, () => { action(); return 0; });

        // ---- geometry ----

        private static PolygonSides ReadSides(JsonObj o)
        {
            string? sides = o.String("sides", null);
            return sides switch
            {
                null or "single" => PolygonSides.Single,
                "double" => PolygonSides.Double,
                "both" => PolygonSides.Both,
                _ => throw new SceneFormatException(o.Child("sides"), $"expected \"single\", \"double\" or \"both\", got \"{sides}\"."),
            };
        }

        private static Polygon ReadPolygon(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            var items = o.Array("vertices");
            if (items.Count < 3)
                throw new SceneFormatException(o.Child("vertices"), $"a polygon needs at least 3 vertices, got {items.Count}.");
            var vertices = new Vector3[items.Count];
            for (int i = 0; i < items.Count; i++)
                vertices[i] = JsonRead.Vec3(items[i].Value, items[i].Path);
            var sides = ReadSides(o);
            o.End();
            return Checked(path, () => new Polygon(vertices, sides, path));
        }

        private static Sphere ReadSphere(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            var s = new Sphere(o.Vec3("center"), o.Float("radius"));
            o.End();
            Checked(path, () => Guard.Sphere(s, path));
            return s;
        }

        private static (Vector3 Min, Vector3 Max) ReadBox(JsonObj o)
        {
            var min = o.Vec3("min");
            var max = o.Vec3("max");
            o.End();
            if (!(min.X < max.X && min.Y < max.Y && min.Z < max.Z))
                throw new SceneFormatException(o.Child("max"), $"every component must be greater than min's, got min {min}, max {max}.");
            return (min, max);
        }

        private static PhysicsModel ReadModel(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            int kinds = (o.Has("polygons") ? 1 : 0) + (o.Has("box") ? 1 : 0) + (o.Has("cellBox") ? 1 : 0);
            if (kinds != 1)
                throw new SceneFormatException(path, "a model needs exactly one of \"polygons\" (with optional \"nodes\"), \"box\" or \"cellBox\".");
            BspTree tree;
            if (o.Opt("box") is { } box)
            {
                var (min, max) = ReadBox(new JsonObj(box, o.Child("box")));
                var sides = ReadSides(o);
                tree = Checked(o.Child("box"), () => BspShapes.Box(min, max, sides));
            }
            else if (o.Opt("cellBox") is { } cellBox)
            {
                var (min, max) = ReadBox(new JsonObj(cellBox, o.Child("cellBox")));
                tree = BspShapes.CellBox(min, max);
            }
            else
            {
                var polygons = new List<Polygon>();
                foreach (var (value, p) in o.Array("polygons"))
                    polygons.Add(ReadPolygon(value, p));
                if (o.Opt("nodes") is { } nodes)
                {
                    var list = new List<BspNodeData>();
                    foreach (var (value, p) in JsonRead.Array(nodes, o.Child("nodes")))
                        list.Add(ReadNode(value, p, polygons));
                    tree = Checked(path, () => BspTree.Create(polygons, list, path));
                }
                else
                {
                    if (polygons.Count == 0)
                        throw new SceneFormatException(o.Child("polygons"), "at least one polygon is needed to compile a BSP tree.");
                    tree = Checked(path, () => BspCompiler.Compile(polygons, o.Child("polygons")));
                }
            }
            Sphere? bounds = o.Opt("boundingSphere") is { } b ? ReadSphere(b, o.Child("boundingSphere")) : null;
            o.End();
            return Checked(path, () => new PhysicsModel(tree, bounds, path));
        }

        private static BspNodeData ReadNode(JsonElement e, string path, List<Polygon> polygons)
        {
            var o = new JsonObj(e, path);
            bool leaf = o.Bool("leaf", false);
            var indices = new List<int>();
            foreach (var (value, p) in o.Array("polygons", optional: true))
                indices.Add(JsonRead.Int(value, p));
            Sphere? bounds = o.Opt("bounds") is { } b ? ReadSphere(b, o.Child("bounds")) : null;
            if (leaf)
            {
                bool solid = o.Bool("solid", false);
                o.End();
                return new BspNodeData { IsLeaf = true, Solid = solid, Polygons = indices, Bounds = bounds };
            }
            Plane plane;
            if (o.Opt("planeOf") is { } of)
            {
                if (o.Has("splitPlane"))
                    throw new SceneFormatException(o.Child("planeOf"), "give either \"splitPlane\" or \"planeOf\", not both.");
                int index = JsonRead.Int(of, o.Child("planeOf"));
                if (index < 0 || index >= polygons.Count)
                    throw new SceneFormatException(o.Child("planeOf"), $"polygon index {index} is out of range 0..{polygons.Count - 1}.");
                plane = polygons[index].Plane;
            }
            else
            {
                var po = o.Obj("splitPlane");
                plane = new Plane(po.Vec3("normal"), po.Float("d"));
                po.End();
            }
            int front = o.Int("front", -1), back = o.Int("back", -1);
            o.End();
            return new BspNodeData { SplitPlane = plane, Front = front, Back = back, Polygons = indices, Bounds = bounds };
        }

        private PhysicsModel Model(JsonElement e, string path)
        {
            string name = JsonRead.String(e, path);
            return _models.TryGetValue(name, out var model)
                ? model
                : throw new SceneFormatException(path, $"unknown model \"{name}\" (known: {Known(_models.Keys)}).");
        }

        private static string Known(IEnumerable<string> names)
        {
            var list = new List<string>(names);
            return list.Count == 0 ? "none" : string.Join(", ", list);
        }

        private PhysicsSetup ReadSetup(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            var parts = new List<SetupPart>();
            foreach (var (value, p) in o.Array("parts", optional: true))
            {
                var po = new JsonObj(value, p);
                PhysicsModel? model = po.Opt("model") is { } m ? Model(m, po.Child("model")) : null;
                var frame = new Frame(po.Opt("origin") is { } origin ? JsonRead.Vec3(origin, po.Child("origin")) : Vector3.Zero, po.Rotation("rotation"));
                float defaultScale = po.Float("defaultScale", 1f);
                po.End();
                parts.Add(new SetupPart(model, frame, defaultScale));
            }
            var cyls = new List<CylSphere>();
            foreach (var (value, p) in o.Array("cylSpheres", optional: true))
            {
                var co = new JsonObj(value, p);
                var c = new CylSphere(co.Vec3("lowPoint"), co.Float("radius"), co.Float("height"));
                co.End();
                Checked(p, () => Guard.CylSphere(c, p));
                cyls.Add(c);
            }
            var spheres = new List<Sphere>();
            foreach (var (value, p) in o.Array("spheres", optional: true))
                spheres.Add(ReadSphere(value, p));
            var setup = new PhysicsSetup
            {
                Parts = parts,
                CylSpheres = cyls,
                Spheres = spheres,
                Height = o.Float("height", 0f),
                Radius = o.Float("radius", 0f),
                StepUpHeight = o.Float("stepUpHeight", 0f),
                StepDownHeight = o.Float("stepDownHeight", 0f),
            };
            o.End();
            Checked(path, () => setup.Validate(path));
            return setup;
        }

        // ---- cells ----

        private void ReadLandblock(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            uint id = o.Id("id");
            if (id > 0xFFFF)
                throw new SceneFormatException(o.Child("id"), $"0x{id:X} is not a 16-bit landblock id.");
            Checked(o.Child("id"), () => Guard.LandblockInWorld(id, o.Child("id")));
            const int vertices = Terrain.VerticesPerSide * Terrain.VerticesPerSide;
            if (o.Has("height") == o.Has("heights"))
                throw new SceneFormatException(path, "a landblock needs exactly one of \"height\" (flat) or \"heights\" (81 values, [x * 9 + y]).");
            var heights = new float[vertices];
            if (o.Opt("height") is { } h)
            {
                float height = JsonRead.Float(h, o.Child("height"));
                Checked(o.Child("height"), () => Guard.Coordinate(height, o.Child("height")));
                Array.Fill(heights, height);
            }
            else
            {
                var items = o.Array("heights");
                if (items.Count != vertices)
                    throw new SceneFormatException(o.Child("heights"), $"expected 81 values (9×9), got {items.Count}.");
                for (int i = 0; i < items.Count; i++)
                    heights[i] = JsonRead.Float(items[i].Value, items[i].Path);
            }
            var words = ReadTerrainTypes(o, path);
            o.End();
            var terrain = Checked(path, () => new Terrain(id, heights, words, path));
            Checked(o.Child("id"), () => _world.Cells.AddLandblock(terrain));
            _landblocks.Add(id);
        }

        // The terrain words of a landblock from its terrain types (bits 2–6 of each word; road and scenery, which
        // physics never reads, stay 0): "terrainType" one type for every vertex, or "terrainTypes" 81 of them,
        // [x * 9 + y]; neither: type 0 everywhere (dry).
        private static ushort[] ReadTerrainTypes(JsonObj o, string path)
        {
            const int vertices = Terrain.VerticesPerSide * Terrain.VerticesPerSide;
            var words = new ushort[vertices];
            if (o.Has("terrainType") && o.Has("terrainTypes"))
                throw new SceneFormatException(path, "a landblock takes at most one of \"terrainType\" (every vertex) or \"terrainTypes\" (81 values, [x * 9 + y]).");
            if (o.Opt("terrainType") is { } t)
            {
                Array.Fill(words, TerrainWord(t, o.Child("terrainType")));
            }
            else if (o.Opt("terrainTypes") is { } ts)
            {
                var items = JsonRead.Array(ts, o.Child("terrainTypes"));
                if (items.Count != vertices)
                    throw new SceneFormatException(o.Child("terrainTypes"), $"expected 81 terrain types (9×9), got {items.Count}.");
                for (int i = 0; i < items.Count; i++)
                    words[i] = TerrainWord(items[i].Value, items[i].Path);
            }
            return words;
        }

        private static ushort TerrainWord(JsonElement e, string path)
        {
            int type = JsonRead.Int(e, path);
            if (type < 0 || type > 31)
                throw new SceneFormatException(path, $"a terrain type is 0..31, got {type}.");
            return (ushort)(type << 2);
        }

        private void ReadEnvCell(JsonElement e, string path, List<(CellPortal, string)> pending, List<EnvCell> cells)
        {
            var o = new JsonObj(e, path);
            uint id = o.Id("id");
            var frame = new Frame(o.Vec3("position"), o.Rotation("rotation"));
            BspTree? physics = o.Opt("physicsModel") is { } pm ? Model(pm, o.Child("physicsModel")).Bsp : null;
            var cellBsp = Model(o.Req("cellModel"), o.Child("cellModel")).Bsp;
            var portals = new List<CellPortal>();
            foreach (var (value, p) in o.Array("portals", optional: true))
            {
                var po = new JsonObj(value, p);
                var polygon = ReadPolygon(po.Req("polygon"), po.Child("polygon"));
                var other = po.Req("otherCell");
                uint otherId = other.ValueKind == JsonValueKind.String && other.GetString() == "outside"
                    ? CellPortal.Outside
                    : JsonRead.Id(other, po.Child("otherCell"));
                bool side = JsonRead.Bool(po.Req("portalSide"), po.Child("portalSide"));
                po.End();
                var portal = new CellPortal(polygon, otherId, side);
                portals.Add(portal);
                pending.Add((portal, po.Child("otherCell")));
            }
            o.End();
            if (!_landblocks.Contains(LandDefs.Landblock(id)))
                throw new SceneFormatException(o.Child("id"), $"cell 0x{id:X8} is not in a landblock of the scene.");
            if (_world.Cells.Get(id) is not null || cells.Exists(c => c.Id == id))
                throw new SceneFormatException(o.Child("id"), $"cell 0x{id:X8}: is already in the world.");
            cells.Add(Checked(o.Child("id"), () => new EnvCell(id, frame, physics, cellBsp, portals)));
        }

        private void ReadBuilding(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            var shell = Model(o.Req("shell"), o.Child("shell"));
            var position = ReadPlacement(o);
            var entrances = new List<uint>();
            foreach (var (value, p) in o.Array("entranceCells", optional: true))
            {
                uint id = JsonRead.Id(value, p);
                if (_world.Cells.Get(id) is not EnvCell)
                    throw new SceneFormatException(p, $"0x{id:X8} is not an env cell of the scene.");
                entrances.Add(id);
            }
            o.End();
            Checked(path, () => _world.Cells.AddBuilding(new Building(shell, position, entrances)));
        }

        /// <summary>Reads "cell" (optional for outdoor placements in a one-landblock scene), "position" and "rotation".</summary>
        private Position ReadPlacement(JsonObj o)
        {
            var origin = o.Vec3("position");
            var rotation = o.Rotation("rotation");
            uint cell;
            if (o.Opt("cell") is { } c)
            {
                cell = JsonRead.Id(c, o.Child("cell"));
                if (_world.Cells.Get(cell) is null)
                    throw new SceneFormatException(o.Child("cell"), $"unknown cell 0x{cell:X8}.");
            }
            else
            {
                if (_landblocks.Count != 1)
                    throw o.Missing(o.Child("cell"), "is required when the scene has more than one landblock.", "cell");
                cell = LandDefs.LandCellAt(_landblocks[0], origin);
                if (cell == 0)
                    throw new SceneFormatException(o.Child("position"), $"{origin} is outside landblock 0x{_landblocks[0]:X4} (0..192 m on X and Y).");
            }
            return new Position(cell, new Frame(origin, rotation));
        }

        private PhysicsSetup Setup(JsonElement e, string path)
        {
            string name = JsonRead.String(e, path);
            return _setups.TryGetValue(name, out var setup)
                ? setup
                : throw new SceneFormatException(path, $"unknown setup \"{name}\" (known: {Known(_setups.Keys)}).");
        }

        private void ReadObject(JsonElement e, string path)
        {
            var o = new JsonObj(e, path);
            uint id = o.Id("id");
            var setup = Setup(o.Req("setup"), o.Child("setup"));
            var position = ReadPlacement(o);
            float scale = o.Float("scale", 1f);
            Checked(o.Child("scale"), () => Guard.Positive(scale, o.Child("scale")));
            var state = o.Opt("state") is { } s ? JsonRead.Flags<PhysicsState>(s, o.Child("state")) : PhysicsState.None;
            var flags = o.Opt("flags") is { } f ? JsonRead.Flags<ShadowFlags>(f, o.Child("flags")) : ShadowFlags.None;
            o.End();
            if (_world.Objects.Contains(id))
                throw new SceneFormatException(o.Child("id"), $"object 0x{id:X8} appears twice.");
            Checked(path, () => _world.Objects.Register(id, setup, position, scale, state, flags));
        }

        // ---- movers ----

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
