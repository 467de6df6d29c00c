using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Body;

/// <summary>
/// <see cref="PhysicsObject"/>, one object per body: stepped through it, a built-in scene's body movers follow their
/// committed replays bit for bit; the step's displacement is the position difference; a running player's speed is
/// the run speed while its body velocity is zero.
/// </summary>
public class PhysicsObjectTests
{
    private static readonly string ReplayDirectory = Path.Combine(AppContext.BaseDirectory, "Replays");

    public static TheoryData<string> ScenesWithBodies()
    {
        var data = new TheoryData<string>();
        foreach (string name in SceneLibrary.Names)
            if (SceneLibrary.Load(name).Movers.Any(m => m.IsBody && !m.IsMissile))
                data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(ScenesWithBodies))]
    public void SteppedAsObjects_TheSceneBodies_FollowTheirCommittedReplays_BitForBit(string name)
    {
        var scene = SceneLibrary.Load(name);
        var committed = Trajectory.LoadFile(Path.Combine(ReplayDirectory, name + ".trajectory.json"));
        var engine = new PhysicsEngine(scene.World);
        // The movers before this one as recorded (what a StickTo command follows), from the committed file.
        var earlier = new List<(SceneMover, IReadOnlyList<TrajectoryFrame>)>();
        int compared = 0;
        for (int m = 0; m < scene.Movers.Count; m++)
        {
            var mover = scene.Movers[m];
            var frames = committed.Movers[m].Frames;
            if (mover.IsBody && !mover.IsMissile)
            {
                var body = mover.StartBody;
                var commands = mover.Commands?.Start(mover.Description, mover.Start, ref body, earlier);
                var obj = new PhysicsObject(mover.Description, mover.Start, body, commands?.Motion);
                for (int f = 0; f < mover.FrameCount; f++)
                {
                    var input = mover.Steps[f];
                    BodyStepResult step;
                    if (commands is null)
                    {
                        step = engine.Step(obj, input.Elapsed, input.DesiredVelocity, input.JumpVelocity);
                    }
                    else
                    {
                        // The motion commands take the object's fields by reference.
                        commands.Give(f, obj.Description, ref obj.State, ref obj.Body);
                        step = engine.Step(obj, input.Elapsed);
                    }
                    string at = $"{name}: mover '{mover.Name}', frame {f}";
                    var expected = frames[f];
                    Assert.True(Bits(expected.Position) == Bits(obj.Position.Frame.Origin), $"{at}: position {obj.Position.Frame.Origin}, recorded {expected.Position}");
                    Assert.True(Bits(expected.Velocity) == Bits(obj.Body.Velocity), $"{at}: velocity {obj.Body.Velocity}, recorded {expected.Velocity}");
                    Assert.True(expected.Cell == obj.Position.CellId, $"{at}: cell 0x{obj.Position.CellId:X8}, recorded 0x{expected.Cell:X8}");
                    Assert.True((expected.Contact, expected.OnWalkable, expected.Quanta, expected.Succeeded)
                        == (obj.State.Contact, obj.State.OnWalkable, step.Quanta, step.Move.Succeeded), $"{at}: contact, walkable, quanta or success");
                    // The object holds what the step returned.
                    Assert.True(Position.SameBits(step.Next.Position, obj.Position), $"{at}: the object's position is not the step's");
                    compared++;
                }
            }
            earlier.Add((mover, frames));
        }
        Assert.True(compared > 0);
    }

    [Fact]
    public void Displacement_IsThePositionDifference_WithinALandblock()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var player = MoverDescription.Player();
        var obj = new PhysicsObject(player, MoverState.OnFloor(TestGeometry.At(100, 100, 0), 0f), BodyState.Creature());
        var desired = new Vector3(3f, 4f, 0f);
        int withQuanta = 0;
        for (int f = 0; f < 50; f++)
        {
            var before = obj.Position.Frame.Origin;
            var step = engine.Step(obj, 1.0 / 60, desired);
            var moved = obj.Position.Frame.Origin - before;
            Assert.True(Bits(moved) == Bits(step.Displacement), $"frame {f}: displacement {step.Displacement}, moved {moved}");
            if (step.Quanta == 0)
                continue;
            // 5 m/s on flat ground: each quantum moves it 5 m/s × its seconds (after the first, which also settles
            // it 0.005 m up onto the floor).
            if (withQuanta++ > 0)
                Assert.Equal(5f, step.Speed, 3);
        }
        Assert.Equal(25, withQuanta); // 50 frames of 1/60 s: a quantum every second frame
    }

    [Fact]
    public void Displacement_IsThePositionDifference_AcrossALandblockBoundary()
    {
        const uint west = TestGeometry.Landblock, east = TestGeometry.Landblock + 0x100;
        var world = new PhysicsWorld();
        world.Cells.AddLandblock(Terrain.Flat(west, 0f));
        world.Cells.AddLandblock(Terrain.Flat(east, 0f));
        var engine = new PhysicsEngine(world);
        var obj = new PhysicsObject(MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(190f, 100f, 0f), 0f), BodyState.Creature());
        var total = Vector3.Zero;
        var startGlobal = obj.Position.ToGlobal();
        for (int f = 0; f < 30; f++)
            total += engine.Step(obj, 1.0 / 30, new Vector3(10f, 0f, 0f)).Displacement;
        Assert.Equal(east, obj.Position.CellId >> 16);
        // 30 quanta of 1/30 s at 10 m/s: 10 m east, across the boundary at x = 192.
        var moved = obj.Position.ToGlobal() - startGlobal;
        Assert.Equal(10f, moved.X, 3);
        Assert.True(Vector3.Distance(moved, total) < 1e-3f, $"displacements add to {total}, the position moved {moved}");
    }

    [Fact]
    public void ALongFrame_SteppedInSeveralQuanta_ReportsTheirTimeAndSpeed()
    {
        // 0.5 s in one call: quanta of 0.2, 0.2 and 0.1 s (CPhysicsObj::update_object's MaxQuantum), 4 m/s on flat ground.
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var obj = new PhysicsObject(MoverDescription.Player(), MoverState.OnFloor(TestGeometry.At(100, 40, 0), 0f), BodyState.Creature());
        engine.Step(obj, 1.0 / 30, Vector3.Zero); // settles onto the floor
        var step = engine.Step(obj, 0.5, new Vector3(0f, 4f, 0f));
        Assert.Equal(3, step.Quanta);
        Assert.Equal(0.5, step.SteppedTime, 6);
        Assert.Equal(2f, step.Displacement.Y, 4);
        Assert.Equal(4f, step.Speed, 3);
    }

    [Fact]
    public void ARunningPlayer_HasZeroVelocity_AndSpeedTheRunSpeed()
    {
        // Run 200: RunForward at 4 m/s × 2.375 = 9.5 m/s, moved by the motion table's root motion, not the velocity.
        // 30 frames into the steady run, then 60 more.
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var player = MoverDescription.Player();
        var motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill: 200, jumpSkill: 200));
        var obj = new PhysicsObject(player, MoverState.OnFloor(TestGeometry.At(100, 40, 0), 0f), BodyState.Creature(), motion);
        motion.Place(player, obj.State, ref obj.Body);
        motion.DoMotion(MotionCommand.WalkForward, new MotionParameters(1f, HoldKey.Run), player, ref obj.State, ref obj.Body);
        for (int f = 0; f < 30; f++)
            engine.Step(obj, 1.0 / 30);
        var distance = Vector3.Zero;
        double seconds = 0;
        for (int f = 0; f < 60; f++)
        {
            var step = engine.Step(obj, 1.0 / 30);
            Assert.Equal(Vector3.Zero, obj.Body.Velocity);
            // Each 1/30 s quantum crosses 2.375 animation frames: 2 or 3 whole frames of 9.5 / 71.25 m.
            float frames = step.Displacement.Length() / (9.5f / 71.25f);
            Assert.True(MathF.Abs(frames - 2f) < 1e-3f || MathF.Abs(frames - 3f) < 1e-3f, $"a quantum moved {frames} animation frames");
            distance += step.Displacement;
            seconds += step.SteppedTime;
        }
        // The root motion is handed out per animation frame crossed (docs/motion-example.md): the cycle plays at
        // 30 × 2.375 = 71.25 frames/s, 9.5 / 71.25 m a frame; quanta 30 to 89 end at 213.75 frames, having crossed
        // 213 - 71 = 142 whole frames since quantum 29: 142 × 9.5 / 71.25 m in 2 s, 9.4667 m/s.
        Assert.Equal(2.0, seconds, 6);
        Assert.Equal(142 * 9.5f / 71.25f / 2f, distance.Length() / (float)seconds, 3);
    }

    [Fact]
    public void ABodyWithAMotionLayer_IsNotSteppedByADesiredVelocity_AndIsNotChanged()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var player = MoverDescription.Player();
        var motion = new ObjectMotion(MotionTables.Humanoid());
        var obj = new PhysicsObject(player, MoverState.OnFloor(TestGeometry.At(100, 40, 0), 0f), BodyState.Creature(), motion);
        var before = (obj.State, obj.Body);
        var ex = Assert.Throws<ArgumentException>(() => engine.Step(obj, 1.0 / 30, new Vector3(1f, 0f, 0f)));
        Assert.StartsWith("body.motion", ex.Message);
        var bad = Assert.ThrowsAny<ArgumentException>(() => engine.Step(obj, double.NaN));
        Assert.StartsWith("elapsed", bad.Message);
        Assert.Equal(before, (obj.State, obj.Body));
    }

    [Fact]
    public void SteppingAnObject_AllocatesNothing_OnceWarm()
    {
        var engine = new PhysicsEngine(TestGeometry.FlatWorld());
        var start = MoverState.OnFloor(TestGeometry.At(100, 40, 0), 0f);
        var obj = new PhysicsObject(MoverDescription.Player(), start, BodyState.Creature());
        void Round()
        {
            obj.State = start;
            obj.Body = BodyState.Creature();
            for (int f = 0; f < 60; f++)
                engine.Step(obj, 1.0 / 60, new Vector3(0f, 5f, 0f));
        }
        Assert.Equal(0, Allocations.PerRound(Round, Round));
    }

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));
}
