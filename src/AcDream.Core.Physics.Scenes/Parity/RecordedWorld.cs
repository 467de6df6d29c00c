using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Parity;

/// <summary>
/// The world the ACE motion and manager recordings were made in, built element by element as their files name
/// it: flat landblock 0xA9B4 (and its flat north neighbour 0xA9B5, which the interpolate files cross into), the
/// door slab, the platform box, a second box where a file names one, and the managers' tree. Every element is
/// built exactly as its reference data's README describes it, and an element a file names that this list does not
/// know is refused (never ignored): a world built without it would start the mover somewhere else.
/// <para>
/// The door is the built-in <c>door</c> scene's slab model (its explicit closed-solid tree, whose solid leaf holds
/// the faces in the order −Y, +Y, +X, −X, +Z, −Z): where the swept sphere can touch two faces, the leaf returns the
/// first it tries (BSPLEAF::sphere_intersects_poly, acclient.c:364199), so the face order is data that changes
/// results. The boxes are the scene format's <c>box</c> shorthand (their face order was not recorded and no file
/// depends on it). Load-time only.
/// </para>
/// </summary>
internal static class RecordedWorld
{
    /// <summary>A static box element: its extents in the object frame and where it stands (landblock 0xA9B4, identity orientation).</summary>
    internal readonly record struct BoxElement(float[] Extents, float[] Position);

    /// <summary>The door slab's extents (x, y, z min..max) and place, as every README describes it.</summary>
    internal static readonly BoxElement Door = new([-0.5f, 0.5f, -0.009f, 0.252f, 0f, 2.2f], [100f, 100f, 0f]);

    /// <summary>The platform's extents and place.</summary>
    internal static readonly BoxElement Platform = new([-4f, 4f, -4f, 4f, 0f, 2f], [60f, 150f, 0f]);

    /// <summary>
    /// The world a motion file's "world" object describes (its values are sentences, checked against what is
    /// built): the landblock, door and platform are required, "box2" is optional, any other field is refused (with a
    /// did-you-mean), and a box's extents and place are read from
    /// its sentence ("x a..b, y c..d, z e..f ... at landblock-local (X,Y,Z)").
    /// </summary>
    public static PhysicsWorld FromMotionFile(JsonObj world)
    {
        string landblock = world.String("landblock");
        if (!landblock.StartsWith("0xA9B4, flat terrain at z 0", StringComparison.Ordinal))
            throw new SceneFormatException(world.Child("landblock"), $"only the flat landblock 0xA9B4 at z 0 is known, got \"{landblock}\".");
        Expect(world, "door", Door);
        Expect(world, "platform", Platform);
        BoxElement? box2 = world.Opt("box2") is { } b ? ParseBox(JsonRead.String(b, world.Child("box2")), world.Child("box2")) : null;
        world.End();
        return Build(box2, tree: false);
    }

    /// <summary>The managers' world (door, platform, and the tree at (40, 100, 0)), as the manager README lists its objects.</summary>
    public static PhysicsWorld Managers() => Build(null, tree: true);

    /// <summary>The roles a manager file's "objects" may list: the creatures it moves and the world <see cref="Managers"/> builds.</summary>
    internal static readonly string[] ManagerRoles = ["mover", "target", "door", "platform", "tree"];

    /// <summary>
    /// Refuses a manager file whose "objects" list an object this world does not build (a role not in
    /// <see cref="ManagerRoles"/>, with a did-you-mean): the run would go on without it.
    /// </summary>
    public static void CheckManagerObjects(JsonObj file)
    {
        foreach (var (value, at) in file.Array("objects", optional: true))
        {
            var other = new JsonObj(value, at);
            string role = other.String("role");
            if (Array.IndexOf(ManagerRoles, role) < 0)
            {
                string hint = FieldNames.Closest(role, ManagerRoles, maxEdits: 2) is { } meant ? $"did you mean \"{meant}\"? " : "";
                throw new SceneFormatException(other.Child("role"), $"unknown object role \"{role}\" ({hint}this world builds: {string.Join(", ", ManagerRoles)}).");
            }
        }
    }

    // The door's sentence must describe the built-in slab, the platform's the recorded platform: a file that moved
    // either would need a world built differently.
    private static void Expect(JsonObj world, string name, BoxElement expected)
    {
        string path = world.Child(name);
        var read = ParseBox(world.String(name), path);
        if (!Same(read.Extents, expected.Extents) || !Same(read.Position, expected.Position))
            throw new SceneFormatException(path, $"describes {Describe(read)}; the recorded {name} is {Describe(expected)}.");
    }

    private static readonly Regex BoxSentence = new(
        @"x (?<x0>-?[0-9.]+)\.\.(?<x1>-?[0-9.]+), y (?<y0>-?[0-9.]+)\.\.(?<y1>-?[0-9.]+), z (?<z0>-?[0-9.]+)\.\.(?<z1>-?[0-9.]+) \(object frame\) at landblock-local \((?<px>-?[0-9.]+), ?(?<py>-?[0-9.]+), ?(?<pz>-?[0-9.]+)\), identity orientation, static",
        RegexOptions.CultureInvariant, TimeSpan.FromSeconds(1));

    /// <summary>A static box element from its sentence; refused (naming <paramref name="path"/>) when it is not one, or has an empty or misplaced box.</summary>
    internal static BoxElement ParseBox(string sentence, string path)
    {
        var m = BoxSentence.Match(sentence);
        if (!m.Success)
            throw new SceneFormatException(path, $"expected \"x a..b, y c..d, z e..f (object frame) at landblock-local (X,Y,Z), identity orientation, static\", got \"{sentence}\".");
        float N(string group) => float.TryParse(m.Groups[group].Value, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) && float.IsFinite(v)
            ? v
            : throw new SceneFormatException(path, $"unreadable number \"{m.Groups[group].Value}\" in \"{sentence}\".");
        var box = new BoxElement([N("x0"), N("x1"), N("y0"), N("y1"), N("z0"), N("z1")], [N("px"), N("py"), N("pz")]);
        if (!(box.Extents[0] < box.Extents[1] && box.Extents[2] < box.Extents[3] && box.Extents[4] < box.Extents[5]))
            throw new SceneFormatException(path, $"an empty box in \"{sentence}\".");
        if (!(box.Position[0] >= 0f && box.Position[0] < 192f && box.Position[1] >= 0f && box.Position[1] < 192f))
            throw new SceneFormatException(path, $"the box stands outside landblock 0xA9B4 in \"{sentence}\".");
        return box;
    }

    private static bool Same(float[] a, float[] b)
    {
        for (int i = 0; i < a.Length; i++)
            if (a[i] != b[i])
                return false;
        return true;
    }

    private static string Describe(BoxElement b) => string.Create(CultureInfo.InvariantCulture,
        $"x {b.Extents[0]}..{b.Extents[1]}, y {b.Extents[2]}..{b.Extents[3]}, z {b.Extents[4]}..{b.Extents[5]} at ({b.Position[0]}, {b.Position[1]}, {b.Position[2]})");

    // The scene the elements make. A scene needs a mover; this one is not used.
    private static PhysicsWorld Build(BoxElement? box2, bool tree)
    {
        var models = new List<string>
        {
            $"\"doorSlab\": {DoorSlabModel()}",
            $"\"platform\": {BoxModel(Platform)}",
        };
        var setups = new List<string>
        {
            "\"door\": { \"parts\": [{ \"model\": \"doorSlab\" }] }",
            "\"platform\": { \"parts\": [{ \"model\": \"platform\" }] }",
            "\"player\": { \"spheres\": [{ \"center\": [0, 0, 0.475], \"radius\": 0.48 }, { \"center\": [0, 0, 1.35], \"radius\": 0.48 }], \"stepUpHeight\": 0.6, \"stepDownHeight\": 0.04 }",
        };
        var objects = new List<string>
        {
            Placed("0x70000001", "door", Door.Position, BspStatic),
            Placed("0x70000F10", "platform", Platform.Position, BspStatic),
        };
        if (box2 is { } b)
        {
            models.Add($"\"box2\": {BoxModel(b)}");
            setups.Add("\"box2\": { \"parts\": [{ \"model\": \"box2\" }] }");
            objects.Add(Placed("0x70000F11", "box2", b.Position, BspStatic));
        }
        if (tree)
        {
            // The manager README's tree 0x70000F20: one cylsphere, radius 0.3, height 6 (setup radius 0.3, height 6).
            setups.Add("\"tree\": { \"cylSpheres\": [{ \"lowPoint\": [0, 0, 0], \"radius\": 0.3, \"height\": 6 }], \"radius\": 0.3, \"height\": 6 }");
            objects.Add(Placed("0x70000F20", "tree", [40f, 100f, 0f], "0x1"));
        }
        var text = new StringBuilder();
        text.Append("{ \"version\": 1, \"name\": \"ace recorded world\", \"models\": { ").AppendJoin(", ", models)
            .Append(" }, \"setups\": { ").AppendJoin(", ", setups)
            .Append(" }, \"landblocks\": [{ \"id\": \"0xA9B4\", \"height\": 0 }, { \"id\": \"0xA9B5\", \"height\": 0 }], \"objects\": [ ")
            .AppendJoin(", ", objects)
            .Append(" ], \"movers\": [{ \"name\": \"unused\", \"setup\": \"player\", \"state\": [\"Gravity\"], \"cell\": \"0xA9B40013\", \"position\": [60, 60, 0], \"floorZ\": 0, \"motion\": [{ \"offset\": [0, 0, 0], \"count\": 1 }] }] }");
        return SceneLoader.Load(text.ToString(), "ace recorded world").World;
    }

    private static string BoxModel(BoxElement b) => string.Create(CultureInfo.InvariantCulture,
        $"{{ \"box\": {{ \"min\": [{b.Extents[0]:R}, {b.Extents[2]:R}, {b.Extents[4]:R}], \"max\": [{b.Extents[1]:R}, {b.Extents[3]:R}, {b.Extents[5]:R}] }} }}");

    // Static (0x1) with a physics BSP (0x10000).
    private const string BspStatic = "0x10001";

    // An object in the cell under its place.
    private static string Placed(string id, string setup, float[] p, string state) => string.Create(CultureInfo.InvariantCulture,
        $"{{ \"id\": \"{id}\", \"setup\": \"{setup}\", \"cell\": \"0x{LandDefs.LandCellAt(0xA9B4, new System.Numerics.Vector3(p[0], p[1], p[2])):X8}\", \"position\": [{p[0]:R}, {p[1]:R}, {p[2]:R}], \"state\": \"{state}\" }}");

    // The built-in door scene's slab model, as that scene holds it (polygons and explicit tree): the same text, so
    // the same face order and tree.
    private static string DoorSlabModel()
    {
        using var doc = JsonRead.Parse(SceneLibrary.ReadText("door"));
        return doc.RootElement.GetProperty("models").GetProperty("doorSlab").GetRawText();
    }
}
