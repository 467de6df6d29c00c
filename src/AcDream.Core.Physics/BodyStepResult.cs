using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>The outcome of one <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>: the move, the body's new state, and how many quanta ran.</summary>
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

    /// <summary>
    /// How many of the quanta ran a transition that was accepted (retail SetPositionInternal, and with it
    /// handle_all_collisions, ran): fewer than <see cref="Quanta"/> when a quantum moved the body less than
    /// EPSILON (no transition) or its transition was refused. <see cref="ContactTracker"/> tracks only steps
    /// with one.
    /// </summary>
    public int Transitions { get; internal init; }

    /// <summary>
    /// How much of the next quantum has gathered: <see cref="BodyState.PendingTime"/> /
    /// <see cref="PhysicsConstants.MinQuantum"/>, from 0 to 1. A renderer draws the body that far from
    /// <see cref="BodyState.QuantumStart"/> towards the current position (<see cref="SmoothPose"/>), at most one
    /// quantum behind the physics, so that every frame advances even when no quantum ran.
    /// </summary>
    public float QuantumFraction => (float)Math.Clamp(Body.PendingTime / PhysicsConstants.MinQuantum, 0.0, 1.0);

    /// <summary>
    /// The pose to draw this frame, in the landblock space of the current position's cell:
    /// <see cref="SmoothFrames.Blend"/> of <see cref="BodyState.QuantumStart"/> and the current position by
    /// <see cref="QuantumFraction"/>.
    /// </summary>
    public Frame SmoothPose => SmoothFrames.Blend(Body.QuantumStart, Next.Position, QuantumFraction);

    /// <summary>
    /// How far the body moved in this step, landblock axes of its start position's landblock, metres: the vector from
    /// where the step began to <see cref="Next"/>'s position, across landblocks (<see cref="Position.GetOffset"/>). It
    /// counts every way the body moved, the motion table's root motion too, which <see cref="BodyState.Velocity"/> does
    /// not hold (a running player's velocity is 0), and a blip. Zero when no quantum ran.
    /// </summary>
    public Vector3 Displacement { get; internal init; }

    /// <summary>The seconds the step's quanta covered (the sum of the quanta): 0 when none ran, else up to the elapsed time plus what had gathered.</summary>
    public double SteppedTime { get; internal init; }

    /// <summary>
    /// The body's speed over this step, m/s: the length of <see cref="Displacement"/> over <see cref="SteppedTime"/>,
    /// 0 when no quantum ran (a renderer at a higher rate than the physics' 30 Hz sees it in the frames with
    /// <see cref="Quanta"/> above 0). A body moved by its motion table moves by whole animation frames, so one quantum's
    /// speed jumps around the run's: at run skill 200 (9.5 m/s, 0.1333 m a frame) a 1/30 s quantum crosses 2 or 3
    /// frames, 8 or 12 m/s; summed over a second the displacements give 9.47 m/s (docs/motion-example.md).
    /// </summary>
    public float Speed => SteppedTime > 0 ? (float)(Displacement.Length() / SteppedTime) : 0f;

    /// <summary>The jump was taken (a non-zero jump speed was given and retail's jump_is_allowed held).</summary>
    public bool Jumped { get; }
}
