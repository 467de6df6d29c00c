using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Drawing a body with even motion (not retail; the physics is untouched). <see cref="BodyStepResult.SmoothPose"/>
/// is retail's pose blended between quanta, and it inherits how the motion layer moves a body: an animation's root
/// motion is applied in whole animation frames, so each quantum carries two or three of them and a steady 9.5 m/s run
/// drawn at 144 Hz steps 0.040 to 0.084 m from one frame to the next (docs/performance.md, "Drawing: even frames").
/// An <see cref="EvenFrames"/>, one per drawn body, follows that pose through two equal first-order lags in a row (a
/// critically damped follower): the drawn origin trails the retail pose by <see cref="Lag"/> seconds of travel at a
/// steady speed and steps evenly, the uneven quanta filtered out; it comes to rest where the body rests, without
/// overshoot. The orientation is the retail pose's, unfiltered. A jump of more than <see cref="SnapDistance"/> (a
/// teleport, a blip) is drawn at once. Plain arithmetic (no exponentials), so the same on every platform.
/// </summary>
public sealed class EvenFrames
{
    private Vector3 _first, _drawn;
    private uint _cellId;
    private bool _started;

    /// <summary>A follower with the given lag and snap distance.</summary>
    /// <param name="lag">
    /// Seconds the drawn origin trails the retail pose at a steady speed (default 0.2 s: 1.9 m at a 9.5 m/s run). Each of
    /// the two stages lags half of it. Less lag draws less evenly: at a steady 9.5 m/s run drawn at 144 Hz the step per
    /// frame stays within about ±12 % of its mean with 0.05 s, ±5 % with 0.1 s, ±2 % with 0.2 s, ±1 % with 0.3 s
    /// (retail's pose: −33 % to +26 %).
    /// </param>
    /// <param name="snapDistance">A retail pose farther than this (metres, default 5) from the drawn one is drawn at once.</param>
    /// <exception cref="ArgumentOutOfRangeException">A lag not in (0, 2] s or a snap distance not finite and positive, named.</exception>
    public EvenFrames(float lag = 0.2f, float snapDistance = 5f)
    {
        if (!(lag > 0f && lag <= 2f))
            throw new ArgumentOutOfRangeException(nameof(lag), lag, "lag: seconds, more than 0 and at most 2.");
        if (!(snapDistance > 0f && snapDistance < float.PositiveInfinity))
            throw new ArgumentOutOfRangeException(nameof(snapDistance), snapDistance, "snapDistance: metres, finite and more than 0.");
        Lag = lag;
        SnapDistance = snapDistance;
    }

    /// <summary>Seconds the drawn origin trails the retail pose at a steady speed.</summary>
    public float Lag { get; }

    /// <summary>Metres: a retail pose farther than this from the drawn one is drawn at once.</summary>
    public float SnapDistance { get; }

    /// <summary>The pose to draw after <paramref name="step"/>, which took <paramref name="elapsed"/> seconds.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A negative or non-finite <paramref name="elapsed"/>, named.</exception>
    public Frame Draw(in BodyStepResult step, double elapsed) => Draw(step.SmoothPose, step.Next.Position.CellId, elapsed);

    /// <summary>
    /// The pose to draw for the retail pose <paramref name="pose"/>, in the landblock space of <paramref name="cellId"/>
    /// (as <see cref="BodyStepResult.SmoothPose"/> is, in its step's cell), <paramref name="elapsed"/> seconds after the
    /// last call. The drawn pose is in the same landblock space.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">A negative or non-finite <paramref name="elapsed"/>, named.</exception>
    public Frame Draw(in Frame pose, uint cellId, double elapsed)
    {
        if (!(elapsed >= 0.0 && elapsed < double.PositiveInfinity))
            throw new ArgumentOutOfRangeException(nameof(elapsed), elapsed, "elapsed: seconds, finite and not negative.");
        if (_started)
        {
            // Both stages move into the new landblock's space with the body (the same point, other coordinates).
            var shift = LandDefs.BlockOffset(cellId, _cellId);
            _first += shift;
            _drawn += shift;
        }
        _cellId = cellId;
        if (!_started || Vector3.DistanceSquared(pose.Origin, _drawn) > SnapDistance * SnapDistance)
        {
            Reset(pose.Origin);
            return pose;
        }
        // Each stage moves a share elapsed / (tau + elapsed) of the way to its input: the backward-Euler step of a lag
        // of tau, stable at any frame time (a long frame moves it most of the way, never past).
        float tau = Lag * 0.5f;
        float share = (float)(elapsed / (tau + elapsed));
        _first += (pose.Origin - _first) * share;
        _drawn += (_first - _drawn) * share;
        return new Frame(_drawn, pose.Orientation);
    }

    /// <summary>Forgets the past: the next <see cref="Draw(in Frame, uint, double)"/> draws its pose as it is.</summary>
    public void Reset() => _started = false;

    private void Reset(Vector3 origin)
    {
        _first = origin;
        _drawn = origin;
        _started = true;
    }
}
