using System;
using System.Collections.Generic;
using System.IO;

namespace AcDream.Core.Physics.Scenes;

/// <summary>The built-in scenes, embedded in the library as JSON (Scenes/BuiltIn/*.json), loadable by name.</summary>
public static class SceneLibrary
{
    private const string Prefix = "AcDream.Core.Physics.Scenes.BuiltIn.";
    private const string Suffix = ".json";

    /// <summary>The built-in scene names, sorted.</summary>
    public static IReadOnlyList<string> Names { get; } = FindNames();

    private static string[] FindNames()
    {
        var names = new List<string>();
        foreach (string resource in typeof(SceneLibrary).Assembly.GetManifestResourceNames())
            if (resource.StartsWith(Prefix, StringComparison.Ordinal) && resource.EndsWith(Suffix, StringComparison.Ordinal))
                names.Add(resource[Prefix.Length..^Suffix.Length]);
        names.Sort(StringComparer.Ordinal);
        return [.. names];
    }

    /// <summary>True when a built-in scene has this name.</summary>
    public static bool Contains(string name) => name is not null && ((IList<string>)Names).Contains(name);

    /// <summary>The JSON text of a built-in scene.</summary>
    /// <exception cref="ArgumentException">No built-in scene has this name.</exception>
    public static string ReadText(string name)
    {
        if (!Contains(name))
            throw new ArgumentException($"unknown built-in scene \"{name}\" (built-in: {string.Join(", ", Names)}).", nameof(name));
        using var stream = typeof(SceneLibrary).Assembly.GetManifestResourceStream(Prefix + name + Suffix)!;
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }

    /// <summary>Loads a built-in scene by name.</summary>
    /// <exception cref="ArgumentException">No built-in scene has this name.</exception>
    public static Scene Load(string name) => SceneLoader.Load(ReadText(name), name);
}
