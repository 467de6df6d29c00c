using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.Tests.Support;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>A retail player with the synthetic humanoid table standing on flat ground at (60, 60, 0), stepped at 30 Hz.</summary>
internal sealed class MotionRig
{
    public readonly PhysicsEngine Engine;
    public readonly MoverDescription Mover = MoverDescription.Player(stepDownHeight: 0.04f);
    public readonly ObjectMotion Motion;
    public MoverState State;
    public BodyState Body = BodyState.Creature();

    public MotionRig(int runSkill = 200, int jumpSkill = 200) : this(TestGeometry.FlatWorld(), 60f, 60f, runSkill, jumpSkill) { }

    /// <summary>The same player in <paramref name="world"/>, standing at (x, y, 0).</summary>
    public MotionRig(PhysicsWorld world, float x, float y, int runSkill = 200, int jumpSkill = 200)
    {
        Engine = new PhysicsEngine(world);
        State = MoverState.OnFloor(TestGeometry.At(x, y, 0f), 0f);
        Motion = new ObjectMotion(MotionTables.Humanoid(), new RetailSkills(runSkill, jumpSkill));
        Motion.Place(Mover, State, ref Body);
    }

    public MotionError Do(uint motion, HoldKey hold = HoldKey.None, float speed = 1f) =>
        Motion.DoMotion(motion, new MotionParameters(speed, hold), Mover, ref State, ref Body);

    public MotionError Stop(uint motion, HoldKey hold = HoldKey.None) =>
        Motion.StopMotion(motion, new MotionParameters(1f, hold), Mover, ref State, ref Body);

    public MotionError Jump(float extent, bool staminaOk = true)
    {
        var charge = Motion.ChargeJump(Mover, State, Body);
        return charge != MotionError.None ? charge : Motion.Jump(extent, staminaOk, Mover, ref State, ref Body);
    }

    public void Frames(int count)
    {
        for (int i = 0; i < count; i++)
        {
            var r = Engine.Step(Mover, State, Body, Motion, 1.0 / 30.0);
            State = r.Next;
            Body = r.Body;
        }
    }

    public Vector3 Origin => State.Position.Frame.Origin;

    /// <summary>The heading, radians, counter-clockwise about +z from +Y.</summary>
    public double Heading
    {
        get
        {
            var forward = Vector3.Transform(Vector3.UnitY, State.Position.Frame.Orientation);
            return Math.Atan2(-forward.X, forward.Y);
        }
    }
}
