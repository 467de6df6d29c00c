using AcDream.Core.Physics.Shapes;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>A body stepped frame by frame through a world at a fixed frame time: the apparatus side of the body tests.</summary>
internal sealed class BodyDriver
{
    private readonly PhysicsEngine _engine;

    public BodyDriver(PhysicsWorld world, MoverDescription description, MoverState state, BodyState body)
    {
        _engine = new PhysicsEngine(world);
        Description = description;
        State = state;
        Body = body;
    }

    public MoverDescription Description { get; }
    public MoverState State { get; private set; }
    public BodyState Body { get; private set; }
    public Vector3 Origin => State.Position.Origin;
    /// <summary>Seconds handed to the engine so far.</summary>
    public double Time { get; private set; }
    public List<Sample> Samples { get; } = new();

    public sealed record Sample(double Time, Vector3 Origin, Vector3 Velocity, bool Contact, bool OnWalkable, int Quanta, BodyStepResult Result, uint[] Collided);

    public BodyStepResult Step(double dt, Vector3 desired, float jump = 0f)
    {
        var r = _engine.Step(Description, State, Body, dt, desired, jump);
        State = r.Next;
        Body = r.Body;
        Time += dt;
        Samples.Add(new Sample(Time, Origin, Body.Velocity, State.Contact, State.OnWalkable, r.Quanta, r, r.Move.CollidedObjects.ToArray()));
        return r;
    }

    /// <summary>Steps until <paramref name="until"/> holds after a frame (or <paramref name="maxSeconds"/> pass); returns the frame's sample.</summary>
    public Sample RunUntil(double dt, Vector3 desired, Func<Sample, bool> until, double maxSeconds = 10)
    {
        while (Time < maxSeconds)
        {
            Step(dt, desired);
            if (until(Samples[^1]))
                return Samples[^1];
        }
        throw new Xunit.Sdk.XunitException($"the condition did not hold within {maxSeconds} s; last sample {Samples[^1]}");
    }

    /// <summary>A static box registered in <paramref name="world"/>.</summary>
    public static void AddBox(PhysicsWorld world, uint id, Vector3 min, Vector3 max)
    {
        var centre = new Vector3((min.X + max.X) / 2, (min.Y + max.Y) / 2, 0);
        var model = new PhysicsModel(TestGeometry.BoxTree(min - centre, max - centre), name: "box");
        var setup = new PhysicsSetup { Parts = [new SetupPart(model, Frame.Identity)] };
        world.Objects.Register(id, setup, TestGeometry.At(centre.X, centre.Y, 0), 1f, PhysicsState.Static);
    }

    /// <summary>The retail player's spheres and step-up without EdgeSlide, so it walks off ledges; step-down as given.</summary>
    public static MoverDescription Runner(float stepDown) =>
        new(0x50000005, MoverDescription.Player().Spheres, 0.6f, stepDown, PhysicsState.Gravity, ObjectInfoState.IsPlayer);
}
