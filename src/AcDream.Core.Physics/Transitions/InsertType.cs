namespace AcDream.Core.Physics.Transitions;

/// <summary>How a sphere path is inserted into the world (retail InsertType).</summary>
internal enum InsertType
{
    /// <summary>A move from a begin position to an end position.</summary>
    Transition = 0,
    /// <summary>Placing an object where it is, sliding out of overlaps if allowed.</summary>
    Placement = 1,
    /// <summary>The first placement of an object in the world.</summary>
    InitialPlacement = 2,
}
