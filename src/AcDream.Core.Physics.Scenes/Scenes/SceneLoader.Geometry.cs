using System.Collections.Generic;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

// The scene loader's geometry: polygons, spheres, boxes, models with their BSP trees, and setups.
public static partial class SceneLoader
{
    private sealed partial class Reader
    {
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
    }
}
