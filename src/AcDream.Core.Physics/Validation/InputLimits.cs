namespace AcDream.Core.Physics.Validation;

/// <summary>
/// The ranges every public entry point accepts, so that no arithmetic inside a query can overflow to
/// infinity or NaN, no recursion can exhaust a thread's stack and no input can make the library run for
/// hours. These are the library's own limits, not retail values (retail checks nothing), except where a
/// limit says it follows a retail data format.
/// </summary>
public static class InputLimits
{
    /// <summary>
    /// The largest absolute value of any coordinate given to the library (positions, vertices, centres,
    /// heights, plane distances), in metres: 100 km, twice the width of the retail world, so a point of
    /// any landblock can be written in any other landblock's frame. Products of three such values stay
    /// far below float's range.
    /// </summary>
    public const float MaxCoordinate = 100_000f;

    /// <summary>
    /// The largest size of any single thing, in metres: 1 km, for sphere, cylinder and model radii (after
    /// scaling), heights, step heights and scales. Retail's largest objects are a few hundred metres across.
    /// </summary>
    public const float MaxExtent = 1_000f;

    /// <summary>
    /// The deepest physics or cell BSP tree accepted, counted in nodes from the root to the deepest leaf
    /// (a lone leaf is depth 1). The queries recurse once per level; at this depth a query, called from
    /// inside <c>PhysicsEngine.Resolve</c>, fits in 128 KB of stack even in a Debug build (twice this depth
    /// needed more than 128 KB in Debug), so a query on a worker thread with a 256 KB stack is safe for any
    /// tree that <c>BspTree.Create</c> accepts (tested). Retail trees are far shallower: compiled BSPs are roughly balanced
    /// (depth about twice log2 of the polygon count) and a cell's containment chain has one node per wall.
    /// A convex solid compiled by <c>BspCompiler</c> has one level per distinct face plane.
    /// </summary>
    public const int MaxBspDepth = 256;

    /// <summary>
    /// The most vertices one polygon may have: 127, because retail stores a polygon's vertex count
    /// (CPolygon::num_pts) in a signed byte.
    /// </summary>
    public const int MaxPolygonVertices = 127;

    /// <summary>
    /// How far, in metres, a polygon's vertex may lie off the polygon's plane, or on the outer side of one
    /// of its edges (a concave corner), before the polygon is refused: 1 mm plus one millionth of the
    /// polygon's largest coordinate (float rounding grows with distance from the origin; 0.1 m at 100 km).
    /// Real retail polygons (the Holtburg cells and buildings) are within 0.06 mm of their planes and
    /// exactly convex. Two consecutive vertices closer than this are a duplicate vertex.
    /// </summary>
    public const float PolygonTolerance = 1e-3f;

    /// <summary>The part of <see cref="PolygonTolerance"/> that grows with the polygon's largest coordinate.</summary>
    public const float PolygonRelativeTolerance = 1e-6f;

    /// <summary>
    /// How far, in metres, a mover's origin may lie outside the cell its state names, beyond the mover's own
    /// reach (the farthest point of its spheres from its origin): 24 m, one outdoor cell. A state whose cell
    /// does not hold it is refused (retail never produces one; the engine would otherwise report every move
    /// as succeeded while leaving the mover where it is). For an outdoor cell the distance is measured
    /// horizontally from the cell's 24 m square; for an indoor cell from the bounding sphere of its BSPs.
    /// </summary>
    public const float MaxDistanceFromCell = 24f;

    /// <summary>
    /// The most polygons <c>BspCompiler.Compile</c> accepts in one call: 2048. Compiling grows faster than
    /// the square of the polygon count for overlapping geometry (the splitter choice scores every candidate
    /// plane against every polygon of a node, and each leaf's solidity is a winding number over all input
    /// polygons); 1 600 scattered triangles take about 2 s on a 2-core machine (docs/performance.md,
    /// <c>bench … compile</c>). Retail physics meshes have at most a few hundred polygons.
    /// </summary>
    public const int MaxCompilePolygons = 2048;

    /// <summary>
    /// The most frames a scene file's movers may walk in all (movers × frames, repeats expanded): 200 000,
    /// about 10 s of running and 100 MB of trajectory. The real-cell scenes have at most about 3 000 frames;
    /// one mover may walk at most <c>SceneLoader.MaxFramesPerMover</c>.
    /// </summary>
    public const int MaxSceneFrames = 200_000;
}
