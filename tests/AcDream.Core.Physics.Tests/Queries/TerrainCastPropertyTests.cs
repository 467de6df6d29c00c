using System.Diagnostics;
using AcDream.Core.Physics.Queries;
using Xunit.Abstractions;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// Ray and sphere casts over terrain against an exact, independently written reference: the first time a
/// sphere moving along a segment comes within its radius of a terrain triangle's front, by brute force over
/// every triangle near the path, in double precision (face by its plane, edges by the capsule quadratic,
/// corners by the sphere quadratic; a ray meets faces only). Three worlds of 3 × 3 landblocks (flat,
/// one tilted plane, random heights) and seeded cases of every kind: random segments, shallow descents
/// (up to 1.2 km), rays lying in the terrain plane, spheres rolling on it, vertical rays down cell and
/// landblock edges and corners, rays through grid corners, starts labelled in another landblock.
///
/// A case whose answer changes when the start moves 0.5 mm up or down is ill-conditioned (a graze); there
/// only "not early and no NaN" is required. Elsewhere the cast must hit exactly when the reference does,
/// at a fraction within 1e-4 of it, with its contact point on the terrain and its normal the terrain's.
/// </summary>
public class TerrainCastPropertyTests(ITestOutputHelper output)
{
    private const int Cases = 100_000;
    private const int Seed = 20261202;
    private const double Shift = 5e-4, FractionTolerance = 1e-4;
    private const int Blocks = 3, FirstX = 0xA8, FirstY = 0xB3;
    private const double Cell = 24, Block = 192, Size = Blocks * Block;

    private enum Ground { Flat, Tilted, Random }

    [Fact]
    public void RayAndSphereCasts_OverTerrain_MatchAnExactReference()
    {
        var clock = Stopwatch.StartNew();
        var worlds = new[] { new TerrainWorld(Ground.Flat, 1), new TerrainWorld(Ground.Tilted, 2), new TerrainWorld(Ground.Random, 3) };
        var rng = new Random(Seed);
        var failures = new List<string>();
        int hits = 0, ambiguous = 0, rays = 0, failed = 0;
        var kinds = new int[7];
        for (int i = 0; i < Cases; i++)
        {
            var world = worlds[i % worlds.Length];
            var (kind, start, end, radius, label) = world.MakeCase(rng);
            kinds[kind]++;
            if (radius == 0f)
                rays++;
            string? problem = Check(world, start, end, radius, label, ref hits, ref ambiguous);
            if (problem is not null)
                failed++;
            if (problem is not null && failures.Count < 12)
                failures.Add($"case {i} ({world.Kind}, kind {kind}): start {start} end {end} r {radius} label 0x{label:X8}: {problem}");
        }
        output.WriteLine($"seed {Seed}: {Cases} cases ({rays} rays), kinds [{string.Join(", ", kinds)}], {hits} hits, {ambiguous} ill-conditioned, {clock.Elapsed.TotalSeconds:F1} s");
        Assert.True(failed == 0, $"{failed} of {Cases} cases disagree with the reference; the first:\n" + string.Join("\n", failures));
        Assert.True(ambiguous < Cases / 10, $"{ambiguous} of {Cases} cases were ill-conditioned: the generator no longer tests much");
    }

    /// <summary>One case: the library's cast against the reference; null when it agrees.</summary>
    private static string? Check(TerrainWorld world, Vector3 start, Vector3 end, float r, uint label, ref int hits, ref int ambiguous)
    {
        var q = world.Query;
        var from = new Position(label, start);
        bool found = r == 0f ? q.RayCast(from, end, out var hit) : q.SphereCast(from, end, r, out hit);
        var offset = TerrainWorld.Origin(label);
        var c = D3.Of(start) + offset;
        var d = D3.Of(end - start);
        var up = world.Reference(c + new D3(0, 0, Shift), d, r);
        var mid = world.Reference(c, d, r);
        var down = world.Reference(c - new D3(0, 0, Shift), d, r);
        // A ray passing within 0.1 mm outside a face (at a corner of the terrain no other face covers) is a graze too.
        var fat = r == 0f ? world.Reference(c, d, r, grow: 1e-4) : mid;
        if (found)
        {
            hits++;
            if (!float.IsFinite(hit.Fraction) || !Finite(hit.Center) || !Finite(hit.Point) || !Finite(hit.Normal))
                return $"NaN or infinity in the hit: {hit}";
            if (hit.Kind != SurfaceKind.Terrain)
                return $"hit {hit.Kind}, expected terrain";
            if (MathF.Abs(hit.Normal.Length() - 1f) > 1e-3f || Vector3.Dot(hit.Normal, end - start) > 1e-3f * (end - start).Length())
                return $"normal {hit.Normal} is not a unit vector facing the cast";
            string? contact = hit.Fraction == 0f ? null : world.CheckContact(D3.Of(hit.Center) + offset, D3.Of(hit.Point) + offset, D3.Of(hit.Normal), r, 2e-3 + FractionTolerance * d.Length, started: world.Clearance(c) >= r && c.Z >= world.HeightAt(c.X, c.Y));
            if (contact is not null)
                return $"{contact} (library {hit}; reference {mid.Found} {mid.Time} {mid.Normal}, shifted {down.Time}..{up.Time})";
        }
        bool agreed = up.Found == mid.Found && mid.Found == down.Found && fat.Found == mid.Found;
        if (!agreed)
        {
            ambiguous++;
            double earliest = Math.Min(up.Found ? up.Time : 2, Math.Min(mid.Found ? mid.Time : 2, down.Found ? down.Time : 2));
            return found && hit.Fraction < earliest - FractionTolerance ? $"early hit at {hit.Fraction} in a graze (reference no earlier than {earliest}; {hit})" : null;
        }
        if (found != mid.Found)
            return found ? $"hit where the reference has none: {hit}" : $"missed the reference's hit at {mid.Time} (n {mid.Normal})";
        if (!found)
            return null;
        double lo = Math.Min(up.Time, Math.Min(mid.Time, down.Time)) - FractionTolerance;
        double hi = Math.Max(up.Time, Math.Max(mid.Time, down.Time)) + FractionTolerance;
        return hit.Fraction < lo || hit.Fraction > hi ? $"fraction {hit.Fraction}, reference {mid.Time} (shifted starts {down.Time}..{up.Time}); {hit}" : null;
    }

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>A double-precision vector, so the reference shares no arithmetic with the library.</summary>
    private readonly record struct D3(double X, double Y, double Z)
    {
        public static D3 Of(Vector3 v) => new(v.X, v.Y, v.Z);
        public static D3 operator +(D3 a, D3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static D3 operator -(D3 a, D3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static D3 operator -(D3 a) => new(-a.X, -a.Y, -a.Z);
        public static D3 operator *(double s, D3 a) => new(s * a.X, s * a.Y, s * a.Z);
        public static double Dot(D3 a, D3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public static D3 Cross(D3 a, D3 b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        public double Length => Math.Sqrt(Dot(this, this));
        public D3 Unit => (1 / Length) * this;
        public override string ToString() => $"({X:G9}, {Y:G9}, {Z:G9})";
    }

    private readonly record struct RefHit(bool Found, double Time, D3 Normal);

    private readonly record struct Triangle(D3 A, D3 B, D3 C, D3 N);

    /// <summary>3 × 3 landblocks of one kind of ground, the library's world over them, and the reference's triangles.</summary>
    private sealed class TerrainWorld
    {
        private readonly double[,] _height = new double[Blocks * 8 + 1, Blocks * 8 + 1];
        private readonly Triangle[,,] _triangles = new Triangle[Blocks * 8, Blocks * 8, 2];
        private readonly float _slopeX, _slopeY, _base;

        public TerrainWorld(Ground kind, int seed)
        {
            Kind = kind;
            var rng = new Random(seed);
            (_slopeX, _slopeY, _base) = kind == Ground.Tilted ? (0.07f, -0.04f, 30f) : (0f, 0f, kind == Ground.Flat ? 0f : 2f);
            for (int x = 0; x <= Blocks * 8; x++)
                for (int y = 0; y <= Blocks * 8; y++)
                    _height[x, y] = kind == Ground.Random ? (float)(rng.NextDouble() * 20) : PlaneHeight(x * Cell, y * Cell);
            var world = new PhysicsWorld();
            for (int bx = 0; bx < Blocks; bx++)
                for (int by = 0; by < Blocks; by++)
                {
                    var heights = new float[81];
                    for (int x = 0; x <= 8; x++)
                        for (int y = 0; y <= 8; y++)
                            heights[x * 9 + y] = (float)_height[bx * 8 + x, by * 8 + y];
                    var terrain = new Terrain((uint)((FirstX + bx) << 8 | (FirstY + by)), heights);
                    world.Cells.AddLandblock(terrain);
                    for (int x = 0; x < 8; x++)
                        for (int y = 0; y < 8; y++)
                            AddCell(bx * 8 + x, by * 8 + y, terrain.IsSouthWestToNorthEastCut(x, y));
                }
            Query = new WorldQuery(world);
        }

        public Ground Kind { get; }
        public WorldQuery Query { get; }

        /// <summary>The tilted plane's height in float, as a caller would compute a point on it.</summary>
        private float PlaneHeight(double x, double y) => _base + _slopeX * (float)x + _slopeY * (float)y;

        private void AddCell(int gx, int gy, bool southWestToNorthEast)
        {
            D3 V(int x, int y) => new(x * Cell, y * Cell, _height[x, y]);
            D3 sw = V(gx, gy), se = V(gx + 1, gy), ne = V(gx + 1, gy + 1), nw = V(gx, gy + 1);
            _triangles[gx, gy, 0] = southWestToNorthEast ? Make(sw, se, ne) : Make(sw, se, nw);
            _triangles[gx, gy, 1] = southWestToNorthEast ? Make(sw, ne, nw) : Make(se, ne, nw);
        }

        private static Triangle Make(D3 a, D3 b, D3 c) => new(a, b, c, D3.Cross(b - a, c - a).Unit);

        /// <summary>The global frame's offset of a landblock's frame (the first landblock's south-west corner is 0).</summary>
        public static D3 Origin(uint cell) => new((((cell >> 24) & 0xFF) - FirstX) * Block, (((cell >> 16) & 0xFF) - FirstY) * Block, 0);

        private static uint LandCellOf(int bx, int by) => (uint)((FirstX + bx) << 24 | (FirstY + by) << 16 | 1);

        /// <summary>The terrain height at a global point, from the reference's triangles (outside the world, at the nearest point of its edge).</summary>
        public double HeightAt(double x, double y)
        {
            (x, y) = (Math.Clamp(x, 0, Size), Math.Clamp(y, 0, Size));
            int gx = Math.Clamp((int)Math.Floor(x / Cell), 0, Blocks * 8 - 1), gy = Math.Clamp((int)Math.Floor(y / Cell), 0, Blocks * 8 - 1);
            for (int k = 0; k < 2; k++)
            {
                var t = _triangles[gx, gy, k];
                if (Barycentric2D(t, x, y, 1e-9))
                    return t.A.Z - ((x - t.A.X) * t.N.X + (y - t.A.Y) * t.N.Y) / t.N.Z;
            }
            return 0;
        }

        private static bool Barycentric2D(Triangle t, double x, double y, double tolerance)
        {
            double E(D3 p, D3 q) => (q.X - p.X) * (y - p.Y) - (q.Y - p.Y) * (x - p.X);
            return E(t.A, t.B) >= -tolerance && E(t.B, t.C) >= -tolerance && E(t.C, t.A) >= -tolerance;
        }

        public (int Kind, Vector3 Start, Vector3 End, float Radius, uint Label) MakeCase(Random rng)
        {
            double U(double lo, double hi) => lo + rng.NextDouble() * (hi - lo);
            int kind = rng.Next(7);
            if (kind == 2 && Kind == Ground.Random)
                kind = 0;
            float r = rng.Next(2) == 0 ? 0f : (float)U(0.05, 1.5);
            D3 s, e;
            switch (kind)
            {
                case 0: // a random segment, mostly short
                {
                    s = Above(U(1, Size - 1), U(1, Size - 1), r + U(0.01, 20));
                    double reach = rng.Next(10) == 0 ? 600 : 60;
                    e = Above(s.X + U(-reach, reach), s.Y + U(-reach, reach), U(-5, 10));
                    break;
                }
                case 1: // a shallow descent, up to 1.2 km long
                {
                    s = Above(U(1, Size - 1), U(1, Size - 1), r + U(0.001, 3));
                    double heading = U(0, 2 * Math.PI), length = U(5, 1200);
                    e = Above(s.X + length * Math.Cos(heading), s.Y + length * Math.Sin(heading), r - U(0.001, 3));
                    break;
                }
                case 2: // along the plane: a ray lying in it, or a sphere rolling on it
                {
                    double heading = U(0, 2 * Math.PI), length = U(1, 300);
                    var n = _triangles[0, 0, 0].N;
                    var lift = r * n;
                    double x = U(1, Size - 1), y = U(1, Size - 1);
                    s = new D3(x, y, PlaneHeight(x, y)) + lift;
                    double x1 = x + length * Math.Cos(heading), y1 = y + length * Math.Sin(heading);
                    e = new D3(x1, y1, PlaneHeight(x1, y1)) + lift;
                    break;
                }
                case 3: // vertical, often down a cell or landblock edge or corner
                {
                    double x = rng.Next(3) == 0 ? Cell * rng.Next(Blocks * 8 + 1) : U(0, Size);
                    double y = rng.Next(3) == 0 ? Cell * rng.Next(Blocks * 8 + 1) : U(0, Size);
                    s = Above(x, y, r + U(0.01, 30));
                    e = Above(x, y, -U(0, 5));
                    break;
                }
                case 4: // aimed through a grid corner or an edge's midpoint
                {
                    double x = Cell * rng.Next(1, Blocks * 8), y = Cell * rng.Next(1, Blocks * 8);
                    if (rng.Next(2) == 0)
                        x += Cell / 2;
                    var target = Above(x, y, r);
                    s = Above(Math.Clamp(x + U(-40, 40), 0, Size), Math.Clamp(y + U(-40, 40), 0, Size), r + U(0, 15));
                    e = s + 1.5 * (target - s);
                    break;
                }
                case 5: // long, across landblocks, high and shallow or steep
                {
                    s = Above(U(1, Size - 1), U(1, Size - 1), r + U(0.5, 40));
                    e = Above(U(1, Size - 1), U(1, Size - 1), U(-3, 3));
                    break;
                }
                default: // short and skimming: up to 5 cm above the ground, a few cells long
                {
                    s = Above(U(1, Size - 1), U(1, Size - 1), r + U(0, 0.05));
                    e = Above(s.X + U(-70, 70), s.Y + U(-70, 70), r + U(-0.05, 0.05));
                    break;
                }
            }
            int bx = Math.Clamp((int)Math.Floor(s.X / Block), 0, Blocks - 1), by = Math.Clamp((int)Math.Floor(s.Y / Block), 0, Blocks - 1);
            if (rng.Next(5) == 0)
                (bx, by) = (rng.Next(Blocks), rng.Next(Blocks));
            uint label = LandCellOf(bx, by);
            var o = Origin(label);
            var start = new Vector3((float)(s.X - o.X), (float)(s.Y - o.Y), (float)s.Z);
            var end = new Vector3((float)(e.X - o.X), (float)(e.Y - o.Y), (float)e.Z);
            return (kind, start, end, r, label);
        }

        private D3 Above(double x, double y, double z) => new(x, y, HeightAt(x, y) + z);

        /// <summary>
        /// The first contact of a sphere moving from <paramref name="c"/> by <paramref name="d"/> with the front
        /// of any terrain triangle: a start within the radius counts (at 0) when it moves into the triangle.
        /// </summary>
        public RefHit Reference(D3 c, D3 d, double r, double grow = 0)
        {
            var best = new RefHit(false, 2, default);
            double reach = r + 1e-3 + Cell * Math.Sqrt(0.5);
            int x0 = Math.Max(0, (int)Math.Floor((Math.Min(c.X, c.X + d.X) - r - 1) / Cell)), x1 = Math.Min(Blocks * 8 - 1, (int)Math.Floor((Math.Max(c.X, c.X + d.X) + r + 1) / Cell));
            int y0 = Math.Max(0, (int)Math.Floor((Math.Min(c.Y, c.Y + d.Y) - r - 1) / Cell)), y1 = Math.Min(Blocks * 8 - 1, (int)Math.Floor((Math.Max(c.Y, c.Y + d.Y) + r + 1) / Cell));
            for (int gx = x0; gx <= x1; gx++)
                for (int gy = y0; gy <= y1; gy++)
                {
                    // Skip cells whose centre is farther from the path (in plan) than half their diagonal plus the radius.
                    double cx = (gx + 0.5) * Cell - c.X, cy = (gy + 0.5) * Cell - c.Y;
                    double dd = d.X * d.X + d.Y * d.Y;
                    double s = dd > 0 ? Math.Clamp((cx * d.X + cy * d.Y) / dd, 0, 1) : 0;
                    double px = cx - s * d.X, py = cy - s * d.Y;
                    if (px * px + py * py > reach * reach)
                        continue;
                    for (int k = 0; k < 2; k++)
                    {
                        var h = FirstContact(_triangles[gx, gy, k], c, d, r, grow);
                        if (h.Found && h.Time < best.Time)
                            best = h;
                    }
                }
            return best;
        }

        private static RefHit FirstContact(in Triangle t, D3 c, D3 d, double r, double grow)
        {
            // Front only: a start behind the plane touches nothing, and a contact counts with the centre in front.
            double side = D3.Dot(t.N, c - t.A), vn = D3.Dot(t.N, d);
            var best = new RefHit(false, 2, default);
            if (side >= 0)
            {
                var away = c - Closest(t, c);
                if (away.Length <= r)
                {
                    var n = r == 0 || away.Length == 0 ? t.N : away.Unit;
                    return D3.Dot(n, d) < 0 ? new RefHit(true, 0, n) : default;
                }
                if (vn < 0)
                {
                    double time = (side - r) / -vn;
                    var p = c + time * d - r * t.N;
                    if (time >= 0 && time <= 1 && InTriangle(t, p, grow))
                        best = new RefHit(true, time, t.N);
                }
            }
            if (r == 0)
                return best;
            var edgeOrCorner = new RefHit(false, 2, default);
            Capsule(t.A, t.B, c, d, r, ref edgeOrCorner);
            Capsule(t.B, t.C, c, d, r, ref edgeOrCorner);
            Capsule(t.C, t.A, c, d, r, ref edgeOrCorner);
            Ball(t.A, c, d, r, ref edgeOrCorner);
            Ball(t.B, c, d, r, ref edgeOrCorner);
            Ball(t.C, c, d, r, ref edgeOrCorner);
            bool inFront = side + edgeOrCorner.Time * vn >= 0;
            return edgeOrCorner.Found && inFront && edgeOrCorner.Time < best.Time ? edgeOrCorner : best;
        }

        /// <summary>The sphere's first contact with the infinite cylinder of radius r around a-b, kept when within the segment.</summary>
        private static void Capsule(D3 a, D3 b, D3 c, D3 d, double r, ref RefHit best)
        {
            var axis = (b - a).Unit;
            var m = c - a;
            var mp = m - D3.Dot(m, axis) * axis;
            var dp = d - D3.Dot(d, axis) * axis;
            if (!Entry(mp, dp, r, best.Time, out double time))
                return;
            double along = D3.Dot(m + time * d, axis);
            if (along < 0 || along > (b - a).Length)
                return;
            best = new RefHit(true, time, (mp + time * dp).Unit);
        }

        private static void Ball(D3 p, D3 c, D3 d, double r, ref RefHit best)
        {
            var m = c - p;
            if (Entry(m, d, r, best.Time, out double time))
                best = new RefHit(true, time, (m + time * d).Unit);
        }

        /// <summary>The time in [0, 1], before <paramref name="limit"/>, at which |m + t·d| falls to r from above (a tangent is no entry).</summary>
        private static bool Entry(D3 m, D3 d, double r, double limit, out double time)
        {
            double qa = D3.Dot(d, d), qb = D3.Dot(m, d), qc = D3.Dot(m, m) - r * r;
            double disc = qb * qb - qa * qc;
            time = qa == 0 || disc <= 0 || qb >= 0 ? -1 : (-qb - Math.Sqrt(disc)) / qa;
            return time >= 0 && time <= 1 && time < limit;
        }

        private static bool InTriangle(in Triangle t, D3 p, double grow = 0) =>
            Side(t.A, t.B, p, t.N, grow) && Side(t.B, t.C, p, t.N, grow) && Side(t.C, t.A, p, t.N, grow);

        // A point on an edge counts for both triangles (1e-9 m from it is rounding, not geometry); grow widens the triangle by that many metres.
        private static bool Side(D3 a, D3 b, D3 p, D3 n, double grow) => D3.Dot(D3.Cross(b - a, p - a), n) >= -(grow + 1e-9) * (b - a).Length;

        private static D3 Closest(in Triangle t, D3 p)
        {
            var onPlane = p - D3.Dot(t.N, p - t.A) * t.N;
            if (InTriangle(t, onPlane))
                return onPlane;
            var ab = OnSegment(t.A, t.B, p);
            var bc = OnSegment(t.B, t.C, p);
            var ca = OnSegment(t.C, t.A, p);
            double dab = (p - ab).Length, dbc = (p - bc).Length, dca = (p - ca).Length;
            return dab <= dbc && dab <= dca ? ab : dbc <= dca ? bc : ca;
        }

        private static D3 OnSegment(D3 a, D3 b, D3 p)
        {
            var e = b - a;
            return a + Math.Clamp(D3.Dot(p - a, e) / D3.Dot(e, e), 0, 1) * e;
        }

        /// <summary>
        /// A reported contact is real: the point lies on the terrain, the centre is the radius from the
        /// terrain (not inside it), and the normal is the direction from the point to the centre (for a
        /// ray, the face normal of a triangle at the point).
        /// </summary>
        public string? CheckContact(D3 center, D3 point, D3 normal, double r, double tolerance, bool started)
        {
            double nearest = double.MaxValue;
            bool faceMatches = false;
            for (int gx = Math.Max(0, (int)Math.Floor((point.X - 1) / Cell)); gx <= Math.Min(Blocks * 8 - 1, (int)Math.Floor((point.X + 1) / Cell)); gx++)
                for (int gy = Math.Max(0, (int)Math.Floor((point.Y - 1) / Cell)); gy <= Math.Min(Blocks * 8 - 1, (int)Math.Floor((point.Y + 1) / Cell)); gy++)
                    for (int k = 0; k < 2; k++)
                    {
                        var t = _triangles[gx, gy, k];
                        double distance = (point - Closest(t, point)).Length;
                        nearest = Math.Min(nearest, distance);
                        faceMatches |= distance <= tolerance && D3.Dot(t.N, normal) >= 1 - 1e-4;
                    }
            if (nearest > tolerance)
                return $"contact point {point} is {nearest} m from the terrain";
            if (r == 0)
                return faceMatches ? null : $"normal {normal} is the face normal of no triangle at the contact point";
            double gap = (center - point).Length - r;
            if (Math.Abs(gap) > tolerance)
                return $"centre is {gap} m off the radius from the contact point";
            if (!started)
                return null;
            double clearance = Clearance(center);
            return clearance < r - tolerance ? $"centre is {r - clearance} m inside the terrain at contact" : null;
        }

        /// <summary>The distance from a point to the nearest terrain triangle within two cells.</summary>
        public double Clearance(D3 p)
        {
            double clearance = double.MaxValue;
            for (int gx = Math.Max(0, (int)Math.Floor(p.X / Cell) - 2); gx <= Math.Min(Blocks * 8 - 1, (int)Math.Floor(p.X / Cell) + 2); gx++)
                for (int gy = Math.Max(0, (int)Math.Floor(p.Y / Cell) - 2); gy <= Math.Min(Blocks * 8 - 1, (int)Math.Floor(p.Y / Cell) + 2); gy++)
                    for (int k = 0; k < 2; k++)
                        clearance = Math.Min(clearance, (p - Closest(_triangles[gx, gy, k], p)).Length);
            return clearance;
        }
    }
}
