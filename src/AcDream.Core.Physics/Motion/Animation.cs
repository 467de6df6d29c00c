using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// What physics needs of an animation (the DAT's Animation, 0x03… file): its frame count and, when the
/// animation has them (flag PosFrames), each frame's root offset. Part frames (poses) and hooks are not kept.
/// </summary>
public sealed class Animation
{
    private readonly RootFrame[] _rootFrames;

    /// <summary>Creates an animation; the motion table checks it (see <see cref="MotionTable"/>).</summary>
    /// <param name="id">The 0x03… id.</param>
    /// <param name="frameCount">The number of frames, at least 1.</param>
    /// <param name="rootFrames">Empty (no root motion) or one root offset per frame (copied).</param>
    public Animation(uint id, int frameCount, IReadOnlyList<RootFrame> rootFrames)
    {
        ArgumentNullException.ThrowIfNull(rootFrames);
        Id = id;
        FrameCount = frameCount;
        _rootFrames = new RootFrame[rootFrames.Count];
        for (int i = 0; i < _rootFrames.Length; i++)
            _rootFrames[i] = rootFrames[i];
    }

    /// <summary>The 0x03… id.</summary>
    public uint Id { get; }
    /// <summary>The number of frames.</summary>
    public int FrameCount { get; }
    /// <summary>The frames' root offsets: empty, or one per frame.</summary>
    public ReadOnlySpan<RootFrame> RootFrames => _rootFrames;
    internal bool HasRootFrames => _rootFrames.Length != 0;
    internal ref readonly RootFrame RootFrame(int frame) => ref _rootFrames[frame];
    internal int RootFrameCount => _rootFrames.Length;
}
