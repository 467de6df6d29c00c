using System;
using System.Collections.Generic;
using System.IO;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Reads scene files (JSON, format version 1, described in docs/scene-format.md) into a <see cref="Scene"/>.
/// Everything is validated; any problem is a <see cref="SceneFormatException"/> whose message starts with
/// the JSON path of the bad value. Loading allocates freely and is never on the engine's per-frame path.
/// </summary>
public static partial class SceneLoader
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

    private sealed partial class Reader(string defaultName, string sha)
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
    }
}
