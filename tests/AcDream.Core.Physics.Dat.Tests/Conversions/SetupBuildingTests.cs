using AcDream.Core.Physics.Dat.Tests.Support;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Enums;
using DatReaderWriter.Types;
using DatFrame = DatReaderWriter.Types.Frame;
using DatSphere = DatReaderWriter.Types.Sphere;

namespace AcDream.Core.Physics.Dat.Tests.Conversions;

/// <summary>
/// A building whose model is a Setup (0x02…): retail builds its part array from the setup
/// (CBuildingObj::makeBuilding → CPartArray::CreateSetup) but collides only part 0 at the building's frame combined
/// with the part's placement frame (CBuildingObj::find_building_collisions, acclient.c 719115). The cottage scene's
/// building (its shell GfxObj at (100, 100, 0), unturned) is written as a setup whose part 0 is the shell placed at
/// (1.5, −2.25, 0.5) in the setup, the building's frame moved back by as much; its movers then walk the scene
/// path's trajectory to the bit. A second part, a wall across the path of the mover walking to the door, is not
/// collided, as in retail.
/// </summary>
public class SetupBuildingTests
{
    private const uint SetupId = 0x0200_0F00, WallId = 0x0100_0F00;
    private static readonly Vector3 PartOffset = new(1.5f, -2.25f, 0.5f);

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    public void ASetupBuilding_CollidesByItsFirstPartAtItsPlacementFrame_AsTheGfxObjBuildingOfTheScenePath(int parts)
    {
        var scene = SceneLibrary.Load("cottage");
        var dat = WorldDat.From(scene.World, SceneLibrary.ReadText("cottage"));
        var building = Assert.Single(dat.Infos[0].Buildings);
        Assert.Equal(new Vector3(100f, 100f, 0f), building.Frame.Origin);
        Assert.Equal(Quaternion.Identity, building.Frame.Orientation);

        var setup = new Setup { Id = SetupId, SortingSphere = new DatSphere(), SelectionSphere = new DatSphere() };
        var frames = new AnimationFrame((uint)parts);
        setup.Parts.Add(building.ModelId);
        frames.Frames.Add(new DatFrame { Origin = PartOffset, Orientation = Quaternion.Identity });
        if (parts == 2)
        {
            // In the setup's space; in the world x 97 to 103, y 97.4 to 97.6, z 0 to 3: the door mover (x 100, y 97 → 101)
            // would meet it if it collided.
            dat.GfxObjs.Add(DatObjects.GfxObj(WallId, BspShapes.Box(new Vector3(-1.5f, -4.85f, 0.5f), new Vector3(4.5f, -4.65f, 3.5f))));
            setup.Parts.Add(WallId);
            frames.Frames.Add(new DatFrame { Origin = Vector3.Zero, Orientation = Quaternion.Identity });
        }
        setup.PlacementFrames.Add(Placement.Default, frames);
        dat.Setups.Add(setup);
        building.ModelId = SetupId;
        building.Frame = new DatFrame { Origin = new Vector3(98.5f, 102.25f, -0.5f), Orientation = Quaternion.Identity };

        using var dats = DatPath.Write(dat);
        using var files = dats.Open();
        var loader = DatPath.Loader(files, dat);
        loader.LoadLandblock(dat.Landblocks[0]);
        var throughDat = scene.WithWorld(loader.World);

        var shell = Assert.Single(scene.World.Cells.CellIds.Select(id => scene.World.Cells.Get(id)).OfType<LandCell>(), c => c.Building is not null).Building!;
        var datShell = Assert.IsType<LandCell>(loader.World.Cells.Get(shell.Position.CellId)).Building!;
        TreeAssert.Same(shell.Shell.Bsp, datShell.Shell.Bsp, "shell");
        Assert.True(Position.SameBits(new Position(shell.Position.CellId, new Frame(new Vector3(100f, 100f, 0f))), datShell.Position), $"shell position {datShell.Position}");
        var bits = TrajectoryReplay.Replay(throughDat, SceneRunner.Run(scene), tolerance: 0f);
        Assert.True(bits.Matches, $"cottage with a {parts}-part setup building against the scene path: {bits.FirstDifference}");
        Assert.Equal(SceneRunner.Run(scene).ToJson(), SceneRunner.Run(throughDat).ToJson());
    }

    [Fact]
    public void ASetupBuilding_WhoseFirstPartHasNoPhysics_IsRefusedNamingIt()
    {
        var info = new LandBlockInfo { Id = 0xA9B4FFFE };
        info.Buildings.Add(new BuildingInfo { ModelId = SetupId, Frame = new DatFrame { Origin = new Vector3(100f, 100f, 0f), Orientation = Quaternion.Identity } });
        var noShell = new PhysicsSetup { Parts = [new SetupPart(null, Frame.Identity)] };
        var ex = Assert.Throws<DatObjectException>(() => DatLandblocks.ToBuilding(info, 0, noShell));
        Assert.Equal("LandBlockInfo 0xA9B4FFFE: buildings[0].modelId: Setup 0x02000F00's first part has no physics, so no shell.", ex.Message);
        var none = new PhysicsSetup();
        Assert.Contains("has no parts", Assert.Throws<DatObjectException>(() => DatLandblocks.ToBuilding(info, 0, none)).Message);
    }
}
