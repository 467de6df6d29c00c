using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatEnvCell = DatReaderWriter.DBObjs.EnvCell;
using DatEnvironment = DatReaderWriter.DBObjs.Environment;
using DatFrame = DatReaderWriter.Types.Frame;
using DatSphere = DatReaderWriter.Types.Sphere;

namespace AcDream.Core.Physics.Dat.Tests.Conversions;

/// <summary>
/// Objects of the end-of-retail DATs, rebuilt from the values DatReaderWriter's own tests assert when they read
/// them (DatReaderWriter.Tests, SetupTests and EnvCellTests, release 2.1.4), written to DAT files, read back
/// and converted: our objects carry the same values where the runtime has them.
/// </summary>
public class RetailFactsTests
{
    /// <summary>Setup 0x02000108: one part (GfxObj 0x010008AB) at the identity default placement, one sphere, step heights 0.3612.</summary>
    [Fact]
    public void Setup0x02000108_KeepsItsSphereHeightsAndPart()
    {
        var setup = new Setup
        {
            Id = 0x02000108,
            Flags = SetupFlags.HasPhysicsBSP,
            Parts = [0x010008AB],
            Spheres = [new DatSphere { Origin = new Vector3(0, -0.1475f, 0.439f), Radius = 0.439f }],
            Height = 0.878f,
            Radius = 0.5269661f,
            StepUpHeight = 0.3612f,
            StepDownHeight = 0.3612f,
            SortingSphere = new DatSphere { Origin = new Vector3(0.000971317f, -0.0658602f, 0.439f), Radius = 0.520641f },
            SelectionSphere = new DatSphere { Origin = new Vector3(0f, 0f, 0.439f), Radius = 0.5269661f },
        };
        var placement = new AnimationFrame(1);
        placement.Frames.Add(new DatFrame { Origin = Vector3.Zero, Orientation = new Quaternion(0, 0, 0, 1) });
        setup.PlacementFrames.Add(Placement.Default, placement);
        // The part's geometry is not stated; a small box stands in for it.
        var part = DatObjects.GfxObj(0x010008AB, BspShapes.Box(new Vector3(-0.3f), new Vector3(0.3f)));
        using var files = WrittenDats.Write([setup, part], []);

        var read = files.Get<Setup>(files.Portal, 0x02000108);
        var result = DatSetups.ToPhysicsSetup(read, id => DatModels.ToPhysicsModel(files.Get<GfxObj>(files.Portal, id)));

        Assert.Equal([new Sphere(new Vector3(0, -0.1475f, 0.439f), 0.439f)], result.Spheres);
        Assert.Empty(result.CylSpheres);
        Assert.Equal((0.878f, 0.5269661f, 0.3612f, 0.3612f), (result.Height, result.Radius, result.StepUpHeight, result.StepDownHeight));
        var only = Assert.Single(result.Parts);
        Assert.NotNull(only.Model);
        Assert.Equal(Vector3.Zero, only.Frame.Origin);
        Assert.Equal(Quaternion.Identity, only.Frame.Orientation);
        Assert.Equal(1f, only.DefaultScale);
        Assert.True(result.HasPhysicsBsp);
    }

    /// <summary>
    /// EnvCell 0x7D64010D (SeenOutside, static objects; environment 0x03B2 structure 13): its position, its two
    /// portals (ExactMatch only, so retail's portal_side = !(flags &amp; 2) is true for both) to 0x105 and 0x109
    /// through polygons 13 and 12, and its first static objects.
    /// </summary>
    [Fact]
    public void EnvCell0x7D64010D_KeepsItsPositionPortalsAndStaticObjects()
    {
        var orientation = new Quaternion(0, 0, -0.707107f, 0.707107f);
        var cell = new DatEnvCell
        {
            Id = 0x7D64010D,
            Flags = EnvCellFlags.SeenOutside | EnvCellFlags.HasStaticObjs,
            EnvironmentId = 0x03B2,
            CellStructure = 13,
            Position = new DatFrame { Origin = new Vector3(85.5f, 109.5f, 12f), Orientation = orientation },
            CellPortals =
            [
                new DatReaderWriter.Types.CellPortal { Flags = PortalFlags.ExactMatch, PolygonId = 13, OtherCellId = 0x105, OtherPortalId = 1 },
                new DatReaderWriter.Types.CellPortal { Flags = PortalFlags.ExactMatch, PolygonId = 12, OtherCellId = 0x109, OtherPortalId = 0 },
            ],
            StaticObjects =
            [
                new Stab { Id = 0x0200033F, Frame = new DatFrame { Origin = new Vector3(77, 118, 12), Orientation = orientation } },
                new Stab { Id = 0x0200016D, Frame = new DatFrame { Origin = new Vector3(79.725f, 113.1f, 12), Orientation = orientation } },
                new Stab { Id = 0x0200036E, Frame = new DatFrame { Origin = new Vector3(80.5f, 118.4f, 12), Orientation = orientation } },
            ],
        };
        // The structure's geometry is not stated: a 4 m room whose polygons 12 and 13 are two of its walls.
        var room = BspShapes.Box(new Vector3(-2, -2, 0), new Vector3(2, 2, 3), PolygonSides.Single);
        var vertices = DatObjects.NewVertexArray();
        var structure = new CellStruct { VertexArray = vertices, CellBSP = DatObjects.CellTree(BspShapes.CellBox(new Vector3(-2, -2, 0), new Vector3(2, 2, 3))) };
        structure.PhysicsBSP = DatObjects.PhysicsTree(room, vertices, structure.PhysicsPolygons);
        structure.Polygons.Add(12, DatObjects.Polygon(room.PolygonArray[0], vertices));
        structure.Polygons.Add(13, DatObjects.Polygon(room.PolygonArray[1], vertices));
        var environment = new DatEnvironment { Id = 0x0D0003B2 };
        environment.Cells.Add(13, structure);
        using var files = WrittenDats.Write([environment], [cell]);

        var readCell = files.Get<DatEnvCell>(files.Cell, 0x7D64010D);
        var readEnvironment = files.Get<DatEnvironment>(files.Portal, DatCells.EnvironmentIdOf(readCell));
        var result = DatCells.ToEnvCell(readCell, DatCells.ToCellStructure(readEnvironment, readCell.CellStructure));

        Assert.Equal(0x0D0003B2u, DatCells.EnvironmentIdOf(readCell));
        Assert.Equal(0x7D64010Du, result.Id);
        Assert.Equal(new Vector3(85.5f, 109.5f, 12f), result.Position.Frame.Origin);
        Assert.Equal(orientation, result.Position.Frame.Orientation);
        Assert.Equal([0x7D640105u, 0x7D640109u], result.Portals.ToArray().Select(p => p.OtherCellId));
        Assert.All(result.Portals.ToArray(), p => Assert.True(p.PortalSide));
        Assert.Equal(room.PolygonArray[1].Vertices.ToArray(), result.Portals[0].Polygon.Vertices.ToArray());
        Assert.Equal(room.PolygonArray[0].Vertices.ToArray(), result.Portals[1].Polygon.Vertices.ToArray());
        Assert.True(DatCells.SeenOutside(readCell));
        var statics = DatCells.StaticObjects(readCell);
        Assert.Equal([0x0200033Fu, 0x0200016Du, 0x0200036Eu], statics.Select(s => s.ModelId));
        Assert.All(statics, s => Assert.Equal(0x7D64010Du, s.Position.CellId));
        Assert.Equal(new Vector3(79.725f, 113.1f, 12), statics[1].Position.Frame.Origin);
        Assert.Equal(orientation, statics[1].Position.Frame.Orientation);
    }

    /// <summary>Retail places a new object's parts by placement Resting (0x65) before Default (CPartArray::SetPlacementFrame).</summary>
    [Fact]
    public void ASetupsRestingPlacement_WinsOverItsDefault()
    {
        var setup = new Setup { Id = 0x02000001, Parts = [0x01000001], SortingSphere = new DatSphere(), SelectionSphere = new DatSphere() };
        var resting = new AnimationFrame(1);
        resting.Frames.Add(new DatFrame { Origin = new Vector3(0, 0, 2), Orientation = Quaternion.Identity });
        var standing = new AnimationFrame(1);
        standing.Frames.Add(new DatFrame { Origin = new Vector3(0, 0, 1), Orientation = Quaternion.Identity });
        setup.PlacementFrames.Add(Placement.Default, standing);
        setup.PlacementFrames.Add(Placement.Resting, resting);

        var result = DatSetups.ToPhysicsSetup(setup, _ => null);

        Assert.Equal(new Vector3(0, 0, 2), result.Parts[0].Frame.Origin);
        Assert.False(result.HasPhysicsBsp);
    }

    /// <summary>A part's default scale is its Z component (retail collides a part's BSP with it), when HasDefaultScale is set.</summary>
    [Fact]
    public void APartsDefaultScale_IsItsZ()
    {
        var setup = new Setup { Id = 0x02000002, Flags = SetupFlags.HasDefaultScale, Parts = [0x01000001], DefaultScale = [new Vector3(3, 4, 0.5f)], SortingSphere = new DatSphere(), SelectionSphere = new DatSphere() };
        using var files = WrittenDats.Write([setup], []);

        var result = DatSetups.ToPhysicsSetup(files.Get<Setup>(files.Portal, 0x02000002), _ => null);

        Assert.Equal(0.5f, result.Parts[0].DefaultScale);
        Assert.Equal(Frame.Identity.Origin, result.Parts[0].Frame.Origin);
    }

    /// <summary>
    /// Heights come from the Region's land height table by index, x * 9 + y, as in CLandBlockStruct; the terrain
    /// words go to the terrain as stored, and their types make water (here vertex (0, 0), type 0x10: the cell at
    /// its corner is partly water, the landblock too).
    /// </summary>
    [Fact]
    public void ALandBlocksHeights_AreTheTablesEntries_AndItsTerrainWordsAreKept()
    {
        var block = new LandBlock { Id = 0xA9B4FFFF };
        for (int i = 0; i < 81; i++)
        {
            block.Height[i] = (byte)(i == 10 ? 200 : i % 3);
            // Road bits 1, type 3, scenery 5; vertex 0 water (type 0x10).
            block.Terrain[i] = (ushort)(i == 0 ? 0x10 << 2 : (5 << 11) | (3 << 2) | 1);
        }
        var table = new float[256];
        for (int i = 0; i < 256; i++)
            table[i] = i * 2f;
        using var files = WrittenDats.Write([], [block]);

        var terrain = DatTerrain.ToTerrain(files.Get<LandBlock>(files.Cell, 0xA9B4FFFF), new DatReaderWriter.Types.LandDefs { LandHeightTable = table });

        Assert.Equal(0xA9B4u, terrain.Landblock);
        Assert.Equal(400f, terrain.HeightAt(1, 1));
        Assert.Equal(2f, terrain.HeightAt(0, 1));
        Assert.Equal(4f, terrain.HeightAt(8, 8));
        Assert.Equal((ushort)((5 << 11) | (3 << 2) | 1), terrain.TerrainWordAt(4, 7));
        Assert.True(terrain.IsWaterAt(0, 0));
        Assert.Equal(World.WaterType.PartiallyWater, terrain.CellWaterType(0, 0));
        Assert.Equal(World.WaterType.NotWater, terrain.CellWaterType(1, 1));
        Assert.Equal(World.WaterType.PartiallyWater, terrain.WaterType);
    }
}
