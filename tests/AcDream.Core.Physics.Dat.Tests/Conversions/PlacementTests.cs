using AcDream.Core.Physics.Dat.Tests.Support;
using DatReaderWriter.DBObjs;
using DatReaderWriter.Types;
using AcDream.Core.Physics.Scenes;
using DatFrame = DatReaderWriter.Types.Frame;

namespace AcDream.Core.Physics.Dat.Tests.Conversions;

/// <summary>Where the DAT's static objects and buildings land, and objects placed by a GfxObj id.</summary>
public class PlacementTests
{
    /// <summary>
    /// A landblock's object frame is landblock-local and may reach past its edge: retail (and ACE) run
    /// LandDefs::adjust_to_outside on it, so it lands in the neighbour's land cell with a local origin there.
    /// </summary>
    [Fact]
    public void ALandblockObjectPastTheEastEdge_LandsInTheNeighboursLandCell()
    {
        var turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f);
        var info = new LandBlockInfo
        {
            Id = 0xA9B4FFFE,
            Objects =
            [
                new Stab { Id = 0x02000001, Frame = new DatFrame { Origin = new Vector3(50, 30, 2), Orientation = turn } },
                new Stab { Id = 0x01000002, Frame = new DatFrame { Origin = new Vector3(195, 10, 0), Orientation = Quaternion.Identity } },
            ],
        };
        using var files = WrittenDats.Write([], [info]);

        var objects = DatLandblocks.Objects(files.Get<LandBlockInfo>(files.Cell, 0xA9B4FFFE));

        // x 50 is column 2, y 30 is row 1: cell 2 * 8 + 1 + 1 = 0x12.
        Assert.Equal(new DatPlacement(0x02000001, new Position(0xA9B40012, new Frame(new Vector3(50, 30, 2), turn))), objects[0]);
        Assert.Equal(0xAAB40001u, objects[1].Position.CellId);
        Assert.Equal(new Vector3(3, 10, 0), objects[1].Position.Frame.Origin);
    }

    /// <summary>A GfxObj without physics converts to no model; an object placed by a GfxObj id is one part at the identity frame.</summary>
    [Fact]
    public void AGfxObjWithoutPhysics_HasNoModel_AndAGfxObjObjectIsOnePart()
    {
        using var files = WrittenDats.Write([DatObjects.GfxObj(0x01000003, null), DatObjects.GfxObj(0x01000004, BspShapes.Box(Vector3.Zero, Vector3.One))], []);

        Assert.Null(DatModels.ToPhysicsModel(files.Get<GfxObj>(files.Portal, 0x01000003)));
        var model = DatModels.ToPhysicsModel(files.Get<GfxObj>(files.Portal, 0x01000004));
        var setup = DatSetups.FromModel(model);

        var part = Assert.Single(setup.Parts);
        Assert.Same(model, part.Model);
        Assert.Equal(Vector3.Zero, part.Frame.Origin);
        Assert.Equal(Quaternion.Identity, part.Frame.Orientation);
        Assert.True(setup.HasPhysicsBsp);
        Assert.Empty(setup.Spheres);
    }
}
