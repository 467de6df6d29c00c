using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.ExceptionServices;
using System.Threading;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// Builds physics BSP trees (the retail BSPTREE shape) from convex polygons, for scenes written by hand
/// rather than read from DAT files.
/// </summary>
/// <remarks>
/// <para>
/// <b>Algorithm.</b> A recursive split whose splitters are always polygon planes. At each node the
/// splitter is the candidate plane with the lowest score <c>8 × splits + |front − back|</c>; candidates
/// are the planes of the node's polygons that are not already a split plane on the path from the root
/// (up to sign); ties go to the polygon that comes first in the input, so the output depends only on the
/// input order (no hashing, no randomness). Polygons crossing the splitter are cut into two convex pieces
/// (new <see cref="Polygon"/>s with the same sidedness; slivers under 1e-7 square units are dropped).
/// A node whose polygons all lie on planes already used above it becomes a leaf holding them.
/// </para>
/// <para>
/// <b>Coplanar polygons.</b> A polygon on the splitter plane facing the same way goes to the
/// <i>back</i> (inside) child; one facing the opposite way goes to the front child. In both cases the
/// polygon ends in a leaf whose region lies behind the polygon, i.e. on its solid side. This is what makes
/// a closed convex solid compile to the retail form: one internal node per face plane (in input order),
/// each front child an empty non-solid leaf, and the innermost back child a solid leaf holding all the
/// faces. (Putting same-facing coplanar polygons in front, as a plain BSP would, leaves a solid's faces in
/// its outside leaves, where retail's leaf tests, which only look at leaves that hold polygons, would
/// miss the solid.) For the sphere-versus-polygon queries the side does not matter: a sphere that can
/// touch a polygon is within reach of its plane and visits both children. A room made of inward-facing
/// polygons compiles to a chain of front (inside) children, which is the shape the cell queries walk.
/// </para>
/// <para>
/// <b>Solid leaves.</b> Every internal node has both children (empty leaves where nothing lies), so no
/// query meets a missing child. No polygon crosses the inside of a leaf's region (the split planes on
/// its path cut the box around the input, grown by a margin), so the region is wholly in or out. A leaf
/// is <see cref="BspNodeData.Solid"/> when it holds polygons and the winding number of all the input
/// polygons around a point strictly inside its region is at least 0.99: the region is closed in by
/// outward-facing geometry. (The classic "back of the last split is solid" rule would make the space
/// under a lone floor quad solid.) Leaves of open geometry (a floor quad, a stair, a box missing a face)
/// are therefore not solid, and empty leaves never are, matching retail's leaf tests, which ignore
/// leaves without polygons. Interpenetrating solids are accepted, but a region inside one solid that
/// holds no polygon is left non-solid; touching solids are fine.
/// </para>
/// <para>
/// <b>Bounds.</b> Every node gets an explicit bounding sphere: the centre of the axis-aligned box of its
/// content and the largest distance to it (plus a 1e-5 relative slack). The content of a leaf is its
/// polygons' vertices, and for a solid leaf also the corners of its region; the content of an internal
/// node is the union of its children's. An empty leaf gets radius 0 at its parent's centre.
/// </para>
/// <para>
/// Nodes are numbered depth first (node, front subtree, back subtree); the tree's polygon list holds the
/// (possibly split) polygons in leaf order, an unsplit input polygon keeping its instance.
/// Recursion depth is at most the number of distinct planes and is limited to <see cref="InputLimits.MaxBspDepth"/>.
/// </para>
/// </remarks>
public static class BspCompiler
{
    /// <summary>Distance within which a vertex counts as on a plane.</summary>
    public const float PlaneEpsilon = 1e-4f;

    private const float MinFragmentArea = 1e-7f;
    private const double EnclosedWinding = 0.99;

    private sealed class Node
    {
        public bool IsLeaf;
        public Plane Plane;
        public Node? Front;
        public Node? Back;
        public bool Solid;
        public List<Polygon> Polygons = new();
        public List<Vector3> Content = new();
        public Sphere Bounds;
    }

    /// <summary>
    /// Compiles a physics BSP tree from convex polygons (see the class remarks for the algorithm, the
    /// placement of coplanar polygons, which leaves are solid and how bounds are computed).
    /// </summary>
    /// <param name="polygons">The polygons, counter-clockwise seen from their front (solids: outward).</param>
    /// <param name="name">A name for error messages.</param>
    /// <returns>A validated tree built with <see cref="BspTree.Create"/>.</returns>
    /// <exception cref="ArgumentException">The list is null or empty, an entry is null, the list holds more than
    /// <see cref="InputLimits.MaxCompilePolygons"/> polygons, or the tree would be deeper than <see cref="InputLimits.MaxBspDepth"/>.</exception>
    public static BspTree Compile(IReadOnlyList<Polygon> polygons, string name = "polygons")
    {
        ArgumentNullException.ThrowIfNull(polygons);
        if (polygons.Count == 0)
            throw new ArgumentException($"{name}: at least one polygon is needed to compile a BSP tree.", nameof(polygons));
        if (polygons.Count > InputLimits.MaxCompilePolygons)
            throw new ArgumentException($"{name}: at most {InputLimits.MaxCompilePolygons} polygons can be compiled into one BSP tree (InputLimits.MaxCompilePolygons), got {polygons.Count}; split the mesh into several parts.", nameof(polygons));
        var set = new List<Polygon>(polygons.Count);
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        for (int i = 0; i < polygons.Count; i++)
        {
            var p = polygons[i] ?? throw new ArgumentException($"{name}[{i}]: is null.", nameof(polygons));
            foreach (var v in p.Vertices)
            {
                min = Vector3.Min(min, v);
                max = Vector3.Max(max, v);
            }
            set.Add(p);
        }

        float margin = MathF.Max(1f, 0.1f * Vector3.Distance(min, max));
        var cell = BoxCell(min - new Vector3(margin), max + new Vector3(margin));

        // The recursion below takes about a kilobyte of stack per tree level, more than a 256 KB worker
        // thread has at InputLimits.MaxBspDepth levels, so it runs on a thread of its own with a stack
        // sized for the limit. Compiling is load-time work; the result does not depend on the thread.
        var nodes = new List<BspNodeData>();
        var outPolygons = new List<Polygon>();
        Exception? failure = null;
        var worker = new Thread(() =>
        {
            try
            {
                var root = Build(set, [.. new bool[set.Count]], new List<(Plane, bool)>(), cell, set, name);
                ComputeBounds(root, null);
                Flatten(root, nodes, outPolygons, new Dictionary<Polygon, int>(ReferenceEqualityComparer.Instance));
            }
            catch (Exception e)
            {
                failure = e;
            }
        }, CompileStackBytes);
        worker.Start();
        worker.Join();
        if (failure is not null)
            ExceptionDispatchInfo.Capture(failure).Throw();
        return BspTree.Create(outPolygons, nodes, name);
    }

    /// <summary>The stack of the compiler's own thread: 16 MB, about sixty times what <see cref="InputLimits.MaxBspDepth"/> levels need.</summary>
    private const int CompileStackBytes = 16 * 1024 * 1024;

    /// <summary>
    /// One node of the recursive split. <paramref name="onPath"/> says, for each polygon of the set, whether
    /// it lies on a split plane of <paramref name="path"/> (such polygons are no candidates); it is carried
    /// down rather than recomputed: a polygon passed down unchanged is on the child's path when it was on
    /// the parent's or is coplanar with the new split (the same classifications the full test would make);
    /// only the pieces of split polygons are tested against the whole path.
    /// </summary>
    private static Node Build(List<Polygon> set, List<bool> onPath, List<(Plane Plane, bool Front)> path, List<Vector3[]> cell, IReadOnlyList<Polygon> all, string name)
    {
        // Each split uses up one plane of the input; deeper than that means float drift broke coplanarity.
        if (path.Count > 2 * all.Count + 64)
            throw new InvalidOperationException($"{name}: BSP compile did not converge (depth {path.Count}); the polygons may be too far from the origin for float precision.");
        // Refused before the recursion gets deep: the tree could not be used anyway (BspTree.Create).
        if (path.Count >= InputLimits.MaxBspDepth)
            throw new ArgumentException($"{name}: the compiled BSP tree would be deeper than {InputLimits.MaxBspDepth} levels (InputLimits.MaxBspDepth); a convex solid needs one level per distinct face plane, so split a mesh with that many planes into several parts.", nameof(all));
        int best = -1;
        int bestScore = int.MaxValue;
        for (int i = 0; i < set.Count; i++)
        {
            if (onPath[i])
                continue;
            var plane = set[i].Plane;
            int front = 0, back = 0, splits = 0;
            int remaining = set.Count;
            bool beaten = false;
            foreach (var p in set)
            {
                switch (Classify(p, plane))
                {
                    case Side.Front: front++; break;
                    case Side.Back: back++; break;
                    case Side.Coplanar:
                        if (Vector3.Dot(p.Plane.Normal, plane.Normal) > 0) back++; else front++;
                        break;
                    default: splits++; break;
                }
                // The score can only end at or above this bound (splits only grow; each polygon left can
                // narrow |front − back| by one); a candidate that cannot beat the best (ties go to the
                // earlier one) is dropped without classifying the rest. The choice is unchanged.
                remaining--;
                if (bestScore != int.MaxValue && 8 * splits + Math.Max(Math.Abs(front - back) - remaining, 0) >= bestScore)
                {
                    beaten = true;
                    break;
                }
            }
            if (beaten)
                continue;
            int score = 8 * splits + Math.Abs(front - back);
            if (score < bestScore)
            {
                bestScore = score;
                best = i;
            }
        }

        if (best < 0)
            return MakeLeaf(set, cell, path, all);

        var split = set[best].Plane;
        var frontSet = new List<Polygon>();
        var backSet = new List<Polygon>();
        var frontOnPath = new List<bool>();
        var backOnPath = new List<bool>();
        List<(Plane, bool)> frontPath = [.. path, (split, true)];
        List<(Plane, bool)> backPath = [.. path, (split, false)];
        for (int i = 0; i < set.Count; i++)
        {
            var p = set[i];
            switch (Classify(p, split))
            {
                case Side.Front: frontSet.Add(p); frontOnPath.Add(onPath[i]); break;
                case Side.Back: backSet.Add(p); backOnPath.Add(onPath[i]); break;
                case Side.Coplanar:
                    if (Vector3.Dot(p.Plane.Normal, split.Normal) > 0) { backSet.Add(p); backOnPath.Add(true); }
                    else { frontSet.Add(p); frontOnPath.Add(true); }
                    break;
                default:
                    SplitPolygon(p, split, name, out var f, out var b);
                    if (f is not null) { frontSet.Add(f); frontOnPath.Add(OnAnyPlane(f, frontPath)); }
                    if (b is not null) { backSet.Add(b); backOnPath.Add(OnAnyPlane(b, backPath)); }
                    break;
            }
        }

        var flipped = new Plane(-split.Normal, -split.D);
        return new Node
        {
            Plane = split,
            Front = Build(frontSet, frontOnPath, frontPath, ClipCell(cell, flipped), all, name),
            Back = Build(backSet, backOnPath, backPath, ClipCell(cell, split), all, name),
        };
    }

    private static Node MakeLeaf(List<Polygon> set, List<Vector3[]> cell, List<(Plane Plane, bool Front)> path, IReadOnlyList<Polygon> all)
    {
        var leaf = new Node { IsLeaf = true, Polygons = set };
        if (set.Count == 0)
            return leaf;
        foreach (var p in set)
            foreach (var v in p.Vertices)
                leaf.Content.Add(v);
        leaf.Solid = IsEnclosed(cell, path, all);
        if (leaf.Solid)
            foreach (var face in cell)
                leaf.Content.AddRange(face);
        return leaf;
    }

    /// <summary>
    /// True when a point strictly inside the region has a winding number of about one (or more) with
    /// respect to all the input polygons, i.e. the region is closed in by outward-facing geometry.
    /// </summary>
    private static bool IsEnclosed(List<Vector3[]> cell, List<(Plane Plane, bool Front)> path, IReadOnlyList<Polygon> all)
    {
        var centre = Vector3.Zero;
        int count = 0;
        foreach (var face in cell)
            foreach (var v in face)
            {
                centre += v;
                count++;
            }
        if (count == 0)
            return false;
        centre /= count;
        foreach (var (plane, front) in path)
        {
            float d = Distance(plane, centre);
            if (front ? d <= PlaneEpsilon : d >= -PlaneEpsilon)
                return false; // the region has no volume
        }
        return WindingNumber(centre, all) >= EnclosedWinding;
    }

    /// <summary>The generalized winding number: the signed solid angle of the polygons seen from the point, over 4π.</summary>
    private static double WindingNumber(Vector3 point, IReadOnlyList<Polygon> polygons)
    {
        double total = 0;
        foreach (var polygon in polygons)
        {
            var v = polygon.Vertices;
            for (int i = 1; i < v.Length - 1; i++)
                total += SolidAngle(v[0] - point, v[i] - point, v[i + 1] - point);
        }
        return total / (4 * Math.PI);
    }

    /// <summary>Signed solid angle of a triangle (Van Oosterom and Strackee); positive when seen from behind its counter-clockwise front.</summary>
    private static double SolidAngle(Vector3 a, Vector3 b, Vector3 c)
    {
        double ax = a.X, ay = a.Y, az = a.Z, bx = b.X, by = b.Y, bz = b.Z, cx = c.X, cy = c.Y, cz = c.Z;
        double la = Math.Sqrt(ax * ax + ay * ay + az * az);
        double lb = Math.Sqrt(bx * bx + by * by + bz * bz);
        double lc = Math.Sqrt(cx * cx + cy * cy + cz * cz);
        double triple = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
        double denominator = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (ax * cx + ay * cy + az * cz) * lb + (bx * cx + by * cy + bz * cz) * la;
        return 2 * PortableMath.Atan2(triple, denominator);
    }

    private static bool OnAnyPlane(Polygon polygon, List<(Plane Plane, bool Front)> path)
    {
        foreach (var (plane, _) in path)
            if (Classify(polygon, plane) == Side.Coplanar)
                return true;
        return false;
    }

    private enum Side { Coplanar, Front, Back, Spanning }

    private static float Distance(in Plane plane, Vector3 point) => Vector3.Dot(plane.Normal, point) + plane.D;

    private static Side Classify(Polygon polygon, in Plane plane)
    {
        bool front = false, back = false;
        foreach (var v in polygon.Vertices)
        {
            float d = Distance(plane, v);
            if (d > PlaneEpsilon) front = true;
            else if (d < -PlaneEpsilon) back = true;
        }
        return front ? (back ? Side.Spanning : Side.Front) : (back ? Side.Back : Side.Coplanar);
    }

    /// <summary>Cuts a convex polygon by a plane; a piece too small to be a polygon comes back null.</summary>
    private static void SplitPolygon(Polygon polygon, in Plane plane, string name, out Polygon? front, out Polygon? back)
    {
        var v = polygon.Vertices;
        var frontPoints = new List<Vector3>();
        var backPoints = new List<Vector3>();
        for (int i = 0; i < v.Length; i++)
        {
            var a = v[i];
            var b = v[(i + 1) % v.Length];
            float da = Distance(plane, a);
            float db = Distance(plane, b);
            if (da >= -PlaneEpsilon) frontPoints.Add(a);
            if (da <= PlaneEpsilon) backPoints.Add(a);
            if ((da > PlaneEpsilon && db < -PlaneEpsilon) || (da < -PlaneEpsilon && db > PlaneEpsilon))
            {
                var cut = a + (b - a) * (da / (da - db));
                frontPoints.Add(cut);
                backPoints.Add(cut);
            }
        }
        front = MakePiece(frontPoints, polygon.Sides, name);
        back = MakePiece(backPoints, polygon.Sides, name);
    }

    private static Polygon? MakePiece(List<Vector3> points, PolygonSides sides, string name)
    {
        if (points.Count < 3 || Area(points.ToArray()) < MinFragmentArea)
            return null;
        return new Polygon(points.ToArray(), sides, name + " (split piece)", cutFromValidPolygon: true);
    }

    private static float Area(ReadOnlySpan<Vector3> v)
    {
        var sum = Vector3.Zero;
        for (int i = 1; i < v.Length - 1; i++)
            sum += Vector3.Cross(v[i] - v[0], v[i + 1] - v[0]);
        return 0.5f * sum.Length();
    }

    /// <summary>The corners of the six box faces (+X, −X, +Y, −Y, +Z, −Z), counter-clockwise from outside.</summary>
    internal static Vector3[][] BoxCorners(Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        return
        [
            [new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1)],
            [new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0)],
            [new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0)],
            [new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1)],
            [new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1)],
            [new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)],
        ];
    }

    /// <summary>The six faces of an axis-aligned box, as the starting region.</summary>
    private static List<Vector3[]> BoxCell(Vector3 min, Vector3 max)
    {
        var faces = new List<Vector3[]>();
        foreach (var p in BoxCorners(min, max))
            faces.Add(p);
        return faces;
    }

    /// <summary>Keeps the part of a convex region behind <paramref name="keepBehind"/>, closing it with a cap face.</summary>
    private static List<Vector3[]> ClipCell(List<Vector3[]> cell, in Plane keepBehind)
    {
        bool anyIn = false, anyOut = false;
        foreach (var face in cell)
            foreach (var p in face)
            {
                float d = Distance(keepBehind, p);
                if (d > PlaneEpsilon) anyOut = true;
                else if (d < -PlaneEpsilon) anyIn = true;
            }
        if (!anyOut)
            return cell;
        if (!anyIn)
            return new List<Vector3[]>();

        var result = new List<Vector3[]>();
        var cap = new List<Vector3>();
        foreach (var face in cell)
        {
            var kept = new List<Vector3>();
            for (int i = 0; i < face.Length; i++)
            {
                var a = face[i];
                var b = face[(i + 1) % face.Length];
                float da = Distance(keepBehind, a);
                float db = Distance(keepBehind, b);
                if (da <= PlaneEpsilon)
                {
                    kept.Add(a);
                    if (da >= -PlaneEpsilon) cap.Add(a);
                }
                if ((da > PlaneEpsilon && db < -PlaneEpsilon) || (da < -PlaneEpsilon && db > PlaneEpsilon))
                {
                    var cut = a + (b - a) * (da / (da - db));
                    kept.Add(cut);
                    cap.Add(cut);
                }
            }
            if (kept.Count >= 3 && Area(kept.ToArray()) > 0f)
                result.Add(kept.ToArray());
        }

        var capFace = OrderCap(cap, keepBehind.Normal);
        if (capFace is not null)
            result.Add(capFace);
        return result;
    }

    /// <summary>Orders points lying on a plane around their centroid (they are the corners of a convex face).</summary>
    private static Vector3[]? OrderCap(List<Vector3> points, Vector3 normal)
    {
        var unique = new List<Vector3>();
        foreach (var p in points)
        {
            bool seen = false;
            foreach (var q in unique)
                if (Vector3.DistanceSquared(p, q) < 1e-10f) { seen = true; break; }
            if (!seen) unique.Add(p);
        }
        if (unique.Count < 3)
            return null;
        var centre = Vector3.Zero;
        foreach (var p in unique) centre += p;
        centre /= unique.Count;
        var axisU = Vector3.Normalize(MathF.Abs(normal.X) < 0.9f ? Vector3.Cross(normal, Vector3.UnitX) : Vector3.Cross(normal, Vector3.UnitY));
        var axisV = Vector3.Cross(normal, axisU);
        var angles = new float[unique.Count];
        for (int i = 0; i < unique.Count; i++)
        {
            var d = unique[i] - centre;
            angles[i] = PortableMath.Atan2(Vector3.Dot(d, axisV), Vector3.Dot(d, axisU));
        }
        var ordered = unique.ToArray();
        Array.Sort(angles, ordered);
        return Area(ordered) > 0f ? ordered : null;
    }

    /// <summary>Bottom-up bounds; empty leaves get radius 0 at their parent's centre.</summary>
    private static List<Vector3> ComputeBounds(Node node, Node? parent)
    {
        if (!node.IsLeaf)
        {
            node.Content = new List<Vector3>(ComputeBounds(node.Front!, node));
            node.Content.AddRange(ComputeBounds(node.Back!, node));
        }
        if (node.Content.Count > 0)
            node.Bounds = SphereAround(node.Content);
        if (!node.IsLeaf)
        {
            if (node.Front!.Content.Count == 0) node.Front.Bounds = new Sphere(node.Bounds.Center, 0f);
            if (node.Back!.Content.Count == 0) node.Back.Bounds = new Sphere(node.Bounds.Center, 0f);
        }
        return node.Content;
    }

    private static Sphere SphereAround(List<Vector3> points)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var p in points)
        {
            min = Vector3.Min(min, p);
            max = Vector3.Max(max, p);
        }
        var centre = (min + max) * 0.5f;
        float radius = 0f;
        foreach (var p in points)
            radius = MathF.Max(radius, Vector3.Distance(centre, p));
        return new Sphere(centre, radius * (1f + 1e-5f) + 1e-5f);
    }

    private static int Flatten(Node node, List<BspNodeData> nodes, List<Polygon> polygons, Dictionary<Polygon, int> polygonIndex)
    {
        int index = nodes.Count;
        nodes.Add(null!);
        if (node.IsLeaf)
        {
            var indices = new int[node.Polygons.Count];
            for (int k = 0; k < indices.Length; k++)
            {
                var p = node.Polygons[k];
                if (!polygonIndex.TryGetValue(p, out int at))
                {
                    at = polygons.Count;
                    polygons.Add(p);
                    polygonIndex.Add(p, at);
                }
                indices[k] = at;
            }
            nodes[index] = new BspNodeData { IsLeaf = true, Solid = node.Solid, Polygons = indices, Bounds = node.Bounds };
            return index;
        }
        int front = Flatten(node.Front!, nodes, polygons, polygonIndex);
        int back = Flatten(node.Back!, nodes, polygons, polygonIndex);
        nodes[index] = new BspNodeData { SplitPlane = node.Plane, Front = front, Back = back, Bounds = node.Bounds };
        return index;
    }
}
