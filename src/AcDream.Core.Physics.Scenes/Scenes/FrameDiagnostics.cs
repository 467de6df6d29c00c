using System.Collections.Generic;
using AcDream.Core.Physics.Diagnostics;

namespace AcDream.Core.Physics.Scenes;

/// <summary>The diagnostics events of one frame of one mover, handed to a <see cref="SceneRunner"/> callback.</summary>
/// <param name="MoverIndex">The mover's index in the scene.</param>
/// <param name="MoverName">The mover's name.</param>
/// <param name="Frame">The frame index (0-based).</param>
/// <param name="Events">The frame's events, in order; valid only during the callback.</param>
public readonly record struct FrameDiagnostics(int MoverIndex, string MoverName, int Frame, IReadOnlyList<TransitionEvent> Events);
