using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>
/// A walking (not running) player held against a wall "wobbles": its heading flips between 0° and 359.43° and it
/// creeps sideways. Both come from the humanoid walk cycle's root frames (frame 1 turns +0.01 rad about z, frame 5
/// −0.01 rad; ±3 mm of sway) under retail's transition rules, not from the wall: retail applies a quantum's root
/// rotation whether or not its translation is refused (CPhysicsObj::UpdateObjectInternal, acclient.c:322718: a failed
/// transition sets the new frame with the old origin; CTransition::find_transitional_position, 313170, turns each
/// accepted sub-step by its share and validate_transition, 312193, returns a refused one to the last accepted
/// position). See docs/open-questions.md, "The walking wobble".
/// </summary>
public class WalkAgainstWallTests
{
    // 360° − 0.01 rad in degrees: the heading while the cycle's frame-1 turn is in effect.
    private const double TurnedHeading = 360.0 - 0.01 * 180.0 / Math.PI;

    // The walk cycle (8 frames at 30 frames a second, one crossed per 30 Hz quantum, after the 3-frame link) holds the
    // +0.01 rad turn for the quanta 4-7 of every 8.
    private static double ExpectedHeading(int frame) => (frame / 4) % 2 == 1 ? TurnedHeading : 0.0;

    private static MotionRig Walk(PhysicsWorld? world, float x, float y)
    {
        var rig = world is null ? new MotionRig() : new MotionRig(world, x, y);
        rig.Do(MotionCommand.Ready);
        rig.Do(MotionCommand.WalkForward);
        return rig;
    }

    [Fact]
    public void AgainstTheSlab_EveryQuantumKeepsItsRootTurn_SoTheHeadingOnlyFlipsAndNeverDrifts()
    {
        // Head-on into the door slab's −Y face (contact at y 99.426 from frame 4): 90 frames, 11 walk cycles.
        var rig = Walk(Bench.DoorScene.Create().World, 100f, 98.9f);
        for (int f = 0; f < 90; f++)
        {
            rig.Frames(1);
            Assert.True(Math.Abs(Headings.Of(rig.State.Position.Frame) - ExpectedHeading(f)) < 1e-3,
                $"frame {f}: heading {Headings.Of(rig.State.Position.Frame)}, expected {ExpectedHeading(f)}");
        }
    }

    [Fact]
    public void AgainstTheSlab_EveryOtherQuantumIsRefusedWhole_AndLosesItsSway()
    {
        // Pressed against the face, a quantum that carries the last sliding normal slides (only the sway and the turned
        // walk's sideways part are left); the next, without it, meets the face and is refused whole (its sway is lost),
        // the alternation ACE records as its `sliding` flag in ace-motion-2's run-into-door.
        var rig = Walk(Bench.DoorScene.Create().World, 100f, 98.9f);
        rig.Frames(5);
        int refused = 0;
        for (int f = 5; f < 89; f++)
        {
            var before = rig.Origin;
            rig.Frames(1);
            Assert.Equal(99.426f, rig.Origin.Y, 3); // held at the face
            if (rig.Origin == before)
                refused++;
        }
        Assert.Equal(42, refused); // half of the 84 quanta
    }

    [Fact]
    public void InTheOpen_TheTurnedWalkCreepsSideways_4Point24MillimetresACycle()
    {
        // While the frame-1 turn is in effect (4 quanta a cycle) the walk's forward offset, 3.12/30 + 0.002 = 0.106 m a
        // frame, points 0.01 rad off +Y: 4 × 0.106 × sin(0.01) = 4.24 mm a cycle towards −X, with no wall at all. The
        // creep of a walker at a wall is this drift (less the refused quanta's share), not something the wall adds.
        var rig = Walk(null, 60f, 60f);
        rig.Frames(9);
        float previous = rig.Origin.X;
        double expected = -4 * (3.12 / 30 + 0.002) * Math.Sin(0.01);
        for (int cycle = 0; cycle < 10; cycle++)
        {
            rig.Frames(8);
            Assert.Equal(expected, rig.Origin.X - previous, 5);
            previous = rig.Origin.X;
        }
    }
}
