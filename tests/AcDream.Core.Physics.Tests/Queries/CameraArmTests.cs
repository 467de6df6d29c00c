using AcDream.Core.Physics.Diagnostics;
using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Queries;

/// <summary>
/// The retail camera arm: a viewer transition (0.3 m sphere, IsViewer | PathClipped | FreeRotate |
/// PerfectClip) that stops just short of the first thing in the way.
/// </summary>
public class CameraArmTests
{
    private const uint Land = 0xA9B40025, Room = 0xA9B40100;

    private static WorldQuery Query(string scene) => new(SceneLibrary.Load(scene).World);
    private static Position At(uint cell, float x, float y, float z) => new(cell, new Vector3(x, y, z));

    [Fact]
    public void InTheCottage_TheCameraStopsShortOfTheNorthWall()
    {
        // The wall's inner face is at y = 104; the camera sphere (0.3 m) touches it with its centre at 103.7.
        // Retail's perfect clip backs off by bisection to within 2 % of a sub-step (0.3 m): at most 6 mm short.
        var arm = Query("cottage").CameraArm(At(Room, 100, 101, 1.5f), new Vector3(100, 106, 1.5f));
        Assert.Equal(CameraPlacement.Swept, arm.Placement);
        Assert.True(arm.Blocked);
        AssertVec.Near(new Vector3(0, -1, 0), arm.Normal, 1e-5f);
        Assert.Equal(Room, arm.Camera.CellId);
        float y = arm.Camera.Origin.Y;
        Assert.InRange(y, 103.7f - 0.006f, 103.7f + 1e-4f);
        Assert.Equal(100f, arm.Camera.Origin.X, 4);
        Assert.Equal(1.5f, arm.Camera.Origin.Z, 4);
    }

    [Fact]
    public void OutsideTheDoor_TheCameraStopsShortOfTheSlab_AndAClearArmReachesTheDesiredPoint()
    {
        var q = Query("door");
        var blocked = q.CameraArm(At(Land, 100, 97, 1.5f), new Vector3(100, 103, 1.5f));
        Assert.True(blocked.Blocked);
        Assert.InRange(blocked.Camera.Origin.Y, 99.691f - 0.006f, 99.691f + 1e-4f);

        // The pivot's cell id names only its frame: labelled with the landblock's first cell, 76 m away, the
        // arm starts in the cell that holds the pivot and meets the same slab.
        var relabelled = q.CameraArm(At(0xA9B40001, 100, 97, 1.5f), new Vector3(100, 103, 1.5f));
        Assert.Equal(Land, relabelled.Camera.CellId);
        Assert.Equal(blocked.Camera.Origin, relabelled.Camera.Origin);

        var clear = q.CameraArm(At(Land, 96, 97, 1.5f), new Vector3(96, 103, 1.5f));
        Assert.Equal(CameraPlacement.Swept, clear.Placement);
        Assert.False(clear.Blocked);
        AssertVec.Near(new Vector3(96, 103, 1.5f), clear.Camera.Origin, 1e-4f);
    }

    [Fact]
    public void IntoTheGround_TheViewersArmOfValidateWalkable_BacksTheCameraAlongItsMotionToWhereItTouches()
    {
        // From (90, 90, 1.5) towards (90, 94, -2): the sphere's bottom meets z = 0 when the centre is at
        // z = 0.3, a fraction 1.2 / 3.5 of the way, y = 90 + 4 × 1.2 / 3.5 = 91.3714. The player's arm would
        // instead lift the sphere straight up at the end of the sub-step that sank (y = 91.58).
        var arm = Query("door").CameraArm(At(Land, 90, 90, 1.5f), new Vector3(90, 94, -2));
        Assert.Equal(CameraPlacement.Swept, arm.Placement);
        Assert.True(arm.Blocked);
        AssertVec.Near(Vector3.UnitZ, arm.Normal, 1e-5f);
        AssertVec.Near(new Vector3(90, 90 + 4 * 1.2f / 3.5f, 0.3f), arm.Camera.Origin, 1e-3f);
    }

    [Fact]
    public void TheViewerSubSteps_AreWholeRadiiAndAShortLastStep_FloorPlusOne()
    {
        // 1 m with a 0.3 m sphere: floor(1 / 0.3) + 1 = 4 sub-steps of 0.3, 0.3, 0.3 and 0.1 m
        // (CTransition::calc_num_steps and find_transitional_position's viewer branch).
        var world = SceneLibrary.Load("door").World;
        var engine = new PhysicsEngine(world) { Observer = new TransitionEventLog() };
        var viewer = new MoverDescription(0, [new Sphere(Vector3.Zero, WorldQuery.ViewerRadius)], 0, 0, PhysicsState.None, WorldQuery.ViewerFlags);
        var result = engine.Resolve(viewer, MoverState.Airborne(At(Land, 90, 90, 2)), At(Land, 90, 91, 2));
        Assert.True(result.Succeeded);
        var steps = ((TransitionEventLog)engine.Observer).Events.Where(e => e.Kind == TransitionEventKind.SubStep).Select(e => e.Vector2.Y).ToArray();
        Assert.Equal(4, steps.Length);
        Assert.Equal(0.3f, steps[0], 5);
        Assert.Equal(0.3f, steps[2], 5);
        Assert.Equal(0.1f, steps[3], 5);
        AssertVec.Near(new Vector3(90, 91, 2), result.Position.Origin, 1e-5f);
    }

    [Fact]
    public void AnArmWhoseSweepFails_GoesToTheDesiredPointWhenACellHoldsIt_ElseToThePivot()
    {
        // A desired point 1200 sub-steps away: the viewer transition is refused (more than 1000 sub-steps).
        var q = Query("door");
        var far = q.CameraArm(At(Land, 100, 90, 2), new Vector3(100, 90 + 0.3f * 1200, 2));
        Assert.Equal(CameraPlacement.AtPivot, far.Placement);     // y 450: no loaded landblock
        AssertVec.Near(new Vector3(100, 90, 2), far.Camera.Origin);

        var world = new PhysicsWorld();
        for (uint y = 0xB4; y <= 0xB7; y++)
            world.Cells.AddLandblock(AcDream.Core.Physics.Terrain.Flat(0xA900 | y, 0f));
        var placed = new WorldQuery(world).CameraArm(At(0xA9B40001, 5, 5, 2), new Vector3(5, 5 + 0.3f * 1200, 2));
        Assert.Equal(CameraPlacement.AtDesired, placed.Placement);
        Assert.Equal(0xA9B50000u, placed.Camera.CellId & 0xFFFF0000u);   // y 365: the next block north (192..384)
    }

    [Fact]
    public void RetailQuirk_ACameraThatBeganIndoors_IgnoresTerrainItIsAlreadyUnderWhileRisingAwayFromIt()
    {
        // acclient 0x0050D010 (OBJECTINFO::validate_walkable, viewer arm): when the back-off fraction is not in
        // (0, 1] and the transition began in an indoor cell, the terrain is passed. The cottage sunk 0.5 m
        // (ground at z = 0.5, the room's floor at 0) and its door removed: the camera leaves the room through
        // the doorway with its sphere 0.3 m under the ground's plane, rising slowly (the fraction is negative),
        // and ends at the desired point. Without the indoor exception it would be pushed along its motion.
        var json = SceneLibrary.ReadText("cottage").Replace("\"landblocks\": [{ \"id\": \"0xA9B4\", \"height\": 0 }]",
            "\"landblocks\": [{ \"id\": \"0xA9B4\", \"height\": 0.5 }]");
        var world = SceneLoader.Load(json).World;
        Assert.True(world.Objects.Unregister(0x7000_0001));
        var arm = new WorldQuery(world).CameraArm(At(Room, 100, 100.5f, 0.5f), new Vector3(100, 97, 0.55f));
        Assert.Equal(CameraPlacement.Swept, arm.Placement);
        Assert.False(arm.Blocked, $"{arm.Camera} n={arm.Normal}");
        Assert.Equal(Land, arm.Camera.CellId);
        AssertVec.Near(new Vector3(100, 97, 0.55f), arm.Camera.Origin, 1e-4f);

        // The same camera begun outdoors (just outside the doorway) is stopped by the ground.
        var outdoors = new WorldQuery(world).CameraArm(At(Land, 100, 99.5f, 0.5f), new Vector3(100, 97, 0.55f));
        Assert.True(outdoors.Blocked);
        AssertVec.Near(Vector3.UnitZ, outdoors.Normal, 1e-5f);
    }
}
