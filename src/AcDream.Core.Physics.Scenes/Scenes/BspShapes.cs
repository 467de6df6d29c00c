using System;
using System.Numerics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Shorthands for simple physics shapes written by hand: boxes, floor quads and rotated slabs, as
/// polygons and as trees compiled by <see cref="BspCompiler"/>.
/// </summary>
public static class BspShapes
{
    /// <summary>
    /// The six faces of an axis-aligned box, facing outward (counter-clockwise seen from outside), in the
    /// order +X, −X, +Y, −Y, +Z, −Z.
    /// </summary>
    /// <param name="min">The low corner.</param>
    /// <param name="max">The high corner; every component must be greater than <paramref name="min"/>'s.</param>
    /// <param name="sides">The sidedness of every face.</param>
    /// <exception cref="ArgumentException">A corner is not finite, or the box is empty or flat on some axis.</exception>
    public static Polygon[] BoxPolygons(Vector3 min, Vector3 max, PolygonSides sides = PolygonSides.Single)
    {
        CheckBox(min, max);
        return MakePolygons(BspCompiler.BoxCorners(min, max), sides, "box");
    }

    /// <summary>
    /// A compiled axis-aligned box: the tree's polygons are <see cref="BoxPolygons"/> (same order); the
    /// tree is the retail closed-solid form (six split nodes, empty front leaves, one solid leaf).
    /// </summary>
    /// <param name="min">The low corner.</param>
    /// <param name="max">The high corner; every component must be greater than <paramref name="min"/>'s.</param>
    /// <param name="sides">The sidedness of every face.</param>
    /// <exception cref="ArgumentException">A corner is not finite, or the box is empty or flat on some axis.</exception>
    public static BspTree Box(Vector3 min, Vector3 max, PolygonSides sides = PolygonSides.Single)
        => BspCompiler.Compile(BoxPolygons(min, max, sides), "box");

    /// <summary>A horizontal rectangle facing up (+Z), centred on <paramref name="center"/>.</summary>
    /// <param name="center">The centre of the rectangle.</param>
    /// <param name="size">The extent along X and Y; both must be greater than zero.</param>
    /// <param name="sides">The sidedness.</param>
    /// <exception cref="ArgumentException">The centre is not finite, or a size is not positive and finite.</exception>
    public static Polygon FloorPolygon(Vector3 center, Vector2 size, PolygonSides sides = PolygonSides.Single)
    {
        Guard.Finite(center, "center");
        Guard.Positive(size.X, "size.X");
        Guard.Positive(size.Y, "size.Y");
        float hx = size.X * 0.5f, hy = size.Y * 0.5f;
        ReadOnlySpan<Vector3> corners =
        [
            center + new Vector3(-hx, -hy, 0), center + new Vector3(hx, -hy, 0),
            center + new Vector3(hx, hy, 0), center + new Vector3(-hx, hy, 0),
        ];
        return new Polygon(corners, sides, "floor");
    }

    /// <summary>A compiled single floor quad (<see cref="FloorPolygon"/>): one split node, an empty front leaf and a non-solid back leaf holding the quad.</summary>
    /// <param name="center">The centre of the rectangle.</param>
    /// <param name="size">The extent along X and Y; both must be greater than zero.</param>
    /// <param name="sides">The sidedness.</param>
    /// <exception cref="ArgumentException">The centre is not finite, or a size is not positive and finite.</exception>
    public static BspTree Floor(Vector3 center, Vector2 size, PolygonSides sides = PolygonSides.Single)
        => BspCompiler.Compile(new[] { FloorPolygon(center, size, sides) }, "floor");

    /// <summary>
    /// The six outward faces of a box of <paramref name="size"/> centred on <paramref name="center"/> and
    /// turned by <paramref name="rotation"/> (normalized first), in the order of <see cref="BoxPolygons"/>.
    /// </summary>
    /// <param name="center">The centre.</param>
    /// <param name="size">The full extents before rotation; all must be greater than zero.</param>
    /// <param name="rotation">The orientation; must be finite and non-zero.</param>
    /// <param name="sides">The sidedness of every face.</param>
    /// <exception cref="ArgumentException">A value is not finite, a size is not positive, or the rotation is zero.</exception>
    public static Polygon[] SlabPolygons(Vector3 center, Vector3 size, Quaternion rotation, PolygonSides sides = PolygonSides.Single)
    {
        Guard.Finite(center, "center");
        Guard.Positive(size.X, "size.X");
        Guard.Positive(size.Y, "size.Y");
        Guard.Positive(size.Z, "size.Z");
        var q = Guard.Rotation(rotation, "rotation");
        var faces = BspCompiler.BoxCorners(-size * 0.5f, size * 0.5f);
        foreach (var face in faces)
            for (int i = 0; i < face.Length; i++)
                face[i] = center + PortableRotation.Apply(face[i], q);
        return MakePolygons(faces, sides, "slab");
    }

    /// <summary>A compiled rotated box (<see cref="SlabPolygons"/>), in the closed-solid form.</summary>
    /// <param name="center">The centre.</param>
    /// <param name="size">The full extents before rotation; all must be greater than zero.</param>
    /// <param name="rotation">The orientation; must be finite and non-zero.</param>
    /// <param name="sides">The sidedness of every face.</param>
    /// <exception cref="ArgumentException">A value is not finite, a size is not positive, or the rotation is zero.</exception>
    public static BspTree Slab(Vector3 center, Vector3 size, Quaternion rotation, PolygonSides sides = PolygonSides.Single)
        => BspCompiler.Compile(SlabPolygons(center, size, rotation, sides), "slab");

    /// <summary>
    /// A containment tree for an indoor cell shaped like an axis-aligned box (cell space): a chain of its six
    /// faces' planes facing inward, no polygons. A point is inside the cell when it is in front of all six
    /// (<see cref="EnvCell.ContainsPoint"/>); pass it as an <see cref="EnvCell"/>'s cell BSP.
    /// Retail cells carry their own containment trees (CellStruct's cell BSP); this one is for worlds built by hand.
    /// </summary>
    /// <param name="min">The low corner.</param>
    /// <param name="max">The high corner; every component must be greater than <paramref name="min"/>'s.</param>
    /// <exception cref="ArgumentException">A corner is not finite, or the box is empty or flat on some axis.</exception>
    public static BspTree CellBox(Vector3 min, Vector3 max)
    {
        CheckBox(min, max);
        var center = (min + max) * 0.5f;
        var bounds = new Sphere(center, Vector3.Distance(center, max));
        Plane[] planes =
        [
            new(-Vector3.UnitX, max.X), new(Vector3.UnitX, -min.X),
            new(-Vector3.UnitY, max.Y), new(Vector3.UnitY, -min.Y),
            new(-Vector3.UnitZ, max.Z), new(Vector3.UnitZ, -min.Z),
        ];
        var nodes = new BspNodeData[6];
        for (int i = 0; i < 6; i++)
            nodes[i] = new BspNodeData { SplitPlane = planes[i], Front = i < 5 ? i + 1 : -1, Back = -1, Bounds = bounds };
        return BspTree.Create(Array.Empty<Polygon>(), nodes, "cellBox");
    }

    private static void CheckBox(Vector3 min, Vector3 max)
    {
        Guard.Finite(min, "min");
        Guard.Finite(max, "max");
        if (!(min.X < max.X))
            throw new ArgumentException($"max.X: must be greater than min.X, got min.X={min.X}, max.X={max.X}.", "max");
        if (!(min.Y < max.Y))
            throw new ArgumentException($"max.Y: must be greater than min.Y, got min.Y={min.Y}, max.Y={max.Y}.", "max");
        if (!(min.Z < max.Z))
            throw new ArgumentException($"max.Z: must be greater than min.Z, got min.Z={min.Z}, max.Z={max.Z}.", "max");
    }

    private static Polygon[] MakePolygons(Vector3[][] faces, PolygonSides sides, string name)
    {
        var polygons = new Polygon[faces.Length];
        for (int i = 0; i < faces.Length; i++)
            polygons[i] = new Polygon(faces[i], sides, $"{name}.faces[{i}]");
        return polygons;
    }
}
