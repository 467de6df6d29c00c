using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// The object pass in a pile of creatures (not retail; it changes no result). Each candidate the cull lists is
/// tested against the check spheres' own box before its shapes are, and a cylinder's test sets only the
/// local-space placement retail's cache_localspace_sphere leaves for it. The reference is the engine with no
/// shortcut (<see cref="Shortcuts.None"/>), which tests every object of every cell the spheres touch, as retail.
/// </summary>
public class CrowdObjectPassTests
{
    private static readonly PhysicsSetup Creature = new()
    {
        CylSpheres = [new CylSphere(Vector3.Zero, 0.48f, 1.835f)], Height = 1.835f, Radius = 0.48f,
    };

    private static readonly PhysicsSetup Stool = new()
    {
        CylSpheres = [new CylSphere(Vector3.Zero, 0.35f, 0.3f)], Height = 0.3f, Radius = 0.35f,
    };

    private static readonly PhysicsSetup Ball = new()
    {
        Spheres = [new Sphere(new Vector3(0, 0, 0.4f), 0.4f)], Height = 0.8f, Radius = 0.4f,
    };

    /// <summary>
    /// 70 creatures, stools and balls packed into 8 m × 8 m (turned every way), and 300 seeded walks of ten
    /// frames through them, as moves and as body steps: every frame's result is the same bits with every shortcut
    /// (the cull, the crowded cell's index, the tight test, the cylinder's local space) and with none. Went red with the check spheres' box shrunk by 20 cm on every side, beyond the reach
    /// boxes' 6 cm margin (shrunk by 5 cm, within it, it stays green, as it should).
    /// </summary>
    [Fact]
    public void InAPile_EveryFrame_IsTheSameBits_AsTestingEveryCandidateOfTheRegion()
    {
        var world = TestGeometry.FlatWorld();
        var rng = new Random(33);
        for (int i = 0; i < 70; i++)
        {
            var at = TestGeometry.At(96 + 8 * rng.NextSingle(), 96 + 8 * rng.NextSingle(), 0);
            at.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.Tau * rng.NextSingle());
            var (setup, flags) = (i % 7) switch { 0 => (Stool, ShadowFlags.None), 1 => (Ball, ShadowFlags.None), _ => (Creature, ShadowFlags.IsCreature) };
            world.Objects.Register(0x8000_0000u + (uint)i, setup, at, 1f, PhysicsState.Gravity, flags);
        }
        var plain = new PhysicsEngine(world, Shortcuts.All);
        var retail = new PhysicsEngine(world, Shortcuts.None);
        var player = MoverDescription.Player();
        int frames = 0, collided = 0;
        for (int walk = 0; walk < 300; walk++)
        {
            var start = MoverState.OnFloor(TestGeometry.At(95 + 10 * rng.NextSingle(), 95 + 10 * rng.NextSingle(), 0), 0f);
            float heading = MathF.Tau * rng.NextSingle(), speed = 0.5f + 6f * rng.NextSingle();
            var velocity = new Vector3(MathF.Cos(heading), MathF.Sin(heading), 0) * speed;
            if (walk % 2 == 0)
            {
                var (a, b) = (start, start);
                for (int f = 0; f < 10; f++, frames++)
                {
                    var ta = a.Position;
                    ta.Frame.Origin += velocity / 30f;
                    var tb = b.Position;
                    tb.Frame.Origin += velocity / 30f;
                    var ra = plain.Resolve(player, a, ta);
                    var rb = retail.Resolve(player, b, tb);
                    Assert.Equal(Bits(rb), Bits(ra));
                    collided += ra.CollidedObjects.Length > 0 ? 1 : 0;
                    (a, b) = (ra.Next, rb.Next);
                }
            }
            else
            {
                var (a, b) = (start, start);
                var (ba, bb) = (BodyState.Creature(), BodyState.Creature());
                for (int f = 0; f < 10; f++, frames++)
                {
                    var ra = plain.Step(player, a, ba, 0.2, velocity);
                    var rb = retail.Step(player, b, bb, 0.2, velocity);
                    Assert.Equal(Bits(rb.Move), Bits(ra.Move));
                    collided += ra.Move.CollidedObjects.Length > 0 ? 1 : 0;
                    (a, b, ba, bb) = (ra.Next, rb.Next, ra.Body, rb.Body);
                }
            }
        }
        Assert.True(collided > frames / 4, $"the walks press into the pile: {collided} of {frames} frames collided");
    }

    /// <summary>
    /// A cylinder's test leaves the path's local space at the cylinder's owner (retail cache_localspace_sphere(p,
    /// 1.0) before CCylSphere::intersects_sphere), which its step-up turns the collision normal by: the placement
    /// and its matrix are the owner's afterwards, whatever space was prepared before. Went red with
    /// <see cref="SpherePath.CacheLocalSpaceForCylinder"/> emptied.
    /// </summary>
    [Fact]
    public void ACylinderTest_LeavesTheLocalSpaceAtItsOwner()
    {
        var path = new SpherePath { NumSphere = 1, InsertType = InsertType.Transition };
        path.InitSphere([new Sphere(new Vector3(0, 0, 0.5f), 0.5f)], 1f);
        var start = TestGeometry.At(100, 100, 0);
        path.InitPath(null, start, start);
        path.SetCheckPos(start, null);
        var before = TestGeometry.At(90, 90, 0);
        before.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f);
        path.CacheLocalSpaceSphere(before, 1f);
        var owner = TestGeometry.At(101, 100, 0);
        owner.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);

        path.CacheLocalSpaceForCylinder(owner);

        Assert.Equal(owner.CellId, path.LocalSpacePos.CellId);
        Assert.Equal(owner.Frame.Origin, path.LocalSpacePos.Frame.Origin);
        Assert.Equal(owner.Frame.Orientation, path.LocalSpacePos.Frame.Orientation);
        // The owner's yaw of 90° turns +X to +Y (within rounding of the quaternion's matrix).
        var turned = path.LocalSpacePos.LocalToGlobalVec(Vector3.UnitX);
        Assert.True(Vector3.Distance(turned, Vector3.UnitY) < 1e-6f, $"+X turned by the owner's frame: {turned}");
    }

    private static string Bits(in MoveResult r)
    {
        var n = r.Next;
        var p = n.Position;
        static string F(float f) => BitConverter.SingleToUInt32Bits(f).ToString("X8");
        return string.Join(' ', p.CellId.ToString("X8"), F(p.Frame.Origin.X), F(p.Frame.Origin.Y), F(p.Frame.Origin.Z),
            F(p.Frame.Orientation.W), F(p.Frame.Orientation.Z), r.Succeeded, n.Contact, n.OnWalkable, n.SlidingNormalValid,
            r.CollisionNormalValid, r.CollidedWithEnvironment, F(n.ContactPlane.Normal.Z), F(n.ContactPlane.D),
            F(n.SlidingNormal.X), F(n.SlidingNormal.Y), F(r.CollisionNormal.X), F(r.CollisionNormal.Y), F(r.CollisionNormal.Z),
            r.LastCollidedObject.ToString("X8"), string.Join(',', r.CollidedObjects.ToArray()));
    }
}
