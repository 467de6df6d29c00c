using AcDream.Core.Physics.Diagnostics;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>A mover walked frame by frame through a world: the apparatus side of the tests.</summary>
internal sealed class Mover
{
    private PhysicsEngine _engine;
    private readonly PhysicsWorld _world;

    public Mover(PhysicsWorld world, MoverDescription description, MoverState start)
    {
        _world = world;
        _engine = new PhysicsEngine(world);
        Description = description;
        State = start;
    }

    public MoverDescription Description { get; }
    public MoverState State { get; private set; }
    public Vector3 Origin => State.Position.Origin;
    public List<Frame> Frames { get; } = new();
    public TransitionEventLog? Log { get; private set; }

    /// <summary>Moves through an engine taking <paramref name="shortcuts"/> (for the tests of a shortcut itself, whatever the run's mode).</summary>
    public Mover With(Shortcuts shortcuts)
    {
        _engine = new PhysicsEngine(_world, shortcuts) { Observer = Log };
        return this;
    }

    public Mover WithLog()
    {
        Log = new TransitionEventLog();
        _engine.Observer = Log;
        return this;
    }

    public sealed record Frame(Vector3 Before, Vector3 Requested, Vector3 After, uint Cell, MoveResult Result, uint[] Collided);

    /// <summary>Requests the mover's origin + offset (same cell label, same orientation) and applies the result.</summary>
    public MoveResult Step(Vector3 offset)
    {
        var target = State.Position;
        target.Frame.Origin += offset;
        var before = Origin;
        var result = _engine.Resolve(Description, State, target);
        State = result.Next;
        Frames.Add(new Frame(before, offset, Origin, State.Position.CellId, result, result.CollidedObjects.ToArray()));
        return result;
    }

    private float _verticalSpeed;

    /// <summary>
    /// One frame as a client drives it: the walk offset plus gravity's fall while the mover is not standing
    /// on walkable ground (the transition itself knows no velocity).
    /// </summary>
    public MoveResult StepWithGravity(Vector3 walk, float dt)
    {
        if (State.Contact && State.OnWalkable)
            _verticalSpeed = 0f;
        else
            _verticalSpeed += PhysicsConstants.Gravity * dt;
        var result = Step(walk + new Vector3(0, 0, _verticalSpeed * dt));
        if (result.Next.Contact && result.Next.OnWalkable)
            _verticalSpeed = 0f;
        return result;
    }

    public void Walk(Vector3 offsetPerFrame, int frames)
    {
        for (int i = 0; i < frames; i++)
            Step(offsetPerFrame);
    }
}
