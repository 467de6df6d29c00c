using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics;

/// <summary>
/// A building standing in an outdoor cell (retail CBuildingObj): a shell model collided like an object
/// part, and the env cells its doorways lead into (retail building portals).
/// </summary>
public sealed class Building
{
    private readonly uint[] _entranceCells;

    /// <summary>Creates a building.</summary>
    /// <param name="shell">The shell's physics model.</param>
    /// <param name="position">Where the shell stands (an outdoor cell id and a landblock-local frame).</param>
    /// <param name="entranceCells">The env cells reached through the building's doorways.</param>
    public Building(PhysicsModel shell, Position position, IReadOnlyList<uint> entranceCells)
    {
        Shell = shell ?? throw new ArgumentNullException(nameof(shell));
        Guard.Pose(ref position.Frame, "building.position");
        Position = position;
        _entranceCells = entranceCells is null ? Array.Empty<uint>() : [.. entranceCells];
    }

    /// <summary>The shell's physics model.</summary>
    public PhysicsModel Shell { get; }
    /// <summary>Where the shell stands.</summary>
    public Position Position { get; }
    /// <summary>The env cells the doorways lead into.</summary>
    public ReadOnlySpan<uint> EntranceCells => _entranceCells;
}
