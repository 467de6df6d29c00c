using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Tests.Queries;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// Each shortcut can be turned off alone (<see cref="Shortcuts"/>), and then gives the very bits of the engine
/// with all of them: a crowd of creatures, stools and balls around the door (more than the crowded-cell index's
/// threshold in one cell), walked into by players as moves and as body steps (pushing on after a refusal repeats
/// the same request), and the hand-picked camera arms. The whole suite also runs with all of them off (CI).
/// Went red with the cull's retail walk taking the cell's objects last to first (ACE's order).
/// </summary>
public class EachShortcutAloneTests
{
    private static readonly Shortcuts[] Each = Enum.GetValues<Shortcuts>()
        .Where(f => f != Shortcuts.None && f != Shortcuts.All && System.Numerics.BitOperations.IsPow2((uint)f)).ToArray();

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

    [Fact]
    public void EveryShortcut_IsASingleFlag_AndAllIsEveryFlag()
    {
        Assert.Equal(16, Each.Length);
        Assert.Equal(Shortcuts.All, Each.Aggregate(Shortcuts.None, (all, f) => all | f));
    }

    [Fact]
    public void EachShortcutOffAlone_MovesAndBodySteps_AreTheSameBits()
    {
        var world = TestScenes.Door();
        var rng = new Random(41);
        for (int i = 0; i < 60; i++)
        {
            // Around the door (at 100, 100), kept off its slab's front and back.
            float x = 94 + 12 * rng.NextSingle(), y = rng.Next(2) == 0 ? 94 + 5 * rng.NextSingle() : 101.5f + 4.5f * rng.NextSingle();
            var at = TestGeometry.At(x, y, 0);
            at.Frame.Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.Tau * rng.NextSingle());
            var (setup, flags) = (i % 7) switch { 0 => (Stool, ShadowFlags.None), 1 => (Ball, ShadowFlags.None), _ => (Creature, ShadowFlags.IsCreature) };
            world.Objects.Register(0x8000_0000u + (uint)i, setup, at, 1f, PhysicsState.Gravity, flags);
        }
        var all = new PhysicsEngine(world, Shortcuts.All);
        var alone = Each.Select(f => new PhysicsEngine(world, Shortcuts.All & ~f)).ToArray();
        var player = MoverDescription.Player();
        int frames = 0, collided = 0, refused = 0;
        for (int walk = 0; walk < 120; walk++)
        {
            var start = MoverState.OnFloor(TestGeometry.At(95 + 10 * rng.NextSingle(), 95 + 10 * rng.NextSingle(), 0), 0f);
            float heading = MathF.Tau * rng.NextSingle(), speed = 0.5f + 6f * rng.NextSingle();
            var velocity = new Vector3(MathF.Cos(heading), MathF.Sin(heading), 0) * speed;
            var states = Enumerable.Repeat(start, alone.Length + 1).ToArray();
            var bodies = Enumerable.Range(0, alone.Length + 1).Select(_ => BodyState.Creature()).ToArray();
            for (int f = 0; f < 10; f++, frames++)
            {
                MoveResult Run(PhysicsEngine engine, int k)
                {
                    if (walk % 2 == 0)
                    {
                        var target = states[k].Position;
                        target.Frame.Origin += velocity / 30f;
                        var r = engine.Resolve(player, states[k], target);
                        states[k] = r.Next;
                        return r;
                    }
                    var step = engine.Step(player, states[k], bodies[k], 0.2, velocity);
                    (states[k], bodies[k]) = (step.Next, step.Body);
                    return step.Move;
                }
                var reference = Run(all, 0);
                var expected = Bits(reference);
                for (int k = 0; k < alone.Length; k++)
                {
                    var actual = Bits(Run(alone[k], k + 1));
                    Assert.True(expected == actual, $"{Each[k]} off, walk {walk} frame {f}: {actual} against {expected}");
                }
                collided += reference.CollisionNormalValid ? 1 : 0;
                refused += reference.Succeeded ? 0 : 1;
            }
        }
        Assert.True(collided > frames / 4, $"the walks press into the crowd and the door: {collided} of {frames} frames collided");
        Assert.True(refused > 0, "some request was refused (and repeated)");
    }

    [Fact]
    public void EachShortcutOffAlone_TheHandPickedCameraArms_AreTheSameBits()
    {
        foreach (var arm in CameraArmCases.Table)
        {
            var world = CameraArmCases.WorldOf(arm.World);
            var from = new Position(arm.Cell, arm.Pivot);
            var expected = Show(new WorldQuery(world, Shortcuts.All).CameraArm(from, arm.Desired, arm.Player));
            foreach (var f in Each)
                Assert.Equal($"{arm.Name}: {expected}", $"{arm.Name}: {Show(new WorldQuery(world, Shortcuts.All & ~f).CameraArm(from, arm.Desired, arm.Player))}");
        }
    }

    private static string Show(in CameraArmResult r) =>
        string.Join(' ', r.Camera.CellId.ToString("X8"), F(r.Camera.Origin.X), F(r.Camera.Origin.Y), F(r.Camera.Origin.Z), r.Placement, r.Blocked,
            F(r.Normal.X), F(r.Normal.Y), F(r.Normal.Z));

    private static string F(float f) => BitConverter.SingleToUInt32Bits(f).ToString("X8");

    // Every field of the result, by its bits.
    private static string Bits(in MoveResult r)
    {
        var n = r.Next;
        var p = n.Position;
        return string.Join(' ', p.CellId.ToString("X8"), F(p.Frame.Origin.X), F(p.Frame.Origin.Y), F(p.Frame.Origin.Z),
            F(p.Frame.Orientation.W), F(p.Frame.Orientation.X), F(p.Frame.Orientation.Y), F(p.Frame.Orientation.Z), r.Succeeded, n.Contact,
            n.OnWalkable, n.SlidingNormalValid, r.CollisionNormalValid, r.CollidedWithEnvironment, r.VelocityKilled, r.LastState,
            F(n.ContactPlane.Normal.X), F(n.ContactPlane.Normal.Y), F(n.ContactPlane.Normal.Z), F(n.ContactPlane.D), n.ContactPlaneCellId.ToString("X8"),
            F(n.SlidingNormal.X), F(n.SlidingNormal.Y), F(n.SlidingNormal.Z), F(r.CollisionNormal.X), F(r.CollisionNormal.Y), F(r.CollisionNormal.Z),
            r.LastCollidedObject.ToString("X8"), string.Join(',', r.CollidedObjects.ToArray()));
    }
}
