using System;
using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// A mover of a scene: what it is, where it starts, and for every frame either its requested offset (moved by
/// <see cref="PhysicsEngine.Resolve"/>) or, for a body mover, its elapsed time, desired motion and jump (moved
/// by <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, double, System.Numerics.Vector3, float)"/>),
/// or, for a motion mover (<see cref="IsMotion"/>), its elapsed time and the motion commands given before each step.
/// </summary>
public sealed class SceneMover
{
    private readonly Vector3[] _motion;
    private readonly SceneStep[] _steps;

    internal SceneMover(string name, MoverDescription description, MoverState start, Vector3[] motion)
        : this(name, description, start, motion, [], default) { }

    private readonly int[] _frameItemStarts = [0];

    internal SceneMover(string name, MoverDescription description, MoverState start, Vector3[] motion, SceneStep[] steps, BodyState startBody)
    {
        Name = name;
        Description = description;
        Start = start;
        _motion = motion;
        _steps = steps;
        StartBody = startBody;
    }

    internal SceneMover(string name, MoverDescription description, MoverState start, Vector3[] motion, SceneStep[] steps, BodyState startBody,
        string path, int[] frameItemStarts, SceneMotion? commands = null)
        : this(name, description, start, motion, steps, startBody)
    {
        Path = path;
        _frameItemStarts = frameItemStarts;
        Commands = commands;
        if (commands is not null)
        {
            var reported = new List<Position>();
            foreach (var c in commands.Commands)
                if (c.Kind == SceneCommandKind.InterpolateTo)
                    reported.Add(c.Position);
            _reported = reported.AsReadOnly();
        }
    }

    private readonly IReadOnlyList<Position> _reported = Array.Empty<Position>();

    /// <summary>
    /// The positions the mover's "interpolateTo" commands report (a server's updates that the position manager smooths
    /// towards), in command order; empty for a mover without such commands. Read-only, for showing them beside the path.
    /// </summary>
    public IReadOnlyList<Position> ReportedPositions => _reported;

    /// <summary>A motion mover's table, skills and commands (its steps carry only the elapsed time); null otherwise.</summary>
    internal SceneMotion? Commands { get; }

    /// <summary>The mover is driven by motion commands through a motion table (<see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, ObjectMotion, double)"/>).</summary>
    public bool IsMotion => Commands is not null;

    /// <summary>The mover's JSON path in its scene file (e.g. <c>movers[3]</c>), for error messages.</summary>
    internal string Path { get; } = "movers[0]";

    /// <summary>
    /// The JSON path of the "motion" (or, for a body, "steps") item that produced frame
    /// <paramref name="frame"/>, repeats counted.
    /// </summary>
    internal string FramePath(int frame)
    {
        if (IsMotion)
            return Path;
        int item = Array.BinarySearch(_frameItemStarts, frame);
        if (item < 0)
            item = ~item - 1;
        return $"{Path}.{(IsBody ? "steps" : "motion")}[{item}]";
    }

    /// <summary>The mover is a body: its frames are <see cref="Steps"/>, run through <see cref="PhysicsEngine.Step(MoverDescription, in MoverState, in BodyState, double, System.Numerics.Vector3, float)"/>.</summary>
    public bool IsBody => _steps.Length > 0;
    /// <summary>
    /// The mover is a missile: a body (<see cref="IsBody"/>) whose state has <see cref="PhysicsState.Missile"/>, run as a
    /// <see cref="Missile"/> through <see cref="PhysicsEngine.Step(Missile, double)"/> (its hit recorded once).
    /// </summary>
    public bool IsMissile => IsBody && !IsMotion && (Description.PhysicsState & PhysicsState.Missile) != 0;
    /// <summary>A body mover's state before the first frame (velocity, friction, elasticity…).</summary>
    public BodyState StartBody { get; }
    /// <summary>A body mover's frames, repeats expanded; empty for an offset mover.</summary>
    public ReadOnlySpan<SceneStep> Steps => _steps;

    /// <summary>The mover's name, unique in its scene.</summary>
    public string Name { get; }
    /// <summary>What the mover is.</summary>
    public MoverDescription Description { get; }
    /// <summary>Its state before the first frame.</summary>
    public MoverState Start { get; }
    /// <summary>The requested offset of each frame (landblock space), repeats expanded; empty for a body mover.</summary>
    public ReadOnlySpan<Vector3> Motion => _motion;
    /// <summary>How many frames the mover walks.</summary>
    public int FrameCount => IsBody ? _steps.Length : _motion.Length;
}
