using System;

namespace AcDream.Core.Physics;

/// <summary>
/// One moving body in one object (retail's CPhysicsObj): what it is (<see cref="Description"/>), where it is and how
/// it stands (<see cref="State"/>), its velocity and carried time (<see cref="Body"/>), and, for a player or creature
/// with a motion table, its motion layer (<see cref="Motion"/>). <see cref="PhysicsEngine.Step(PhysicsObject, double)"/>
/// steps it and keeps the outcome in it; the step's result says what happened, how far it moved
/// (<see cref="BodyStepResult.Displacement"/>) and how fast (<see cref="BodyStepResult.Speed"/>).
/// </summary>
/// <remarks>
/// A server that keeps its bodies in arrays of structs calls the struct-level steps instead
/// (<c>engine.Step(description, state, body, …)</c>): this object holds the same values and its steps give the same
/// results bit for bit. <see cref="State"/> and <see cref="Body"/> are fields so that the motion commands, which take
/// them by reference, can be given them directly: <c>motion.DoMotion(command, parameters, obj.Description, ref obj.State, ref obj.Body)</c>.
/// Not thread-safe: one object is stepped by one engine at a time.
/// </remarks>
public sealed class PhysicsObject
{
    private MoverDescription _description;

    /// <summary>Where the body is and how it stands; the engine writes the step's <see cref="BodyStepResult.Next"/> here.</summary>
    public MoverState State;

    /// <summary>Its velocity, spin, friction, elasticity and carried time; the engine writes the step's <see cref="BodyStepResult.Body"/> here.</summary>
    public BodyState Body;

    /// <summary>A body from its parts; nothing is checked against a world until its first step.</summary>
    /// <param name="description">What it is.</param>
    /// <param name="state">Where it is (for example <c>engine.Place(description, position).Next</c>).</param>
    /// <param name="body">Its velocity, friction and elasticity (<see cref="BodyState.Creature"/> for a player or creature).</param>
    /// <param name="motion">Its motion layer, for a player or creature moved by motion commands; null for a body without a motion table.</param>
    public PhysicsObject(MoverDescription description, in MoverState state, in BodyState body, ObjectMotion? motion = null)
    {
        ArgumentNullException.ThrowIfNull(description);
        _description = description;
        State = state;
        Body = body;
        Motion = motion;
    }

    /// <summary>What the body is; may be replaced between steps (a description is immutable: <see cref="MoverDescription.With"/> makes the changed copy).</summary>
    public MoverDescription Description
    {
        get => _description;
        set
        {
            ArgumentNullException.ThrowIfNull(value, nameof(Description));
            _description = value;
        }
    }

    /// <summary>The motion layer that moves it (motion commands are given to it between steps), or null.</summary>
    public ObjectMotion? Motion { get; }

    /// <summary>Where it is (<see cref="MoverState.Position"/> of <see cref="State"/>).</summary>
    public Position Position => State.Position;
}
