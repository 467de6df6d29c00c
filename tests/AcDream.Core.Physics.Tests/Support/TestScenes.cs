using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>Minimal scenes for apparatus tests: each holds only what its behaviour needs.</summary>
internal static class TestScenes
{
    public const uint DoorId = Bench.DoorScene.DoorId;
    public static readonly Vector3 DoorOrigin = Bench.DoorScene.DoorOrigin;

    /// <summary>The slab's faces in door space: front at Y = -0.009, back at Y = 0.252 (the seed's door).</summary>
    public const float SlabFront = Bench.DoorScene.SlabFront, SlabBack = Bench.DoorScene.SlabBack,
        SlabHalfWidth = Bench.DoorScene.SlabHalfWidth, SlabHeight = Bench.DoorScene.SlabHeight;

    public const float PlayerRadius = Bench.DoorScene.PlayerRadius;

    /// <summary>A flat floor at z = 0 with the door standing on it, facing -Y, in the middle of a land cell.</summary>
    public static PhysicsWorld Door(PhysicsState state = (PhysicsState)0x10008, bool registerShapesOnly = false)
    {
        var world = TestGeometry.FlatWorld();
        var position = TestGeometry.At(DoorOrigin.X, DoorOrigin.Y, DoorOrigin.Z);
        if (registerShapesOnly)
            world.Objects.Register(DoorId, ShadowShapeBuilder.FromSetup(TestGeometry.DoorSetup()), position, 1f, state);
        else
            world.Objects.Register(DoorId, TestGeometry.DoorSetup(), position, 1f, state);
        return world;
    }

    /// <summary>How deep the retail player's spheres at <paramref name="origin"/> reach into the door slab (≤ 0 when clear).</summary>
    public static float SlabPenetration(Vector3 origin) => Bench.DoorScene.SlabPenetration(origin);

    /// <summary>The seed's apparatus player: the retail player's spheres and step-up, with step-down 0.04.</summary>
    public static MoverDescription SeedPlayer() => MoverDescription.Player(stepDownHeight: 0.04f);

    public static Mover Player(PhysicsWorld world, float x, float y, MoverDescription? description = null)
    {
        var position = TestGeometry.At(x, y, 0);
        return new Mover(world, description ?? SeedPlayer(), MoverState.OnFloor(position, 0f));
    }
}
