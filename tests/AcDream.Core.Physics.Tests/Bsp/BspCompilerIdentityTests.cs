using AcDream.Core.Physics.Bench.Compile;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Bsp;

/// <summary>
/// The compiler's output is pinned bit for bit: every node (leaf flag, solid flag, split plane, bounds,
/// children, polygon indices) and every output polygon (vertices, sidedness) is hashed, per input, and
/// compared with hashes recorded before the compiler was made faster. A change of tree shape changes
/// collision results, so any difference here is a behaviour change.
/// </summary>
public class BspCompilerIdentityTests
{
    /// <summary>Input name → FNV-1a hash of the compiled tree, recorded with the original (cubic) compiler.</summary>
    private static readonly Dictionary<string, ulong> Recorded = new()
    {
        ["soup-60"] = 0x7D2B8FE75C5221ABUL,
        ["soup-150"] = 0xF13DF926CDD68346UL,
        ["soup-400"] = 0x41FA69863521F78DUL,
        ["prism-12"] = 0x1FB49B82C86C7010UL,
        ["prism-40"] = 0x7D9176665D39BE94UL,
        ["heightfield-6"] = 0x25FAF088B9926363UL,
        ["heightfield-12"] = 0x4C4A40C8E50146B2UL,
        ["box"] = 0x075D74F4FE58E992UL,
        ["two-boxes"] = 0x4D4169B4AB12DDB8UL,
    };

    private static Polygon[] Input(string name) => name switch
    {
        "soup-60" => CompileMeshes.Soup(60, 7),
        "soup-150" => CompileMeshes.Soup(150, 8),
        "soup-400" => CompileMeshes.Soup(400, 9),
        "prism-12" => CompileMeshes.Prism(12),
        "prism-40" => CompileMeshes.Prism(40),
        "heightfield-6" => CompileMeshes.HeightField(6, 3),
        "heightfield-12" => CompileMeshes.HeightField(12, 4),
        "box" => TestGeometry.BoxFaces(new Vector3(-1, -2, 0), new Vector3(1, 2, 3)),
        "two-boxes" => [.. TestGeometry.BoxFaces(new Vector3(-1, -1, 0), new Vector3(1, 1, 2)), .. TestGeometry.BoxFaces(new Vector3(0.5f, 0.5f, 1), new Vector3(3, 2, 4))],
        _ => throw new ArgumentException(name),
    };

    public static TheoryData<string> Inputs()
    {
        var data = new TheoryData<string>();
        foreach (var name in Recorded.Keys)
            data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(Inputs))]
    public void CompiledTree_IsBitIdenticalToTheRecording(string name)
    {
        var tree = BspCompiler.Compile(Input(name), name);
        ulong hash = Hash(tree);
        Assert.True(Recorded[name] == hash, $"{name}: compiled tree hash 0x{hash:X16}, recorded 0x{Recorded[name]:X16} ({tree.Nodes.Length} nodes, {tree.Polygons.Length} polygons)");
    }

    private static ulong Hash(BspTree tree)
    {
        ulong h = 14695981039346656037UL;
        void Add(uint v)
        {
            for (int i = 0; i < 4; i++)
            {
                h ^= (byte)(v >> (8 * i));
                h *= 1099511628211UL;
            }
        }
        void F(float v) => Add(BitConverter.SingleToUInt32Bits(v));
        void V(Vector3 v) { F(v.X); F(v.Y); F(v.Z); }
        foreach (var node in tree.Nodes)
        {
            Add(node.IsLeaf ? 1u : 0u);
            Add(node.Solid ? 1u : 0u);
            V(node.SplitPlane.Normal);
            F(node.SplitPlane.D);
            V(node.Bounds.Center);
            F(node.Bounds.Radius);
            Add((uint)node.Front);
            Add((uint)node.Back);
            Add((uint)node.PolygonCount);
            for (int k = 0; k < node.PolygonCount; k++)
                Add((uint)tree.PolygonIndices[node.FirstPolygon + k]);
        }
        foreach (var polygon in tree.Polygons)
        {
            Add((uint)polygon.Sides);
            Add((uint)polygon.VertexCount);
            foreach (var v in polygon.Vertices)
                V(v);
        }
        return h;
    }
}
