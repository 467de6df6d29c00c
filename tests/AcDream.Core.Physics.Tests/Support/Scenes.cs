using AcDream.Core.Physics;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>Minimal scenes for apparatus tests: each holds only what its behaviour needs.</summary>
internal static class Scenes
{
    public const uint DoorId = 0x7000_0001;
    public static readonly Vector3 DoorOrigin = new(100, 100, 0);

    /// <summary>The slab's faces in door space: front at Y = -0.009, back at Y = 0.252 (the seed's door).</summary>
    public const float SlabFront = -0.009f, SlabBack = 0.252f, SlabHalfWidth = 0.5f, SlabHeight = 2.2f;

    public const float PlayerRadius = 0.48f;

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
    public static float SlabPenetration(Vector3 origin)
    {
        var min = DoorOrigin + new Vector3(-SlabHalfWidth, SlabFront, 0);
        var max = DoorOrigin + new Vector3(SlabHalfWidth, SlabBack, SlabHeight);
        float worst = float.NegativeInfinity;
        foreach (float z in new[] { 0.475f, 1.35f })
        {
            var c = origin + new Vector3(0, 0, z);
            var closest = Vector3.Clamp(c, min, max);
            worst = MathF.Max(worst, PlayerRadius - Vector3.Distance(c, closest));
        }
        return worst;
    }

    /// <summary>The seed's apparatus player: the retail player's spheres and step-up, with step-down 0.04.</summary>
    public static MoverDescription SeedPlayer() => MoverDescription.Player(stepDownHeight: 0.04f);

    public static Mover Player(PhysicsWorld world, float x, float y, MoverDescription? description = null)
    {
        var position = TestGeometry.At(x, y, 0);
        return new Mover(world, description ?? SeedPlayer(), MoverState.OnFloor(position, 0f));
    }
}
