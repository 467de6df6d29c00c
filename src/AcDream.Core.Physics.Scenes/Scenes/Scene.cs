using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// A loaded scene, ready to run: the world (cells, buildings, objects) and the movers with their motions.
/// Movers do not see each other: each walks alone through the same world (see docs/scene-format.md).
/// </summary>
public sealed class Scene
{
    internal Scene(string name, string description, string sha256, PhysicsWorld world, IReadOnlyList<SceneMover> movers)
    {
        Name = name;
        Description = description;
        Sha256 = sha256;
        World = world;
        Movers = movers;
    }

    /// <summary>The scene's name (its "name" field, or the file name).</summary>
    public string Name { get; }
    /// <summary>The scene's description, or empty.</summary>
    public string Description { get; }
    /// <summary>The SHA-256 (lower-case hex) of the scene text with CRLF line ends read as LF.</summary>
    public string Sha256 { get; }
    /// <summary>The world.</summary>
    public PhysicsWorld World { get; }
    /// <summary>The movers, in file order.</summary>
    public IReadOnlyList<SceneMover> Movers { get; }

    /// <summary>The same movers in another world (for example one loaded from the DAT files): the scene's own world is not used.</summary>
    /// <param name="world">The world the movers walk through; their start cells must be in it when the scene runs.</param>
    public Scene WithWorld(PhysicsWorld world)
    {
        ArgumentNullException.ThrowIfNull(world);
        return new Scene(Name, Description, Sha256, world, Movers);
    }
}
