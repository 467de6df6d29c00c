namespace AcDream.Core.Physics.Parity;

/// <summary>A MoveTo call a manager parity file makes before a frame's time passes.</summary>
internal readonly record struct MoveToCall(MoveToKind Kind, Position Target, MoveToParameters Parameters, uint ObjectId)
{
    /// <summary>The JSON path of the recorded command the call was read from (for the errors of a refused call).</summary>
    public string Path { get; init; } = string.Empty;
}
