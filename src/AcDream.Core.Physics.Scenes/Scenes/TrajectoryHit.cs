namespace AcDream.Core.Physics.Scenes;

/// <summary>A missile's hit as a trajectory records it: what was hit and in which quantum of the flight (see <see cref="MissileHit"/>).</summary>
/// <param name="Kind">Object or environment.</param>
/// <param name="ObjectId">The object hit, or 0 for the environment.</param>
/// <param name="Quantum">The quantum of the flight that hit, from 1.</param>
public readonly record struct TrajectoryHit(MissileHitKind Kind, uint ObjectId, int Quantum);
