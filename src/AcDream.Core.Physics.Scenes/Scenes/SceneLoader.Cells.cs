using System;
using System.Collections.Generic;
using System.Text.Json;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

// The scene loader's world: landblocks (terrain), env cells and their portals, buildings, and placed objects.
public static partial class SceneLoader
{
    private sealed partial class Reader
    {
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
                // The scene's portalSide says the owning cell is in front of the polygon; retail's portal_side
                // (CellPortal's) is true when it is behind: the opposite convention.
                var portal = new CellPortal(polygon, otherId, !side);
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
    }
}
