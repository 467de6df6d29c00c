using System.IO;
using System.Text;
using System.Threading;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Tests.Robustness;

/// <summary>
/// Recursion cannot exhaust a thread's stack: BSP trees deeper than <see cref="InputLimits.MaxBspDepth"/>
/// are refused where they are made (code, compiler, scene files), and every recursive query over the
/// deepest accepted tree runs on a thread with a 256 KB stack.
/// </summary>
public class StackDepthTests
{
    private const int SmallStack = 256 * 1024;

    /// <summary>
    /// The deepest tree Create accepts, shaped so that every query walks all of it: a chain of split planes
    /// that all pass through the vertical line x = 1, y = 0 (normals turning around it), each with one
    /// front child, ending in a leaf that holds a wall quad at x = 1. A sphere near the line straddles every
    /// split, so each query descends the whole chain to the wall.
    /// </summary>
    private static BspTree DeepestTree()
    {
        var wall = new Polygon([new Vector3(1, -1, 0), new Vector3(1, 1, 0), new Vector3(1, 1, 2), new Vector3(1, -1, 2)]);
        int depth = InputLimits.MaxBspDepth;
        var nodes = new BspNodeData[depth];
        for (int i = 0; i < depth - 1; i++)
        {
            float angle = 0.3f + i * 0.001f;
            var normal = new Vector3(MathF.Cos(angle), MathF.Sin(angle), 0f);
            nodes[i] = new BspNodeData { SplitPlane = new Plane(normal, -Vector3.Dot(normal, new Vector3(1f, 0, 0))), Front = i + 1, Back = -1 };
        }
        nodes[depth - 1] = new BspNodeData { IsLeaf = true, Polygons = [0] };
        return BspTree.Create([wall], nodes, "deep");
    }

    private static void OnSmallStack(Action action)
    {
        Exception? failure = null;
        var thread = new Thread(() =>
        {
            try { action(); }
            catch (Exception e) { failure = e; }
        }, SmallStack);
        thread.Start();
        thread.Join();
        if (failure is not null)
            throw new Xunit.Sdk.XunitException("the query failed on the 256 KB thread: " + failure);
    }

    [Fact]
    public void EveryRecursiveBspQuery_OverTheDeepestAcceptedTree_RunsOnA256KBThread()
    {
        var tree = DeepestTree();
        Assert.Equal(InputLimits.MaxBspDepth, tree.Nodes.Length);
        // Moving into the wall's front (+X) face: centre 0.3 m from it, within the sphere's reach of every split.
        var sphere = new Sphere(new Vector3(1.3f, 0, 1), 0.48f);
        var movement = new Vector3(-0.2f, 0, 0);
        bool polyHit = false, solidHit = false, solidPolyHit = false, walkable = true, changed = false;
        Polygon? hitPoly = null, solidPoly = null, found = null;
        OnSmallStack(() =>
        {
            var contact = Vector3.Zero;
            polyHit = BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere, movement, ref hitPoly, ref contact);
            solidHit = BspNodeQuery.SphereIntersectsSolid(tree, 0, sphere, centerCheck: true);
            bool centerSolid = false;
            solidPolyHit = BspNodeQuery.SphereIntersectsSolidPoly(tree, 0, sphere, sphere.Radius, ref centerSolid, ref solidPoly, centerCheck: true);
            walkable = BspNodeQuery.HitsWalkable(tree, 0, sphere, Vector3.UnitX, 0.5f);
            var valid = sphere;
            float interp = 1f;
            BspNodeQuery.FindWalkable(tree, 0, ref valid, ref found, movement, Vector3.UnitX, 0.5f, ref interp, ref changed);
        });
        // Each query reached the wall at the bottom of the chain.
        Assert.True(polyHit, "sphere_intersects_poly did not reach the wall");
        Assert.Same(tree.Polygons[0], hitPoly);
        Assert.True(solidHit, "sphere_intersects_solid did not reach the wall");
        // (Straddled splits return the centre-solid flag, false here; the polygon found is what shows the depth.)
        Assert.False(solidPolyHit);
        Assert.Same(tree.Polygons[0], solidPoly);
        Assert.True(walkable, "hits_walkable (the wall is ground for up = +X) did not reach the wall");
        Assert.True(changed, "find_walkable did not reach the wall");
        Assert.Same(tree.Polygons[0], found);
    }

    [Fact]
    public void AMoverWalkingIntoAnObjectWithTheDeepestAcceptedTree_ResolvesOnA256KBThread()
    {
        var world = TestGeometry.FlatWorld();
        var model = new PhysicsModel(DeepestTree());
        var setup = new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] };
        world.Objects.Register(0x70000001, setup, TestGeometry.At(100, 100, 0), 1f, PhysicsState.None);
        var player = MoverDescription.Player();
        var state = MoverState.OnFloor(TestGeometry.At(102.5f, 100, 0), 0f);
        bool hit = false;
        OnSmallStack(() =>
        {
            var engine = new PhysicsEngine(world);
            for (int frame = 0; frame < 15; frame++)
            {
                var target = state.Position;
                target.Frame.Origin.X -= 0.1f;
                var result = engine.Resolve(player, state, target);
                hit |= result.CollidedObjects.Span.Contains(0x70000001u);
                state = result.Next;
            }
        });
        // The wall's front at x = 101 stops the 0.48 m spheres at about x = 101.48.
        Assert.True(hit, "the mover never hit the wall at the bottom of the deep tree");
        Assert.InRange(state.Position.Origin.X, 101.47f, 101.6f);
    }

    [Fact]
    public void Create_RefusesATreeOneLevelDeeperThanTheLimit_NamingTheNode()
    {
        var quad = BspShapes.FloorPolygon(Vector3.Zero, new Vector2(2, 2));
        BspTree.Create([quad], BadInputTests.Chain(InputLimits.MaxBspDepth), "gfx");
        var e = Assert.Throws<ArgumentException>(() => BspTree.Create([quad], BadInputTests.Chain(InputLimits.MaxBspDepth + 1), "gfx"));
        Assert.Contains($"gfx.nodes[{InputLimits.MaxBspDepth}]", e.Message);
        Assert.Contains("MaxBspDepth", e.Message);
    }

    [Fact]
    public void Create_RefusesAFiftyThousandNodeChain_WithoutRecursing()
    {
        var quad = BspShapes.FloorPolygon(Vector3.Zero, new Vector2(2, 2));
        var e = Assert.Throws<ArgumentException>(() => BspTree.Create([quad], BadInputTests.Chain(50_000), "gfx"));
        Assert.Contains("deeper than", e.Message);
    }

    /// <summary>A convex prism with <paramref name="sides"/> side faces, a top and a bottom, outward faces.</summary>
    internal static Polygon[] Prism(int sides)
    {
        var faces = new List<Polygon>();
        var top = new Vector3[sides];
        var bottom = new Vector3[sides];
        for (int i = 0; i < sides; i++)
        {
            double a = 2 * Math.PI * i / sides;
            var p = new Vector3(10 * (float)Math.Cos(a), 10 * (float)Math.Sin(a), 0f);
            bottom[sides - 1 - i] = p;
            top[i] = p + new Vector3(0, 0, 1);
        }
        // Faces of more than 127 vertices are not allowed: cap with triangles fanned from the centre.
        for (int i = 0; i < sides; i++)
        {
            int j = (i + 1) % sides;
            var a = top[i] - Vector3.UnitZ;
            var b = top[j] - Vector3.UnitZ;
            faces.Add(new Polygon([a, b, b + Vector3.UnitZ, a + Vector3.UnitZ]));
            faces.Add(new Polygon([new Vector3(0, 0, 1), top[i], top[j]]));
            faces.Add(new Polygon([Vector3.Zero, b, a]));
        }
        return faces.ToArray();
    }

    [Fact]
    public void Compile_RefusesAConvexSolidWithMorePlanesThanTheDepthLimit()
    {
        // One level per distinct face plane: 520 sides + 520 top and 520 bottom triangles sharing two planes.
        var e = Assert.Throws<ArgumentException>(() => BspCompiler.Compile(Prism(InputLimits.MaxBspDepth + 8), "gfx"));
        Assert.StartsWith("gfx: the compiled BSP tree would be deeper than", e.Message);
    }

    [Fact]
    public void Compile_OfAConvexSolidJustWithinTheDepthLimit_RunsOnA256KBThread()
    {
        // 250 sides, a top and a bottom: 252 distinct planes, one level each, then the solid leaf.
        var prism = AcDream.Core.Physics.Bench.Compile.CompileMeshes.Prism(InputLimits.MaxBspDepth - 6);
        BspTree? tree = null;
        OnSmallStack(() => tree = BspCompiler.Compile(prism, "prism"));
        int depth = 0;
        for (int i = 0; i >= 0; i = tree!.Nodes[i].IsLeaf ? -1 : tree.Nodes[i].Back)
            depth++;
        Assert.Equal(InputLimits.MaxBspDepth - 3, depth);
    }

    [Fact]
    public void SceneFile_WithATreeDeeperThanTheLimit_IsRefusedNamingTheModel()
    {
        var json = new StringBuilder();
        json.Append("""{"version":1,"models":{"deep":{"polygons":[{"vertices":[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],"nodes":[""");
        int depth = InputLimits.MaxBspDepth + 1;
        for (int i = 0; i < depth - 1; i++)
            json.Append($$"""{"splitPlane":{"normal":[0,0,1],"d":0},"front":{{i + 1}}},""");
        json.Append("""{"leaf":true,"polygons":[0]}]}},"landblocks":[{"id":"0xA9B4","height":0}],"movers":[]}""");
        var e = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(json.ToString()));
        Assert.StartsWith("models.deep", e.Message);
        Assert.Contains("deeper than", e.Message);
    }

    [Fact]
    public void SceneFile_NestedDeeperThan64_IsRefusedAsBadJson()
    {
        string json = new string('[', 10_000) + new string(']', 10_000);
        var e = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(json));
        Assert.StartsWith("invalid JSON", e.Message);
        Assert.Contains("depth", e.Message);
    }

    /// <summary>The shared data folder: a sibling named "shared" of the repository or of one of its parents; null when absent.</summary>
    internal static string? SharedFolder()
    {
        var dir = new DirectoryInfo(BadInputTests.RepoRoot());
        for (; dir?.Parent is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.Parent.FullName, "shared");
            if (Directory.Exists(Path.Combine(candidate, "real-cells")))
                return candidate;
        }
        return null;
    }

    [Fact]
    public void RealRetailCells_PassThePolygonChecks_AndTheirStatesLieNearTheirCells()
    {
        string? shared = SharedFolder();
        if (shared is null)
            return; // the shared data is not on this machine (CI without it): nothing to check
        var files = Directory.GetFiles(Path.Combine(shared, "real-cells", "scenes"), "*.json");
        Assert.NotEmpty(files);
        foreach (string file in files)
        {
            var scene = SceneLoader.LoadFile(file);
            // Every recorded start state lies near its cell (InputLimits.MaxDistanceFromCell): no mover is refused.
            var trajectory = SceneRunner.Run(scene);
            Assert.Equal(scene.Movers.Count, trajectory.Movers.Count);
        }
    }
}
