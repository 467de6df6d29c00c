using System;
using System.Numerics;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// A convex physics polygon: its vertices (counter-clockwise seen from the front), its plane and its
/// sidedness. Immutable after construction; the plane is computed the retail way (see <see cref="MakePlane"/>).
/// Queries live in <see cref="PolygonQuery"/>.
/// </summary>
public sealed class Polygon
{
    private readonly Vector3[] _vertices;

    /// <summary>
    /// Creates a polygon, validating it: 3 to <see cref="InputLimits.MaxPolygonVertices"/> finite vertices,
    /// non-zero area, planar, convex and counter-clockwise seen from the front, no vertex repeated (within
    /// <see cref="InputLimits.PolygonTolerance"/>). Errors name the field and the vertex.
    /// </summary>
    /// <param name="vertices">The vertices, counter-clockwise seen from the front. Copied.</param>
    /// <param name="sides">The sidedness.</param>
    /// <param name="name">A name for error messages (e.g. "polygons[3]").</param>
    public Polygon(ReadOnlySpan<Vector3> vertices, PolygonSides sides = PolygonSides.Single, string name = "polygon")
    {
        if (vertices.Length < 3)
            throw new ArgumentException($"{name}: a polygon needs at least 3 vertices, got {vertices.Length}.", nameof(vertices));
        if (vertices.Length > InputLimits.MaxPolygonVertices)
            throw new ArgumentException($"{name}.vertices: a polygon has at most {InputLimits.MaxPolygonVertices} vertices (retail stores the count in a signed byte), got {vertices.Length}.", nameof(vertices));
        // The field's name is built only for the message (a DAT load checks thousands of vertices).
        for (int i = 0; i < vertices.Length; i++)
            if (!Guard.IsCoordinate(vertices[i]))
                Guard.Finite(vertices[i], $"{name}.vertices[{i}]");
        // The three values are 0 to 2; a range check, not Enum.IsDefined, whose first call in a process reads the
        // enum's metadata (about 1.5 ms of the first landblock load on the 2-core test machine).
        if (sides > PolygonSides.Both)
            throw new ArgumentException($"{name}.sides: unknown sidedness {(int)sides}.", nameof(sides));
        _vertices = vertices.ToArray();
        Sides = sides;
        Plane = MakePlane(_vertices, name);
        Guard.ConvexPolygon(_vertices, Plane, name);
        (BoxMin, BoxMax) = Box(_vertices);
    }

    /// <summary>
    /// A piece cut from a validated convex polygon by a plane (the BSP compiler): convex by construction,
    /// so only the plane is computed; the shape checks, whose tolerances are meant for input, are skipped.
    /// </summary>
    internal Polygon(Vector3[] pieceVertices, PolygonSides sides, string name, bool cutFromValidPolygon)
    {
        System.Diagnostics.Debug.Assert(cutFromValidPolygon);
        _vertices = pieceVertices;
        Sides = sides;
        Plane = MakePlane(_vertices, name);
        (BoxMin, BoxMax) = Box(_vertices);
    }

    /// <summary>The vertices' axis-aligned box (exact: the corners are vertex coordinates), for culling before exact tests.</summary>
    internal readonly Vector3 BoxMin, BoxMax;

    private static (Vector3 Min, Vector3 Max) Box(Vector3[] vertices)
    {
        Vector3 min = vertices[0], max = vertices[0];
        for (int i = 1; i < vertices.Length; i++)
        {
            min = Vector3.Min(min, vertices[i]);
            max = Vector3.Max(max, vertices[i]);
        }
        return (min, max);
    }

    /// <summary>The vertices.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices;

    /// <summary>The number of vertices.</summary>
    public int VertexCount => _vertices.Length;

    /// <summary>The plane: unit normal and D, with Dot(N, p) + D = 0 on the polygon.</summary>
    public Plane Plane { get; }

    /// <summary>The sidedness.</summary>
    public PolygonSides Sides { get; }

    /// <summary>
    /// Retail make_plane: the normal is the normalized sum of the fan cross products from vertex 0
    /// (robust for slightly non-planar input), D is minus the mean of the vertices' projections.
    /// </summary>
    internal static Plane MakePlane(ReadOnlySpan<Vector3> v, string name)
    {
        var sum = Vector3.Zero;
        for (int i = 1; i < v.Length - 1; i++)
            sum += Vector3.Cross(v[i] - v[0], v[i + 1] - v[0]);
        float length = sum.Length();
        if (!(length > 1e-12f))
            throw new ArgumentException($"{name}: degenerate polygon (zero area or collinear vertices).");
        var normal = sum / length;
        float dot = 0f;
        for (int i = 0; i < v.Length; i++)
            dot += Vector3.Dot(normal, v[i]);
        return new Plane(normal, -(dot / v.Length));
    }

    /// <inheritdoc />
    public override string ToString() => $"Polygon({_vertices.Length} verts, n={Plane.Normal}, d={Plane.D}, {Sides})";
}
