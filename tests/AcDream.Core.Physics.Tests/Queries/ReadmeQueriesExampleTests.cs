using System.IO;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>The README's "World queries" example, kept compiling and checked for what its comments say.</summary>
public class ReadmeQueriesExampleTests
{
    [Fact]
    public void TheReadmeExample_RunsAndSaysWhatItsCommentsSay()
    {
        var output = new StringWriter();
        var saved = Console.Out;
        Console.SetOut(output);
        try
        {
            // --- README "World queries" (keep in step) ---
            var world = SceneLibrary.Load("cottage").World;             // a room behind a doorway, the door in it
            var query = new WorldQuery(world);                           // one per thread
            var outside = new Position(0xA9B40025, new Vector3(100, 97, 1));

            if (query.TryFindFloor(outside, maxDrop: 10f, out var floor))          // terrain, indoor floors, object tops
                Console.WriteLine($"floor z={floor.Point.Z} {floor.Kind} 0x{floor.CellId:X8}");
            if (query.TryFindCell(new Position(0xA9B40025, new Vector3(100, 102, 1)), out var cell))
                Console.WriteLine($"cell 0x{cell.CellId:X8}");                     // 0xA9B40100: the room, through the building
            if (query.SphereCast(outside, new Vector3(100, 103, 1), 0.3f, out var hit))
                Console.WriteLine($"{hit.Kind} 0x{hit.ObjectId:X8} at {hit.Point}, normal {hit.Normal}");   // the door's front face
            if (query.RayCast(outside, new Vector3(100, 103, 1), out var picked, QueryLayers.All))         // picking, ethereal too
                Console.WriteLine($"picked 0x{picked.ObjectId:X8}");

            Span<ObjectOverlap> near = stackalloc ObjectOverlap[16];
            int count = query.OverlapSphere(outside, 5f, near);                    // ids and the shape that overlapped
            for (int i = 0; i < count; i++)
                Console.WriteLine(near[i]);

            var arm = query.CameraArm(pivot: new Position(0xA9B40100, new Vector3(100, 101, 1.5f)),
                                      desired: new Vector3(100, 106, 1.5f), playerId: 0x50000001);
            Console.WriteLine($"camera at {arm.Camera} ({arm.Placement}, blocked: {arm.Blocked})");   // short of the north wall
            // --- end ---
        }
        finally
        {
            Console.SetOut(saved);
        }
        var lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal("floor z=0 Terrain 0xA9B40025", lines[0]);
        Assert.Equal("cell 0xA9B40100", lines[1]);
        Assert.StartsWith("Object 0x70000001 at <100", lines[2]);
        Assert.Equal("picked 0x70000001", lines[3]);
        Assert.StartsWith("0x70000001 Bsp[0]", lines[4]);
        Assert.StartsWith("camera at 0xA9B40100 <100", lines[5]);
        Assert.EndsWith("(Swept, blocked: True)", lines[5].TrimEnd());
    }
}
