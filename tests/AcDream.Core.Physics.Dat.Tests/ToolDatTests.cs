using System.Globalization;
using AcDream.Core.Physics.Tool;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>The tool on DAT files: the dat summary, --dat worlds for run and query, and one-line refusals.</summary>
public class ToolDatTests
{
    private static (int Code, string Out, string Err) Tool(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void Dat_SummarisesALandblock()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        var (code, output, err) = Tool("dat", dats.Directory, "0x8040");
        Assert.Equal(0, code);
        Assert.Equal("", err);
        var lines = output.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal("landblock 0x8040: 64 land cells (terrain 0 to 4 m), 0 env cells (0 portals, 0 to outside), 0 buildings (0 entrance cells), 1 static object (1 model)", lines[0]);
        Assert.Equal("physics polygons: 0 in env cells, 0 in building shells, 0 in object parts; deepest physics BSP 0 (none)", lines[1]);
        Assert.Equal("hasObjects set: LandBlockInfo 0x8040FFFE read", lines[2]);
    }

    [Fact]
    public void Dat_SaysWhenTheFlagLeavesALandBlockInfoUnread()
    {
        using var dats = new TempDats([WorldWriter.Region(), WorldWriter.Post(0x02000001)],
            [WorldWriter.Land(0x8040), WorldWriter.Info(0x8040, 0, (0x02000001, new Vector3(96f, 100.9f, 0f))), WorldWriter.Land(0x8041)]);
        var (code, output, err) = Tool("dat", dats.Directory, "0x8040");
        Assert.True(code == 0, err);
        var lines = output.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.StartsWith("landblock 0x8040: 64 land cells (", lines[0]);
        Assert.EndsWith(", 0 static objects (0 models)", lines[0]);
        Assert.Equal("hasObjects clear: LandBlockInfo 0x8040FFFE in the file, not read (retail reads it only when the flag is set)", lines[2]);
        (code, output, err) = Tool("dat", dats.Directory, "0x8041");
        Assert.True(code == 0, err);
        Assert.Equal("hasObjects clear: no LandBlockInfo", output.Split('\n', StringSplitOptions.RemoveEmptyEntries)[2]);
    }

    [Fact]
    public void Dat_CountsTheCottagesCellsPortalsPolygonsAndDeepestTree_AsTheSceneHasThem()
    {
        // The cottage scene's world written as DAT files; the expected counts come from the scene's own world
        // (its env cells, portals, building, objects and their trees, walked node by node here).
        var world = Scenes.SceneLibrary.Load("cottage").World;
        using var dats = Support.DatPath.Write(Support.WorldDat.From(world));
        var cells = world.Cells.CellIds.Where(id => (id & 0xFFFF) >= 0x0100).Select(id => (EnvCell)world.Cells.Get(id)!).ToList();
        uint landblock = cells[0].Id >> 16;
        var records = world.Objects.Records.ToList();
        int portals = cells.Sum(c => c.Portals.Length), outside = cells.Sum(c => c.Portals.ToArray().Count(p => p.LeadsOutside));
        int cellPolygons = cells.Sum(c => c.PhysicsBsp?.Polygons.Length ?? 0);
        int objectPolygons = records.Sum(r => r.Setup!.Parts.Sum(p => p.Model?.Bsp.Polygons.Length ?? 0));
        int depth = cells.Select(c => Depth(c.PhysicsBsp)).Concat(records.SelectMany(r => r.Setup!.Parts.Select(p => Depth(p.Model?.Bsp)))).Max();
        var (code, output, err) = Tool("dat", dats.Directory, $"0x{landblock:X4}");
        Assert.True(code == 0, err);
        Assert.Contains($"{N(cells.Count, "env cell")} ({N(portals, "portal")}, {outside} to outside)", output);
        Assert.Contains($"{N(records.Count, "static object")} (", output);
        Assert.Contains($"physics polygons: {cellPolygons} in env cells, ", output);
        Assert.Contains($" in object parts; deepest physics BSP {depth} (", output);
        Assert.Contains($"{objectPolygons} in object parts", output);
        Assert.True(cellPolygons > 0 && depth > 1);
    }

    private static string N(int n, string noun) => $"{n} {noun}{(n == 1 ? "" : "s")}";

    private static int Depth(Bsp.BspTree? tree) => tree is null ? 0 : Depth(tree, 0);

    private static int Depth(Bsp.BspTree tree, int node) =>
        node < 0 ? 0 : 1 + Math.Max(Depth(tree, tree.Nodes[node].Front), Depth(tree, tree.Nodes[node].Back));

    [Fact]
    public void Dat_WithoutALandblock_ListsTheFiles()
    {
        using var dats = WorldWriter.Grid(0x80, 0x81, 0x40, 0x40);
        var (code, output, _) = Tool("dat", dats.Directory);
        Assert.Equal(0, code);
        Assert.Contains("2 landblocks: 0x8040 0x8140", output);
        Assert.StartsWith("client_portal.dat: ", output);
    }

    [Fact]
    public void Dat_Refusals_AreOneLineAndExit2()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        var (code, output, err) = Tool("dat", dats.Directory, "0x9999");
        Assert.Equal(2, code);
        Assert.Equal("", output);
        Assert.Equal("acdream-physics: client_cell_1.dat 0x9999FFFF: is absent (expected a LandBlock).", err.TrimEnd());
        File.Copy(dats.CellPath, dats.PortalPath, overwrite: true);
        (code, _, err) = Tool("dat", dats.Directory);
        Assert.Equal(2, code);
        Assert.Equal("acdream-physics: client_portal.dat: is a cell DAT file, expected a portal DAT file.", err.TrimEnd());
        Assert.Equal(2, Tool("dat", dats.Directory, "nothex").Code);
    }

    [Fact]
    public void QueryAndRun_TakeTheWorldFromTheDatFiles()
    {
        // The boulder scene's movers start in 0xA9B4; the DAT world there is rolling land with a post.
        using var dats = WorldWriter.Grid(0xA8, 0xAA, 0xB3, 0xB5);
        var (code, output, err) = Tool("query", "boulder", "floor", "96", "96", "50", "--dat", dats.Directory);
        Assert.True(code == 0, err);
        float expected = WorldWriter.TableHeight(WorldWriter.HeightIndex(0xA9B4, 4, 4));
        string z = output.Split(' ')[1];
        Assert.StartsWith("z=", z);
        Assert.Equal(expected, float.Parse(z[2..], CultureInfo.InvariantCulture), 4);
        Assert.NotEqual(0f, expected);                                  // the scene's own floor is at 0
        (code, output, err) = Tool("query", "boulder", "near", "96", "100.9", "1", "1", "--dat", dats.Directory);
        Assert.True(code == 0, err);
        Assert.Contains("0x7A9B4000", output);                         // the DAT's post, by its default id
        (code, _, err) = Tool("run", "boulder", "--dat", dats.Directory);
        Assert.True(code == 0, err);
    }

    [Fact]
    public void DatFlag_NamesALandblockTheFilesLack()
    {
        using var dats = WorldWriter.Grid(0x80, 0x80, 0x40, 0x40);
        var (code, _, err) = Tool("run", "boulder", "--dat", dats.Directory);
        Assert.Equal(2, code);
        Assert.Contains("client_cell_1.dat: mover north-centre starts in landblock 0xA9B4, which the file does not hold.", err);
    }
}
