using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Dat.Tests.Parity;

/// <summary>
/// Every portal of the real Holtburg cells (shared/real-cells/scenes) has retail's portal_side on the scene path and
/// on the DAT path: <c>!(flags &amp; 2)</c> (CCellPortal::UnPack) of the flags in the retail cell dumps the scenes were
/// made from (shared/real-cells/source, "R other polygon flags" lines). The scenes' own portalSide is the opposite
/// convention (the owning cell in front of the polygon), which the scene loader turns round. Compiled only when the
/// shared folder is present.
/// </summary>
public class RealCellsPortalSideTests
{
    public static TheoryData<string> Scenes()
    {
        var data = new TheoryData<string>();
        if (SharedFolders.Find("real-cells") is { } dir)
            foreach (string file in Directory.GetFiles(Path.Combine(dir, "scenes"), "cottage*.json").OrderBy(f => f, StringComparer.Ordinal))
                data.Add(Path.GetFileName(file));
        return data;
    }

    [Theory]
    [MemberData(nameof(Scenes))]
    public void EveryPortal_HasTheDumpsRetailSide_OnBothPaths(string file)
    {
        string dir = SharedFolders.Find("real-cells")!;
        var scene = SceneLoader.LoadFile(Path.Combine(dir, "scenes", file));
        var dat = DatPath.Through(scene.World);
        int portals = 0;
        foreach (uint id in scene.World.Cells.CellIds.Where(id => (id & 0xFFFF) >= 0x0100))
        {
            var expected = DumpSides(Path.Combine(dir, "source", $"{id:X8}.txt"));
            foreach (var (path, world) in new[] { ("scene", scene.World), ("DAT", dat) })
            {
                var cell = Assert.IsType<EnvCell>(world.Cells.Get(id));
                // The scenes dropped portals to cells outside the set; every portal kept is in the dump.
                var actual = cell.Portals.ToArray().Select(p => (p.OtherCellId & 0xFFFF, p.PortalSide)).Order().ToList();
                Assert.NotEmpty(actual);
                foreach (var portal in actual)
                    Assert.True(expected.Contains(portal), $"{file} {path} path: cell 0x{id:X8} portal to 0x{portal.Item1:X4} side {portal.PortalSide}; the dump has {string.Join(", ", expected.Select(e => $"0x{e.Other:X4} {e.Side}"))}");
                portals += actual.Count;
            }
        }
        Assert.True(portals > 0);
    }

    private static List<(uint Other, bool Side)> DumpSides(string dump) =>
        File.ReadLines(dump).Where(l => l.StartsWith("R ", StringComparison.Ordinal)).Select(l =>
        {
            var f = l.Split(' ', StringSplitOptions.RemoveEmptyEntries);
            uint flags = uint.Parse(f[3], System.Globalization.CultureInfo.InvariantCulture);
            return (uint.Parse(f[1], System.Globalization.CultureInfo.InvariantCulture), (flags & 2) == 0);
        }).ToList();
}
