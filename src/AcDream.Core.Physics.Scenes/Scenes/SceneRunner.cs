using System;
using System.Collections.Generic;
using System.Reflection;
using AcDream.Core.Physics.Diagnostics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Runs a scene: every mover, alone, frame by frame through one <see cref="PhysicsEngine"/>, each frame
/// requesting the mover's current position plus that frame's offset (same cell label and orientation),
/// as a client's per-frame motion would; a body mover's frames go through <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in AcDream.Core.Physics.BodyState, double, System.Numerics.Vector3, float)"/>
/// with its elapsed time, desired motion and jump.
/// </summary>
public static class SceneRunner
{
    /// <summary>The library's informational version (written into trajectory headers).</summary>
    public static string LibraryVersion { get; } =
        typeof(SceneRunner).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion
        ?? typeof(SceneRunner).Assembly.GetName().Version?.ToString() ?? "unknown";

    /// <summary>Runs every mover of the scene and records the trajectory.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="diagnostics">When set, a <see cref="TransitionEventLog"/> is attached and this is called after every frame with its events.</param>
    public static Trajectory Run(Scene scene, Action<FrameDiagnostics>? diagnostics = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        var engine = new PhysicsEngine(scene.World);
        TransitionEventLog? log = diagnostics is null ? null : new TransitionEventLog();
        engine.Observer = log;
        var movers = new List<MoverTrajectory>(scene.Movers.Count);
        for (int m = 0; m < scene.Movers.Count; m++)
        {
            var mover = scene.Movers[m];
            var frames = new List<TrajectoryFrame>(mover.FrameCount);
            var state = mover.Start;
            var body = mover.StartBody;
            var motion = mover.Commands?.Start(mover.Description, state, ref body, Earlier(scene, movers));
            var missile = Launch(mover);
            for (int f = 0; f < mover.FrameCount; f++)
            {
                SceneStep? step = null;
                var target = state.Position;
                if (mover.IsBody)
                    step = mover.Steps[f];
                else
                    target.Frame.Origin += mover.Motion[f];
                try
                {
                    frames.Add(Advance(engine, mover.Description, step, target, ref state, ref body, motion, f, missile));
                }
                catch (ArgumentException ex)
                {
                    throw Refused(mover, f, ex);
                }
                catch (SceneFormatException ex)
                {
                    throw new SceneFormatException(ex.JsonPath, $"mover \"{mover.Name}\", frame {f}: {ex.Detail}", ex);
                }
                if (log is not null)
                {
                    diagnostics!(new FrameDiagnostics(m, mover.Name, f, log.Events));
                    log.Clear();
                }
            }
            movers.Add(new MoverTrajectory(mover.Name, frames));
        }
        return new Trajectory(scene.Name, scene.Sha256, LibraryVersion, movers);
    }

    /// <summary>The movers run so far with their frames (what a StickTo command follows).</summary>
    internal static List<(SceneMover, IReadOnlyList<TrajectoryFrame>)> Earlier(Scene scene, IReadOnlyList<MoverTrajectory> done, int count = -1)
    {
        if (count < 0)
            count = done.Count;
        var list = new List<(SceneMover, IReadOnlyList<TrajectoryFrame>)>(count);
        for (int i = 0; i < count; i++)
            list.Add((scene.Movers[i], done[i].Frames));
        return list;
    }

    /// <summary>
    /// One frame of a mover: a body step when <paramref name="step"/> is given, else a move to
    /// <paramref name="target"/>. Advances <paramref name="state"/> (and <paramref name="body"/>) only when the
    /// engine accepts the input; its <see cref="ArgumentException"/> otherwise passes through.
    /// </summary>
    internal static TrajectoryFrame Advance(PhysicsEngine engine, MoverDescription description, SceneStep? step, in Position target,
        ref MoverState state, ref BodyState body, SceneMotion.Cursor? motion = null, int frame = 0, Missile? missile = null)
    {
        if (step is { } m && missile is not null)
        {
            var flown = engine.Step(missile, m.Elapsed);
            state = missile.State;
            body = missile.Body;
            return TrajectoryFrame.From(m, flown);
        }
        if (step is { } s)
        {
            var stepped = motion is null
                ? engine.Step(description, state, body, s.Elapsed, s.DesiredVelocity, s.JumpVelocity)
                : StepMotion(engine, description, s.Elapsed, ref state, ref body, motion, frame);
            state = stepped.Next;
            body = stepped.Body;
            return TrajectoryFrame.From(s, stepped, motion?.Motion);
        }
        var result = engine.Resolve(description, state, target);
        state = result.Next;
        return TrajectoryFrame.From(target, result);
    }

    /// <summary>A missile mover's <see cref="Missile"/> at its start (airborne, with its start body), or null for any other mover.</summary>
    internal static Missile? Launch(SceneMover mover)
    {
        if (!mover.IsMissile)
            return null;
        try
        {
            return new Missile(mover.Description, mover.Start.Position, mover.StartBody);
        }
        catch (ArgumentException ex)
        {
            throw Refused(mover, 0, ex);
        }
    }

    /// <summary>A motion mover's frame: that frame's commands are given, then the body steps through the motion layer.</summary>
    internal static BodyStepResult StepMotion(PhysicsEngine engine, MoverDescription description, double elapsed, ref MoverState state,
        ref BodyState body, SceneMotion.Cursor motion, int frame)
    {
        motion.Give(frame, description, ref state, ref body);
        return engine.Step(description, state, body, motion.Motion, elapsed);
    }

    /// <summary>
    /// Input the engine refused while a scene ran, as a <see cref="SceneFormatException"/> naming the JSON
    /// path it came from: the mover (its start state, on the first frame) or the motion or step item of that
    /// frame, and the mover and frame.
    /// </summary>
    private static SceneFormatException Refused(SceneMover mover, int frame, ArgumentException ex)
    {
        bool startState = frame == 0 && (ex.Message.StartsWith("state.", StringComparison.Ordinal) || ex.Message.StartsWith("body.", StringComparison.Ordinal));
        string path = startState ? mover.Path : mover.FramePath(frame);
        var wrapped = SceneFormatException.Wrap(path, ex);
        return new SceneFormatException(path, $"mover \"{mover.Name}\", frame {frame}: {wrapped.Detail}", ex);
    }
}
