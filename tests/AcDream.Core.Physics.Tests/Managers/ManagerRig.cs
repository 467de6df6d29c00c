using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Managers;

/// <summary>
/// The reference data's world for the managers (flat landblocks 0xA9B4 and its north neighbour 0xA9B5, the door slab
/// box at (100, 100, 0)) and one retail player (Run 200: run rate 2.375, max speed 9.5 m/s) with the humanoid table,
/// placed on the floor and stepped at 30 Hz through the motion body step.
/// </summary>
internal sealed class ManagerRig
{
    public const uint Block = 0xA9B4, NorthBlock = 0xA9B5;

    private const string WorldScene = """
        {
          "version": 1,
          "name": "managers world",
          "models": { "doorSlab": { "box": { "min": [-0.5, -0.009, 0], "max": [0.5, 0.252, 2.2] } } },
          "setups": {
            "door": { "parts": [{ "model": "doorSlab" }] },
            "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }, { "center": [0, 0, 1.35], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 }
          },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }, { "id": "0xA9B5", "height": 0 }],
          "objects": [{ "id": "0x7000_0001", "setup": "door", "cell": "0xA9B40025", "position": [100, 100, 0], "state": "0x10001" }],
          "movers": [{ "name": "unused", "setup": "player", "state": ["Gravity"], "cell": "0xA9B40013", "position": [60, 60, 0], "floorZ": 0, "motion": [{ "offset": [0, 0, 0], "count": 1 }] }]
        }
        """;

    public readonly PhysicsEngine Engine = new(SceneLoader.Load(WorldScene, "managers world").World);
    public readonly MoverDescription Mover = MoverDescription.Player(objectId: 0x50000003, stepDownHeight: 0.04f);
    public readonly ObjectMotion Motion;
    public MoverState State;
    public BodyState Body = BodyState.Creature();

    public ManagerRig(float x, float y, uint block = Block)
    {
        State = MoverState.OnFloor(At(x, y, block), 0f);
        Motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(200, 200));
        Motion.Place(Mover, State, ref Body);
    }

    public PositionManager Manager => Motion.PositionManager;

    public static Position At(float x, float y, uint block = Block) =>
        new(LandDefs.LandCellAt(block, new Vector3(x, y, 0f)), new Vector3(x, y, 0f));

    public void InterpolateTo(float x, float y, uint block = Block, bool keepHeading = false) =>
        Manager.InterpolateTo(At(x, y, block), keepHeading, Mover, ref State);

    public BodyStepResult Frame()
    {
        var r = Engine.Step(Mover, State, Body, Motion, 1.0 / 30.0);
        State = r.Next;
        Body = r.Body;
        return r;
    }

    public void Frames(int count)
    {
        for (int i = 0; i < count; i++)
            Frame();
    }

    public Vector3 Origin => State.Position.Frame.Origin;

    /// <summary>The compass heading, degrees (0 = +Y, 90 = +X).</summary>
    public float Heading => Headings.Of(State.Position.Frame);
}
