using System.Numerics;

namespace AcDream.Core.Physics.Transitions;

/// <summary>
/// How a move is cut into sub-steps (retail calc_num_steps of the begin-to-end offset), and, when it was
/// worked out before the path was set up, the first sub-step's motion as the carried sliding normal and
/// contact plane constrain it (the first half of adjust_offset). <see cref="Transition.RefusesBeforeFirstStep"/>
/// computes both to decide a refusal; find_transitional_position takes them from here instead of computing
/// them again from the very same inputs (not retail; changes no result).
/// </summary>
/// <remarks>
/// Shortcut <see cref="Shortcuts.StepPlan"/> (not retail; taken in <c>PhysicsEngine.Move</c>). Skips: working
/// out the step count and the first sub-step's constrained motion a second time. Same result: the very same
/// arithmetic on the very same inputs. Proof: the replays and RefusedMoveTests, with shortcuts on and off.
/// </remarks>
internal struct StepPlan
{
    /// <summary>The whole motion, begin to end.</summary>
    public Vector3 Offset;
    /// <summary>The motion of one sub-step.</summary>
    public Vector3 PerStep;
    /// <summary>The number of sub-steps.</summary>
    public int NumSteps;
    /// <summary><see cref="FirstOffset"/> and <see cref="FirstSlidingNormalValid"/> are known.</summary>
    public bool FirstKnown;
    /// <summary>The first sub-step's motion after <see cref="Transition.ConstrainOffset"/>.</summary>
    public Vector3 FirstOffset;
    /// <summary>Whether the sliding normal stays valid after the first sub-step's constraint.</summary>
    public bool FirstSlidingNormalValid;
}
