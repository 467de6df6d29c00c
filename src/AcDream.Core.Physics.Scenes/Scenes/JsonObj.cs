using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text.Json;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// A JSON object being read strictly: every field asked for is remembered, and <see cref="End"/> refuses
/// any field that was never asked for (typos are errors). Duplicate fields are refused on creation.
/// A misspelt field is reported as unknown before the missing-field error it causes: when a required field
/// is absent (<see cref="Req"/>, <see cref="Missing"/>), a field not read yet whose name is one edit from
/// it is refused first, with a did-you-mean. Load-time only; allocates freely.
/// </summary>
internal sealed class JsonObj
{
    private readonly JsonElement _element;
    private readonly HashSet<string> _known = new(StringComparer.Ordinal);

    public JsonObj(JsonElement element, string path)
    {
        Path = path;
        if (element.ValueKind != JsonValueKind.Object)
            throw new SceneFormatException(path, $"expected an object, got {JsonRead.Kind(element)}.");
        _element = element;
        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var p in element.EnumerateObject())
            if (!seen.Add(p.Name))
                throw new SceneFormatException(Child(p.Name), "field appears more than once.");
    }

    /// <summary>The object's JSON path.</summary>
    public string Path { get; }

    /// <summary>The path of a field of this object.</summary>
    public string Child(string name) => Path.Length == 0 ? name : $"{Path}.{name}";

    /// <summary>The field, or null when absent or JSON null.</summary>
    public JsonElement? Opt(string name)
    {
        _known.Add(name);
        return _element.TryGetProperty(name, out var v) && v.ValueKind != JsonValueKind.Null ? v : null;
    }

    /// <summary>True when the field is present and not null.</summary>
    public bool Has(string name) => Opt(name).HasValue;

    /// <summary>The field; throws naming it when absent (or naming the misspelt field that was meant).</summary>
    public JsonElement Req(string name) => Opt(name) ?? throw Missing(Child(name), "is required.", name);

    /// <summary>
    /// The error for a missing field, <paramref name="message"/> at <paramref name="path"/>; but when a field of
    /// this object not read yet is one edit away from one of <paramref name="meant"/> (or differs only in case),
    /// it is refused as unknown instead, with a did-you-mean: the typo is the mistake to fix. One edit only,
    /// because the fields not read yet may include real fields whose names are near the missing one.
    /// </summary>
    public SceneFormatException Missing(string path, string message, params string[] meant)
    {
        foreach (var p in _element.EnumerateObject())
            if (!_known.Contains(p.Name) && FieldNames.Closest(p.Name, meant, maxEdits: 1) is { } name)
                return new SceneFormatException(Child(p.Name), $"unknown field \"{p.Name}\"; did you mean \"{name}\"?");
        return new SceneFormatException(path, message);
    }

    /// <summary>The fields in file order (all count as known).</summary>
    public IEnumerable<(string Name, JsonElement Value)> Fields()
    {
        foreach (var p in _element.EnumerateObject())
        {
            _known.Add(p.Name);
            yield return (p.Name, p.Value);
        }
    }

    /// <summary>Refuses fields that were never asked for.</summary>
    public void End()
    {
        foreach (var p in _element.EnumerateObject())
            if (!_known.Contains(p.Name))
            {
                var known = new List<string>(_known);
                known.Sort(StringComparer.Ordinal);
                string hint = FieldNames.Closest(p.Name, known, maxEdits: 2) is { } meant ? $"did you mean \"{meant}\"? " : "";
                throw new SceneFormatException(Child(p.Name), $"unknown field \"{p.Name}\" ({hint}expected one of: {string.Join(", ", known)}).");
            }
    }

    public float Float(string name) => JsonRead.Float(Req(name), Child(name));
    public float Float(string name, float fallback) => Opt(name) is { } v ? JsonRead.Float(v, Child(name)) : fallback;
    public bool Bool(string name, bool fallback) => Opt(name) is { } v ? JsonRead.Bool(v, Child(name)) : fallback;
    public string String(string name) => JsonRead.String(Req(name), Child(name));
    public string? String(string name, string? fallback) => Opt(name) is { } v ? JsonRead.String(v, Child(name)) : fallback;
    public Vector3 Vec3(string name) => JsonRead.Vec3(Req(name), Child(name));
    public Quaternion Rotation(string name) => Opt(name) is { } v ? JsonRead.Rotation(v, Child(name)) : Quaternion.Identity;
    public uint Id(string name) => JsonRead.Id(Req(name), Child(name));
    public int Int(string name, int fallback) => Opt(name) is { } v ? JsonRead.Int(v, Child(name)) : fallback;
    public JsonObj Obj(string name) => new(Req(name), Child(name));
    public IReadOnlyList<(JsonElement Value, string Path)> Array(string name) => JsonRead.Array(Req(name), Child(name));
    public IReadOnlyList<(JsonElement Value, string Path)> Array(string name, bool optional) =>
        Opt(name) is { } v ? JsonRead.Array(v, Child(name)) : System.Array.Empty<(JsonElement, string)>();
}
