using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Dat.Tests.Parity;

/// <summary>
/// The DAT path rebuilds a scene's geometry to the bit: every env cell's physics tree and every object part's
/// tree node for node (planes, spheres, children, leaf flags, polygon order, vertices, sides), every object at
/// the same position bits with the same setup shapes. The containment trees keep their planes and shape but not
/// their spheres, which a DAT CellBSP does not store (a cell is bounded by its physics tree's sphere). Every land
/// cell has the same triangles and water type.
/// </summary>
public class ScenesTreesThroughDatTests
{
    public static TheoryData<string> BuiltInScenes()
    {
        var data = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(BuiltInScenes))]
    public void EveryTreeAndObject_IsTheSceneOne(string name)
    {
        var scene = SceneLibrary.Load(name);
        var dat = DatPath.Through(scene.World, SceneLibrary.ReadText(name));
        Assert.Equal(scene.World.Cells.CellIds.OrderBy(i => i), dat.Cells.CellIds.OrderBy(i => i));
        foreach (uint id in scene.World.Cells.CellIds)
            if (scene.World.Cells.Get(id) is EnvCell e)
            {
                var d = Assert.IsType<EnvCell>(dat.Cells.Get(id));
                TreeAssert.Same(e.PhysicsBsp!, d.PhysicsBsp!, $"0x{id:X8}.physics");
                TreeAssert.Same(e.CellBsp, d.CellBsp, $"0x{id:X8}.cell", bounds: false);
                Assert.True(Position.SameBits(e.Position, d.Position), $"0x{id:X8}.position");
                Assert.Equal(e.Portals.Length, d.Portals.Length);
                for (int p = 0; p < e.Portals.Length; p++)
                {
                    Assert.Equal(e.Portals[p].OtherCellId, d.Portals[p].OtherCellId);
                    Assert.Equal(e.Portals[p].PortalSide, d.Portals[p].PortalSide);
                    Assert.True(e.Portals[p].Polygon.Vertices.SequenceEqual(d.Portals[p].Polygon.Vertices), $"0x{id:X8}.portals[{p}].polygon");
                }
            }
            else if (scene.World.Cells.Get(id) is LandCell land)
            {
                var datLand = Assert.IsType<LandCell>(dat.Cells.Get(id));
                Assert.Equal(land.WaterType, datLand.WaterType);
                Assert.Equal(land.Triangles.First.Vertices.ToArray(), datLand.Triangles.First.Vertices.ToArray());
                Assert.Equal(land.Triangles.Second.Vertices.ToArray(), datLand.Triangles.Second.Vertices.ToArray());
                if (land.Building is not { } building)
                    continue;
                var other = datLand.Building!;
                TreeAssert.Same(building.Shell.Bsp, other.Shell.Bsp, $"0x{id:X8}.building");
                Assert.True(Position.SameBits(building.Position, other.Position), $"0x{id:X8}.building.position");
                Assert.Equal(building.EntranceCells.ToArray(), other.EntranceCells.ToArray());
            }
        var datRecords = dat.Objects.Records.ToDictionary(r => r.Id);
        Assert.Equal(scene.World.Objects.Count, dat.Objects.Count);
        foreach (var r in scene.World.Objects.Records)
        {
            var d = datRecords[r.Id];
            Assert.True(Position.SameBits(r.Position, d.Position), $"object 0x{r.Id:X8}.position");
            Assert.Equal((r.Scale, r.State, r.Flags), (d.Scale, d.State, d.Flags));
            Assert.Equal(r.Setup!.Spheres, d.Setup!.Spheres);
            Assert.Equal(r.Setup.CylSpheres, d.Setup.CylSpheres);
            Assert.Equal((r.Setup.Height, r.Setup.Radius, r.Setup.StepUpHeight, r.Setup.StepDownHeight), (d.Setup.Height, d.Setup.Radius, d.Setup.StepUpHeight, d.Setup.StepDownHeight));
            Assert.Equal(r.Setup.Parts.Count, d.Setup.Parts.Count);
            for (int i = 0; i < r.Setup.Parts.Count; i++)
            {
                Assert.Equal((r.Setup.Parts[i].Frame.Origin, r.Setup.Parts[i].Frame.Orientation, r.Setup.Parts[i].DefaultScale), (d.Setup.Parts[i].Frame.Origin, d.Setup.Parts[i].Frame.Orientation, d.Setup.Parts[i].DefaultScale));
                Assert.Equal(r.Setup.Parts[i].Model is null, d.Setup.Parts[i].Model is null);
                if (r.Setup.Parts[i].Model is { } m)
                    TreeAssert.Same(m.Bsp, d.Setup.Parts[i].Model!.Bsp, $"object 0x{r.Id:X8}.parts[{i}]");
            }
        }
    }
}
