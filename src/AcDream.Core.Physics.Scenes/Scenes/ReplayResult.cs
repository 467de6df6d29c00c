using System.Collections.Generic;

namespace AcDream.Core.Physics.Scenes;

/// <summary>The outcome of a replay.</summary>
public sealed class ReplayResult
{
    internal ReplayResult(ReplayDifference? difference, int framesCompared, float tolerance, IReadOnlyList<string> notes)
    {
        FirstDifference = difference;
        FramesCompared = framesCompared;
        Tolerance = tolerance;
        Notes = notes;
    }

    /// <summary>True when every frame matched.</summary>
    public bool Matches => FirstDifference is null;
    /// <summary>The first difference, or null.</summary>
    public ReplayDifference? FirstDifference { get; }
    /// <summary>How many frames were re-run and matched before the first difference (all of them on a match).</summary>
    public int FramesCompared { get; }
    /// <summary>The tolerance used for lengths.</summary>
    public float Tolerance { get; }
    /// <summary>Remarks that do not fail the replay (e.g. a different library version).</summary>
    public IReadOnlyList<string> Notes { get; }
}
