namespace AcDream.Core.Physics;

/// <summary>Which key is held with a motion command (retail HoldKey).</summary>
public enum HoldKey
{
    /// <summary>Not given: the interpreter's current hold key applies.</summary>
    Invalid = 0,
    /// <summary>No key: walk.</summary>
    None = 1,
    /// <summary>The run key: walk forward becomes run, sidestep is sped up by the run rate, turns by 1.5.</summary>
    Run = 2,
}
