using AcDream.Core.Physics.Bsp;
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

/// <summary>Damaged or hostile DAT objects are refused with a <see cref="DatObjectException"/> naming the object and the field; nothing is built from them.</summary>
public class BadInputTests
{
    private const uint Gfx = 0x0100_0020;

    /// <summary>A GfxObj holding a unit box as one leaf (six polygons, ids 0..5).</summary>
    private static GfxObj Box() => DatObjects.GfxObj(Gfx, BspTree.Create(BspShapes.BoxPolygons(Vector3.Zero, Vector3.One),
        [new BspNodeData { IsLeaf = true, Polygons = [0, 1, 2, 3, 4, 5] }], "unit box"));

    private static DatObjectException Refused(Action convert, uint id, params string[] words)
    {
        var ex = Assert.Throws<DatObjectException>(convert);
        Assert.Equal(id, ex.ObjectId);
        Assert.Contains($"0x{id:X8}", ex.Message);
        foreach (string word in words)
            Assert.Contains(word, ex.Message);
        return ex;
    }

    private static PhysicsBSPNode Internal(PhysicsBSPNode? front, PhysicsBSPNode? back) => new()
    {
        Type = DatObjects.InternalType(front is not null, back is not null),
        SplittingPlane = new Plane(Vector3.UnitZ, -0.5f),
        PosNode = front,
        NegNode = back,
        BoundingSphere = new DatSphere { Origin = new Vector3(0.5f), Radius = 1f },
    };

    [Fact]
    public void ACyclicTree_IsRefused()
    {
        var gfx = Box();
        var leaf = gfx.PhysicsBSP.Root!;
        var root = Internal(leaf, null);
        var middle = Internal(root, null);
        root.NegNode = middle;
        root.Type = BSPNodeType.BPIN;
        gfx.PhysicsBSP.Root = root;
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "GfxObj", "physicsBSP", "reached twice");
    }

    [Fact]
    public void ASharedSubtree_IsRefused()
    {
        var gfx = Box();
        var leaf = gfx.PhysicsBSP.Root!;
        gfx.PhysicsBSP.Root = Internal(leaf, leaf);
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "physicsBSP.nodes[2]", "reached twice");
    }

    [Fact]
    public void ATreeDeeperThanTheRuntimeTakes_IsRefused()
    {
        var gfx = Box();
        var node = gfx.PhysicsBSP.Root!;
        for (int i = 0; i < 300; i++)
            node = Internal(node, null);
        gfx.PhysicsBSP.Root = node;
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "deeper than 256", "MaxBspDepth");
    }

    [Fact]
    public void ALeafNamingAnAbsentPolygon_IsRefused()
    {
        var gfx = Box();
        gfx.PhysicsBSP.Root!.Polygons.Add(77);
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "physicsBSP.nodes[0].polygons[6]", "polygon 77");
    }

    [Fact]
    public void APolygonWithAnAbsentVertex_IsRefused()
    {
        var gfx = Box();
        gfx.PhysicsPolygons[3].VertexIds[1] = 999;
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "physicsBSP.polygons[3].vertexIds[1]", "vertex 999");
    }

    [Fact]
    public void APolygonOurPolygonRejects_IsRefused_NamingIt()
    {
        var gfx = Box();
        // Two vertices.
        gfx.PhysicsPolygons[2].VertexIds.RemoveAt(0);
        gfx.PhysicsPolygons[2].VertexIds.RemoveAt(0);
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "physicsBSP.polygons[2]", "3 to 127");
        // Not planar: one vertex lifted off its face.
        var bent = Box();
        ushort lifted = (ushort)bent.PhysicsPolygons[4].VertexIds[2];
        bent.VertexArray.Vertices[lifted].Origin += new Vector3(0.3f, -0.2f, 0.25f);
        var ex = Refused(() => DatModels.ToPhysicsModel(bent), Gfx, "physicsBSP.polygons[4]");
        Assert.IsType<ArgumentException>(ex.InnerException);
    }

    [Fact]
    public void APortalNodeInAPhysicsTree_AndATreeWithoutRoot_AreRefused()
    {
        var gfx = Box();
        gfx.PhysicsBSP.Root = Internal(gfx.PhysicsBSP.Root, null);
        gfx.PhysicsBSP.Root.Type = BSPNodeType.Portal;
        Refused(() => DatModels.ToPhysicsModel(gfx), Gfx, "portal node");
        Refused(() => DatGeometry.ToCellBsp(0x0D000001, "cells[0].cellBSP", new CellBSPTree()), 0x0D000001, "Environment", "no root");
    }

    [Fact]
    public void ABrokenSplitPlaneOrSphere_IsRefused_NamingTheNode()
    {
        var flat = Box();
        flat.PhysicsBSP.Root = Internal(flat.PhysicsBSP.Root, null);
        flat.PhysicsBSP.Root.SplittingPlane = new Plane(Vector3.Zero, 0f);
        Refused(() => DatModels.ToPhysicsModel(flat), Gfx, "physicsBSP: ", "nodes[0].splitPlane.normal", "zero length");

        var far = Box();
        far.PhysicsBSP.Root = Internal(far.PhysicsBSP.Root, null);
        far.PhysicsBSP.Root.SplittingPlane = new Plane(Vector3.UnitZ, float.NaN);
        Refused(() => DatModels.ToPhysicsModel(far), Gfx, "nodes[0].splitPlane.d");

        var shrunk = Box();
        shrunk.PhysicsBSP.Root!.BoundingSphere = new DatSphere { Origin = Vector3.Zero, Radius = -1f };
        Refused(() => DatModels.ToPhysicsModel(shrunk), Gfx, "nodes[0].bounds.radius", "zero or more");

        var lost = Box();
        lost.PhysicsBSP.Root!.BoundingSphere = new DatSphere { Origin = new Vector3(float.PositiveInfinity, 0, 0), Radius = 1f };
        Refused(() => DatModels.ToPhysicsModel(lost), Gfx, "nodes[0].bounds.center");

        var cellTree = DatObjects.CellTree(BspShapes.CellBox(Vector3.Zero, Vector3.One));
        cellTree.Root!.SplittingPlane = new Plane(new Vector3(float.NaN, 0, 1), 0f);
        Refused(() => DatGeometry.ToCellBsp(0x0D000001, "cells[0].cellBSP", cellTree), 0x0D000001, "cells[0].cellBSP: ", "nodes[0].splitPlane.normal");
    }

    [Fact]
    public void ASetupWhosePlacementDoesNotMatchItsParts_IsRefused()
    {
        var setup = new Setup { Id = 0x02000050, Parts = [Gfx, Gfx] };
        var frames = new AnimationFrame(1);
        frames.Frames.Add(new DatFrame { Origin = Vector3.Zero, Orientation = Quaternion.Identity });
        setup.PlacementFrames.Add(Placement.Default, frames);
        Refused(() => DatSetups.ToPhysicsSetup(setup, _ => null), 0x02000050, "Setup", "placementFrames", "1 frames for 2 parts");
        var scaled = new Setup { Id = 0x02000051, Flags = SetupFlags.HasDefaultScale, Parts = [Gfx] };
        Refused(() => DatSetups.ToPhysicsSetup(scaled, _ => null), 0x02000051, "defaultScale");
        var huge = new Setup { Id = 0x02000052, Parts = Enumerable.Repeat<QualifiedDataId<GfxObj>>(Gfx, 300).ToList() };
        Refused(() => DatSetups.ToPhysicsSetup(huge, _ => null), 0x02000052, "at most 256 parts");
        var negative = new Setup { Id = 0x02000053, StepUpHeight = float.NaN };
        Refused(() => DatSetups.ToPhysicsSetup(negative, _ => null), 0x02000053, "stepUpHeight");
    }

    [Fact]
    public void CellsAndLandblocksNamingWhatIsNotThere_AreRefused()
    {
        var environment = new DatEnvironment { Id = 0x0D000007 };
        Refused(() => DatCells.ToCellStructure(environment, 3), 0x0D000007, "no cell structure 3");

        var vertices = DatObjects.NewVertexArray();
        var structure = new CellStruct { VertexArray = vertices, CellBSP = DatObjects.CellTree(BspShapes.CellBox(Vector3.Zero, Vector3.One)) };
        structure.PhysicsBSP = DatObjects.PhysicsTree(BspShapes.Box(Vector3.Zero, Vector3.One), vertices, structure.PhysicsPolygons);
        environment.Cells.Add(0, structure);
        var converted = DatCells.ToCellStructure(environment, 0);
        var cell = new DatEnvCell
        {
            Id = 0xA9B40100,
            EnvironmentId = 7,
            Position = new DatFrame { Origin = new Vector3(10, 10, 0), Orientation = Quaternion.Identity },
            CellPortals = [new DatReaderWriter.Types.CellPortal { PolygonId = 9, OtherCellId = 0xFFFF }],
        };
        Refused(() => DatCells.ToEnvCell(cell, converted), 0xA9B40100, "EnvCell", "cellPortals[0].polygonId", "polygon 9");
        cell.EnvironmentId = 8;
        Refused(() => DatCells.ToEnvCell(cell, converted), 0xA9B40100, "environment 0x0D000008");

        var block = new LandBlock { Id = 0xA9B4FFFE };
        Refused(() => DatTerrain.ToTerrain(block, new DatReaderWriter.Types.LandDefs { LandHeightTable = new float[256] }), 0xA9B4FFFE, "0xXXYYFFFF");
        var outside = new LandBlock { Id = 0xFFB4FFFF };
        Refused(() => DatTerrain.ToTerrain(outside, new DatReaderWriter.Types.LandDefs { LandHeightTable = new float[256] }), 0xFFB4FFFF, "LandBlock");

        var info = new LandBlockInfo { Id = 0xA9B4FFFE };
        var shell = DatModels.ToPhysicsModel(Box())!;
        Refused(() => DatLandblocks.ToBuilding(info, 0, shell), 0xA9B4FFFE, "LandBlockInfo", "buildings[0]", "0 buildings");
    }

    /// <summary>
    /// A static object's frame the world would refuse when it is registered (the fuzz of damaged objects found
    /// these reaching the world, whose message named the object's game id, not the DAT object): refused where it
    /// is read, naming the LandBlockInfo or env cell and the field.
    /// </summary>
    [Fact]
    public void APlacementFrameTheWorldRefuses_IsRefusedNamingTheObjectAndField()
    {
        var info = WorldWriter.Info(0xA9B4, 0, (0x02000001, new Vector3(30, 30, 0)), (0x02000001, new Vector3(40, 40, 0)));
        info.Objects[1].Frame.Orientation = new Quaternion(float.NaN, 0, 0, 1);
        Refused(() => DatLandblocks.Objects(info), 0xA9B4FFFE, "LandBlockInfo", "objects[1].frame.orientation", "finite");
        info.Objects[1].Frame.Orientation = new Quaternion(0, 0, 0, 2e31f);
        Refused(() => DatLandblocks.Objects(info), 0xA9B4FFFE, "objects[1].frame.orientation", "overflows");

        var cell = new DatEnvCell
        {
            Id = 0xA9B40100,
            Flags = EnvCellFlags.HasStaticObjs,
            StaticObjects = [new Stab { Id = 0x02000001, Frame = new DatFrame { Origin = new Vector3(1, 2, 3), Orientation = Quaternion.Identity } }],
        };
        cell.StaticObjects[0].Frame.Origin = new Vector3(1, float.PositiveInfinity, 3);
        Refused(() => DatCells.StaticObjects(cell), 0xA9B40100, "EnvCell", "staticObjects[0].frame.origin");
        cell.StaticObjects[0].Frame.Origin = new Vector3(1, 2, 3);
        cell.StaticObjects[0].Frame.Orientation = default;
        Refused(() => DatCells.StaticObjects(cell), 0xA9B40100, "staticObjects[0].frame.orientation", "zero length");
    }

    [Fact]
    public void AnObjectFileReaderNamesTheFile()
    {
        var ex = new DatObjectException(0x01000020, "physicsBSP: has no root node.").InFile("client_portal.dat");
        Assert.Equal("client_portal.dat: GfxObj 0x01000020: physicsBSP: has no root node.", ex.Message);
        Assert.Equal("client_portal.dat", ex.File);
    }

    /// <summary>A landblock whose env cell has a portal to a cell that is not there is not loaded at all: the world keeps what it had.</summary>
    [Fact]
    public void ALandblockWithAPortalToNoCell_IsNotLoaded_AndTheWorldIsUnchanged()
    {
        var scene = SceneLibrary.Load("cellar");
        var dat = WorldDat.From(scene.World);
        var bad = dat.EnvCells[0];
        bad.CellPortals[0].OtherCellId = 0x01FF;
        using var dats = DatPath.Write(dat);
        using var files = dats.Open();
        var loader = DatPath.Loader(files, dat);
        var world = loader.World;

        var ex = Assert.Throws<ArgumentException>(() => loader.LoadLandblock(dat.Landblocks[0]));

        Assert.Contains($"0x{(bad.Id & 0xFFFF0000) | 0x01FF:X8}", ex.Message);
        Assert.False(world.Cells.HasLandblock(dat.Landblocks[0]));
        Assert.Empty(world.Cells.CellIds);
        Assert.Equal(0, world.Objects.Count);
        Assert.Empty(loader.Loaded);
    }
}
