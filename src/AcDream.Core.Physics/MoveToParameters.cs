using System;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// Retail's MovementParameters for a MoveTo or a turn (CMovementDefs, acclient.c:339436 for the defaults):
/// <see cref="Default"/> is retail's constructor. Distances in metres, headings in compass degrees
/// (0 facing +Y, 90 facing +X).
/// </summary>
public readonly record struct MoveToParameters
{
    /// <summary>Retail's defaults: <see cref="MoveToFlags.RetailDefault"/>, distance to object 0.6 m, min distance 0, fail distance float.MaxValue (none), speed 1, walk/run threshold 15 m, heading 0, hold key Invalid.</summary>
    public static MoveToParameters Default => new();

    /// <summary>Retail's defaults (see <see cref="Default"/>).</summary>
    public MoveToParameters() { }

    /// <summary>The bitfield.</summary>
    public MoveToFlags Flags { get; init; } = MoveToFlags.RetailDefault;
    /// <summary>distance_to_object: arrived when the distance is at most this (default 0.6 m, 0x3F19999A).</summary>
    public float DistanceToObject { get; init; } = 0.6f;
    /// <summary>min_distance: moving away ends when the distance is at least this (default 0).</summary>
    public float MinDistance { get; init; }
    /// <summary>fail_distance: the move fails (<see cref="MoveToError.YouChargedTooFar"/>) once the mover is farther than this from where it started (default float.MaxValue: never).</summary>
    public float FailDistance { get; init; } = float.MaxValue;
    /// <summary>desired_heading: the heading of a TurnToHeading, or the final heading with <see cref="MoveToFlags.UseFinalHeading"/> (default 0, facing +Y).</summary>
    public float DesiredHeading { get; init; }
    /// <summary>
    /// speed: the motion commands' speed (default 1; more than 0, at most 100). A move arrives when a quantum ends within
    /// the arrival distance (<see cref="DistanceToObject"/>, from the mover's cylinder with UseSpheres): retail's
    /// HandleMoveToPosition (acclient.c:345576) tests the distance only after each quantum. So a straight run arrives
    /// for certain while one quantum's step (the run speed, 4 m/s × run rate × speed, times the quantum) is at most twice
    /// that distance: with the retail player (radius 0.48 m), the default 0.6 m, run rate 2.375 and 30 quanta a second,
    /// up to Speed 6.8. Faster, retail's behaviour is kept: a runner whose steps fall past the band is turned back by the
    /// aim correction and, under the client's <see cref="MoveToProgressRule.CountOnly"/>, circles the target for ever
    /// (at Speed 100 it steps 31.7 m a quantum); a caller that moves that fast sets a larger DistanceToObject.
    /// </summary>
    public float Speed { get; init; } = 1f;
    /// <summary>
    /// walk_run_threshhold: with CanWalk and CanRun, the mover runs when the distance beyond <see cref="DistanceToObject"/>
    /// is more than this. Retail's constructor sets 15 m (0x41700000, acclient.c:339436); ACE's sets 1 m.
    /// </summary>
    public float WalkRunThreshold { get; init; } = 15f;
    /// <summary>hold_key_to_apply for the turn of a TurnToHeading (default <see cref="HoldKey.Invalid"/>: the interpreter's current hold key; a move decides its own: Run or None).</summary>
    public HoldKey HoldKey { get; init; } = HoldKey.Invalid;

    internal bool Has(MoveToFlags f) => (Flags & f) != 0;

    /// <summary>Throws an <see cref="ArgumentException"/> naming the first field that is not usable; nothing is changed.</summary>
    internal void Check(string name)
    {
        if ((Flags & ~(MoveToFlags)0x3FFFF) != 0)
            throw new ArgumentException($"{name}.Flags: unknown bits 0x{(uint)Flags & ~0x3FFFFu:X}.", name);
        NonNegativeOrMax(DistanceToObject, name, ".DistanceToObject");
        NonNegativeOrMax(MinDistance, name, ".MinDistance");
        if (!(FailDistance >= 0f) || float.IsNaN(FailDistance))
            throw new ArgumentException($"{name}.FailDistance: must be 0 or more (float.MaxValue for none), got {FailDistance}.", name);
        if (!(DesiredHeading >= 0f && DesiredHeading < 360f))
            throw new ArgumentException($"{name}.DesiredHeading: must be a heading in [0, 360) degrees, got {DesiredHeading}.", name);
        if (!(Speed > 0f && Speed <= 100f))
            throw new ArgumentException($"{name}.Speed: must be more than 0 and at most 100, got {Speed}.", name);
        NonNegativeOrMax(WalkRunThreshold, name, ".WalkRunThreshold");
        if (HoldKey is not (HoldKey.Invalid or HoldKey.None or HoldKey.Run))
            throw new ArgumentException($"{name}.HoldKey: must be Invalid, None or Run, got {HoldKey}.", name);
    }

    private static void NonNegativeOrMax(float v, string name, string field)
    {
        if (!(v >= 0f) || float.IsNaN(v) || v > InputLimits.MaxCoordinate)
            throw new ArgumentException($"{name}{field}: must be finite, 0 to {InputLimits.MaxCoordinate}, got {v}.", name);
    }

    /// <summary>
    /// MovementParameters::get_command (acclient.c:346174): the command for the distance (WalkForward towards,
    /// WalkForward away, WalkBackwards, or 0 when there), whether it moves away, and the hold key (Run with
    /// CanCharge, or CanRun when it cannot walk or is more than the walk/run threshold beyond the distance to the object).
    /// </summary>
    internal void GetCommand(float distance, out uint command, out HoldKey key, out bool movingAway)
    {
        command = 0;
        movingAway = false;
        bool away = Has(MoveToFlags.MoveAway), towards = Has(MoveToFlags.MoveTowards);
        if (away && towards)
        {
            // towards_and_away (acclient.c:346152).
            if (distance > DistanceToObject)
                command = MotionCommand.WalkForward;
            else if (distance - MinDistance < PhysicsConstants.Epsilon)
            {
                command = MotionCommand.WalkBackwards;
                movingAway = true;
            }
        }
        else if (away)
        {
            if (distance < MinDistance)
            {
                command = MotionCommand.WalkForward;
                movingAway = true;
            }
        }
        else if (distance > DistanceToObject)
        {
            command = MotionCommand.WalkForward;
        }
        bool run = Has(MoveToFlags.CanCharge)
            || Has(MoveToFlags.CanRun) && (!Has(MoveToFlags.CanWalk) || distance - DistanceToObject > WalkRunThreshold);
        key = run ? HoldKey.Run : HoldKey.None;
    }

    /// <summary>MovementParameters::get_desired_heading (acclient.c:346223): 180 when the command faces away from where it goes, else 0.</summary>
    internal static float DesiredHeadingOffset(uint command, bool movingAway) => command switch
    {
        MotionCommand.RunForward or MotionCommand.WalkForward => movingAway ? 180f : 0f,
        MotionCommand.WalkBackwards => movingAway ? 0f : 180f,
        _ => 0f,
    };
}
