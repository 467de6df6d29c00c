namespace AcDream.Core.Physics.Scenes;

/// <summary>The first place where a replay disagrees with its recording.</summary>
public sealed class ReplayDifference
{
    internal ReplayDifference(string mover, int frame, string field, string expected, string actual)
    {
        Mover = mover;
        Frame = frame;
        Field = field;
        Expected = expected;
        Actual = actual;
    }

    /// <summary>The mover's name; empty for a header difference.</summary>
    public string Mover { get; }
    /// <summary>The frame index (0-based); -1 when the difference is not in a frame (header, mover or frame counts).</summary>
    public int Frame { get; }
    /// <summary>The field, e.g. <c>position.y</c>, <c>cell</c>, <c>collided</c>.</summary>
    public string Field { get; }
    /// <summary>The recorded value.</summary>
    public string Expected { get; }
    /// <summary>The value the replay produced.</summary>
    public string Actual { get; }

    /// <inheritdoc />
    public override string ToString()
    {
        string where = Frame >= 0 ? $"mover '{Mover}', frame {Frame}" : Mover.Length > 0 ? $"mover '{Mover}'" : "header";
        return $"{where}, field {Field}: expected {Expected}, actual {Actual}";
    }
}
