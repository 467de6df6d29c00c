using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// One frame of one mover: the input (the requested target, or for a body mover the <see cref="SceneStep"/>)
/// and everything the engine resolved (the outputs).
/// </summary>
public sealed class TrajectoryFrame
{
    /// <summary>The requested target position (input of an offset mover's frame; default for a body frame).</summary>
    public Position Target { get; init; }
    /// <summary>A body frame's input (elapsed time, desired motion, jump); null for an offset mover's frame.</summary>
    public SceneStep? Step { get; init; }
    /// <summary>A body frame's velocity after the step (output).</summary>
    public Vector3 Velocity { get; init; }
    /// <summary>How many quanta a body frame stepped (output).</summary>
    public int Quanta { get; init; }
    /// <summary>The resolved origin, landblock-local.</summary>
    public Vector3 Position { get; init; }
    /// <summary>The resolved cell id.</summary>
    public uint Cell { get; init; }
    /// <summary>The mover touches a contact plane.</summary>
    public bool Contact { get; init; }
    /// <summary>The mover stands on walkable ground.</summary>
    public bool OnWalkable { get; init; }
    /// <summary>The contact plane is valid (the mover is in contact with it at the end of the frame).</summary>
    public bool ContactPlaneValid { get; init; }
    /// <summary>The (last known) contact plane.</summary>
    public Plane ContactPlane { get; init; }
    /// <summary>The cell whose landblock space the contact plane is in; 0 when none is known.</summary>
    public uint ContactPlaneCell { get; init; }
    /// <summary>A collision normal was recorded this frame.</summary>
    public bool CollisionNormalValid { get; init; }
    /// <summary>The collision normal.</summary>
    public Vector3 CollisionNormal { get; init; }
    /// <summary>The mover is sliding.</summary>
    public bool SlidingNormalValid { get; init; }
    /// <summary>The sliding normal.</summary>
    public Vector3 SlidingNormal { get; init; }
    /// <summary>The ids of the objects collided with, in the engine's order.</summary>
    public IReadOnlyList<uint> CollidedObjects { get; init; } = Array.Empty<uint>();
    /// <summary>The move was accepted.</summary>
    public bool Succeeded { get; init; }

    /// <summary>A motion mover's frame: its heading and the interpreted state after the step; null for other frames.</summary>
    public TrajectoryMotion? Motion { get; init; }

    /// <summary>A missile's frame in which its hit was reported (<see cref="MissileStepResult.Hit"/>); null for every other frame.</summary>
    public TrajectoryHit? Hit { get; init; }

    /// <summary>Builds a missile's frame from its step's result: a body frame, with the hit when this step reported it.</summary>
    public static TrajectoryFrame From(SceneStep step, in MissileStepResult result)
    {
        var frame = From(step, result.Step);
        var hit = result.Hit;
        return hit.Kind == MissileHitKind.None ? frame : Copy(frame, new TrajectoryHit(hit.Kind, hit.ObjectId, hit.Quantum));
    }

    private static TrajectoryFrame Copy(TrajectoryFrame f, TrajectoryHit hit) => new()
    {
        Target = f.Target, Step = f.Step, Velocity = f.Velocity, Quanta = f.Quanta, Position = f.Position, Cell = f.Cell,
        Contact = f.Contact, OnWalkable = f.OnWalkable, ContactPlaneValid = f.ContactPlaneValid, ContactPlane = f.ContactPlane,
        ContactPlaneCell = f.ContactPlaneCell, CollisionNormalValid = f.CollisionNormalValid, CollisionNormal = f.CollisionNormal,
        SlidingNormalValid = f.SlidingNormalValid, SlidingNormal = f.SlidingNormal, CollidedObjects = f.CollidedObjects,
        Succeeded = f.Succeeded, Motion = f.Motion, Hit = hit,
    };

    /// <summary>Builds a body frame from its input and the engine's result (copies the collided ids).</summary>
    public static TrajectoryFrame From(SceneStep step, in BodyStepResult result) =>
        Build(default, step, result.Body.Velocity, result.Quanta, result.Move);

    /// <summary>Builds a body frame; with <paramref name="motion"/>, a motion mover's frame recording its heading and interpreted state.</summary>
    internal static TrajectoryFrame From(SceneStep step, in BodyStepResult result, ObjectMotion? motion) =>
        Build(default, step, result.Body.Velocity, result.Quanta, result.Move,
            motion is null ? null : new TrajectoryMotion(result.Next.Position.Frame.Orientation, motion.Interpreted));

    /// <summary>Builds a frame from a target and the engine's result (copies the collided ids).</summary>
    public static TrajectoryFrame From(Position target, in MoveResult result) => Build(target, null, default, 0, result);

    private static TrajectoryFrame Build(Position target, SceneStep? step, Vector3 velocity, int quanta, in MoveResult result,
        TrajectoryMotion? motion = null)
    {
        var next = result.Next;
        return new TrajectoryFrame
        {
            Target = target,
            Step = step,
            Velocity = velocity,
            Quanta = quanta,
            Position = next.Position.Origin,
            Cell = next.Position.CellId,
            Contact = next.Contact,
            OnWalkable = next.OnWalkable,
            ContactPlaneValid = next.Contact,
            ContactPlane = next.ContactPlane,
            ContactPlaneCell = next.ContactPlaneCellId,
            CollisionNormalValid = result.CollisionNormalValid,
            CollisionNormal = result.CollisionNormal,
            SlidingNormalValid = next.SlidingNormalValid,
            SlidingNormal = next.SlidingNormal,
            CollidedObjects = result.CollidedObjects.ToArray(),
            Succeeded = result.Succeeded,
            Motion = motion,
        };
    }
}
