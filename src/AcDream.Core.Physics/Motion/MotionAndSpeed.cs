namespace AcDream.Core.Physics.Motion;

/// <summary>A motion with its speed (a modifier or an action of a <see cref="MotionTableState"/>).</summary>
/// <param name="Id">The motion command.</param>
/// <param name="Speed">Its speed.</param>
public readonly record struct MotionAndSpeed(uint Id, float Speed);
