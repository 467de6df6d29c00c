namespace AcDream.Core.Physics.Body;

/// <summary>The outcome of one <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.Body.BodyState, double, System.Numerics.Vector3, float)"/>: the move, the body's new state, and how many quanta ran.</summary>
public readonly struct BodyStepResult
{
    internal BodyStepResult(MoveResult move, BodyState body, int quanta, bool jumped)
    {
        Move = move;
        Body = body;
        Quanta = quanta;
        Jumped = jumped;
    }

    /// <summary>
    /// The move, as <see cref="PhysicsEngine.Resolve"/> reports one: the mover's next state, and what the
    /// step's transitions touched. Over several quanta the collided objects are gathered in order without
    /// repeats, the collision normal is the last one recorded, and <see cref="MoveResult.Succeeded"/> is
    /// false when any quantum's transition was refused. With no quantum run it is an unchanged success.
    /// </summary>
    public MoveResult Move { get; }

    /// <summary>The body's state for the next call.</summary>
    public BodyState Body { get; }

    /// <summary>The mover's state for the next call (<see cref="MoveResult.Next"/>).</summary>
    public MoverState Next => Move.Next;

    /// <summary>
    /// How many quanta were stepped: 0 while less than <see cref="PhysicsConstants.MinQuantum"/> has
    /// gathered or when the elapsed time was dropped (longer than <see cref="PhysicsConstants.HugeQuantum"/>).
    /// </summary>
    public int Quanta { get; }

    /// <summary>The jump was taken (a non-zero jump speed was given and retail's jump_is_allowed held).</summary>
    public bool Jumped { get; }
}
