using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Diagnostics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Re-runs a recorded trajectory: for every mover, from the scene's start state, each frame's recorded
/// target is resolved again and the outputs are compared with the recording; the first difference is
/// reported. Positions, planes and vectors compare within a tolerance (metres; default 1e-5); flags,
/// cells and object ids compare exactly.
/// </summary>
public static class TrajectoryReplay
{
    /// <summary>The default tolerance for positions, plane distances and vector components.</summary>
    public const float DefaultTolerance = 1e-5f;

    /// <summary>Replays a trajectory against its scene.</summary>
    /// <param name="scene">The scene the trajectory was recorded from (its SHA-256 must match the header's).</param>
    /// <param name="trajectory">The recording.</param>
    /// <param name="tolerance">The tolerance for lengths and vector components.</param>
    /// <param name="diagnostics">When set, a <see cref="TransitionEventLog"/> is attached and this is called after every re-run frame with its events.</param>
    public static ReplayResult Replay(Scene scene, Trajectory trajectory, float tolerance = DefaultTolerance, Action<FrameDiagnostics>? diagnostics = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(trajectory);
        if (!(tolerance >= 0f) || !float.IsFinite(tolerance))
            throw new ArgumentException($"tolerance: must be a finite number of zero or more, got {tolerance}.", nameof(tolerance));
        var notes = new List<string>();
        if (trajectory.LibraryVersion != SceneRunner.LibraryVersion)
            notes.Add($"recorded with library {trajectory.LibraryVersion}, replayed with {SceneRunner.LibraryVersion}");
        if (!string.Equals(trajectory.SceneSha256, scene.Sha256, StringComparison.OrdinalIgnoreCase))
            return Fail(new ReplayDifference("", -1, "sceneSha256", trajectory.SceneSha256, scene.Sha256), 0, tolerance, notes);
        if (trajectory.Movers.Count != scene.Movers.Count)
            return Fail(new ReplayDifference("", -1, "movers.count", Str(trajectory.Movers.Count), Str(scene.Movers.Count)), 0, tolerance, notes);

        var engine = new PhysicsEngine(scene.World);
        TransitionEventLog? log = diagnostics is null ? null : new TransitionEventLog();
        engine.Observer = log;
        int compared = 0;
        for (int m = 0; m < scene.Movers.Count; m++)
        {
            var mover = scene.Movers[m];
            var recorded = trajectory.Movers[m];
            if (recorded.Name != mover.Name)
                return Fail(new ReplayDifference(mover.Name, -1, "name", recorded.Name, mover.Name), compared, tolerance, notes);
            if (recorded.Frames.Count != mover.FrameCount)
                return Fail(new ReplayDifference(mover.Name, -1, "frames.count", Str(recorded.Frames.Count), Str(mover.FrameCount)), compared, tolerance, notes);
            var state = mover.Start;
            var body = mover.StartBody;
            // A StickTo follows the earlier movers' recorded frames (compared equal before this mover is replayed).
            var motion = mover.Commands?.Start(mover.Description, state, ref body, SceneRunner.Earlier(scene, trajectory.Movers, m));
            Missile? missile;
            try
            {
                missile = SceneRunner.Launch(mover);
            }
            catch (SceneFormatException ex)
            {
                return Fail(new ReplayDifference(mover.Name, 0, "step", "a valid input", ex.Message), compared, tolerance, notes);
            }
            for (int f = 0; f < recorded.Frames.Count; f++)
            {
                var expected = recorded.Frames[f];
                if (mover.IsBody != expected.Step.HasValue)
                    return Fail(new ReplayDifference(mover.Name, f, "step", mover.IsBody ? "a body step" : "a target",
                        expected.Step.HasValue ? "a body step" : "a target"), compared, tolerance, notes);
                TrajectoryFrame actual;
                try
                {
                    actual = SceneRunner.Advance(engine, mover.Description, expected.Step, expected.Target, ref state, ref body, motion, f, missile);
                }
                catch (ArgumentException ex)
                {
                    return Fail(new ReplayDifference(mover.Name, f, expected.Step.HasValue ? "step" : "target", "a valid input", ex.Message), compared, tolerance, notes);
                }
                catch (SceneFormatException ex)
                {
                    return Fail(new ReplayDifference(mover.Name, f, "step", "a valid input", ex.Message), compared, tolerance, notes);
                }
                if (log is not null)
                {
                    diagnostics!(new FrameDiagnostics(m, mover.Name, f, log.Events));
                    log.Clear();
                }
                var difference = Compare(mover.Name, f, expected, actual, tolerance);
                if (difference is not null)
                    return Fail(difference, compared, tolerance, notes);
                compared++;
            }
        }
        return new ReplayResult(null, compared, tolerance, notes);
    }

    private static ReplayResult Fail(ReplayDifference d, int compared, float tolerance, List<string> notes) => new(d, compared, tolerance, notes);

    private static string Str(int v) => v.ToString(CultureInfo.InvariantCulture);
    private static string Str(float v) => v.ToString("R", CultureInfo.InvariantCulture);
    private static string Str(bool v) => v ? "true" : "false";
    private static string Hex(uint v) => $"0x{v:X8}";

    /// <summary>The first field of <paramref name="actual"/> that differs from <paramref name="expected"/>, in file order.</summary>
    internal static ReplayDifference? Compare(string mover, int frame, TrajectoryFrame expected, TrajectoryFrame actual, float tolerance)
    {
        ReplayDifference? D(string field, string e, string a) => new(mover, frame, field, e, a);
        ReplayDifference? Vec(string field, Vector3 e, Vector3 a)
        {
            if (Near(e.X, a.X)) { } else return D(field + ".x", Str(e.X), Str(a.X));
            if (Near(e.Y, a.Y)) { } else return D(field + ".y", Str(e.Y), Str(a.Y));
            if (Near(e.Z, a.Z)) { } else return D(field + ".z", Str(e.Z), Str(a.Z));
            return null;
        }
        bool Near(float e, float a) => MathF.Abs(e - a) <= tolerance || e == a;

        return Vec("position", expected.Position, actual.Position)
            ?? (expected.Cell != actual.Cell ? D("cell", Hex(expected.Cell), Hex(actual.Cell)) : null)
            ?? (expected.Contact != actual.Contact ? D("contact", Str(expected.Contact), Str(actual.Contact)) : null)
            ?? (expected.OnWalkable != actual.OnWalkable ? D("onWalkable", Str(expected.OnWalkable), Str(actual.OnWalkable)) : null)
            ?? (expected.ContactPlaneValid != actual.ContactPlaneValid ? D("contactPlane.valid", Str(expected.ContactPlaneValid), Str(actual.ContactPlaneValid)) : null)
            ?? Vec("contactPlane.normal", expected.ContactPlane.Normal, actual.ContactPlane.Normal)
            ?? (!Near(expected.ContactPlane.D, actual.ContactPlane.D) ? D("contactPlane.d", Str(expected.ContactPlane.D), Str(actual.ContactPlane.D)) : null)
            ?? (expected.ContactPlaneCell != actual.ContactPlaneCell ? D("contactPlane.cell", Hex(expected.ContactPlaneCell), Hex(actual.ContactPlaneCell)) : null)
            ?? (expected.CollisionNormalValid != actual.CollisionNormalValid ? D("collisionNormal.valid", Str(expected.CollisionNormalValid), Str(actual.CollisionNormalValid)) : null)
            ?? Vec("collisionNormal.vector", expected.CollisionNormal, actual.CollisionNormal)
            ?? (expected.SlidingNormalValid != actual.SlidingNormalValid ? D("slidingNormal.valid", Str(expected.SlidingNormalValid), Str(actual.SlidingNormalValid)) : null)
            ?? Vec("slidingNormal.vector", expected.SlidingNormal, actual.SlidingNormal)
            ?? (!SameIds(expected.CollidedObjects, actual.CollidedObjects) ? D("collided", Ids(expected.CollidedObjects), Ids(actual.CollidedObjects)) : null)
            ?? (expected.Succeeded != actual.Succeeded ? D("succeeded", Str(expected.Succeeded), Str(actual.Succeeded)) : null)
            ?? (expected.Step is null ? null
                : Vec("body.velocity", expected.Velocity, actual.Velocity)
                ?? (expected.Quanta != actual.Quanta ? D("body.quanta", Str(expected.Quanta), Str(actual.Quanta)) : null))
            ?? CompareMotion(expected.Motion, actual.Motion)
            ?? (expected.Hit != actual.Hit ? D("hit", HitText(expected.Hit), HitText(actual.Hit)) : null);

        static string HitText(TrajectoryHit? h) => h is { } v ? $"{v.Kind} 0x{v.ObjectId:X8} in quantum {v.Quantum}" : "none";

        ReplayDifference? CompareMotion(TrajectoryMotion? e, TrajectoryMotion? a)
        {
            if (e is null || a is null)
                return e is null == a is null ? null : D("motion", e is null ? "none" : "a motion frame", a is null ? "none" : "a motion frame");
            var (er, ar) = (e.Value.Rotation, a.Value.Rotation);
            var (ei, ai) = (e.Value.Interpreted, a.Value.Interpreted);
            ReplayDifference? Command(string field, uint ec, uint ac, float es, float @as) =>
                ec != ac ? D($"motion.{field}.command", MotionCommandNames.Name(ec), MotionCommandNames.Name(ac))
                : !Near(es, @as) ? D($"motion.{field}.speed", Str(es), Str(@as)) : null;
            return (!Near(er.W, ar.W) ? D("motion.rotation.w", Str(er.W), Str(ar.W)) : null)
                ?? Vec("motion.rotation", new Vector3(er.X, er.Y, er.Z), new Vector3(ar.X, ar.Y, ar.Z))
                ?? (ei.Style != ai.Style ? D("motion.style", Hex(ei.Style), Hex(ai.Style)) : null)
                ?? Command("forward", ei.ForwardCommand, ai.ForwardCommand, ei.ForwardSpeed, ai.ForwardSpeed)
                ?? Command("sideStep", ei.SideStepCommand, ai.SideStepCommand, ei.SideStepSpeed, ai.SideStepSpeed)
                ?? Command("turn", ei.TurnCommand, ai.TurnCommand, ei.TurnSpeed, ai.TurnSpeed);
        }
    }

    private static bool SameIds(IReadOnlyList<uint> a, IReadOnlyList<uint> b)
    {
        if (a.Count != b.Count) return false;
        for (int i = 0; i < a.Count; i++)
            if (a[i] != b[i]) return false;
        return true;
    }

    private static string Ids(IReadOnlyList<uint> ids)
    {
        var parts = new List<string>(ids.Count);
        foreach (uint id in ids) parts.Add(Hex(id));
        return "[" + string.Join(", ", parts) + "]";
    }
}
