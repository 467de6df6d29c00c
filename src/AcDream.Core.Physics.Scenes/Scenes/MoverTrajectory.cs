using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics.Scenes;

/// <summary>The frames of one mover of a scene.</summary>
public sealed class MoverTrajectory
{
    /// <summary>Creates a mover's trajectory.</summary>
    public MoverTrajectory(string name, IReadOnlyList<TrajectoryFrame> frames)
    {
        Name = name ?? throw new ArgumentNullException(nameof(name));
        Frames = frames ?? throw new ArgumentNullException(nameof(frames));
    }

    /// <summary>The mover's name in the scene.</summary>
    public string Name { get; }
    /// <summary>Its frames, in order.</summary>
    public IReadOnlyList<TrajectoryFrame> Frames { get; }
}
