using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Validation;

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

/// <summary>Typed reads of JSON values; every error names the value's path.</summary>
internal static class JsonRead
{
    public static readonly JsonDocumentOptions Options = new()
    {
        CommentHandling = JsonCommentHandling.Skip,
        AllowTrailingCommas = false,
        MaxDepth = 64,
    };

    /// <summary>Parses a document; a syntax error becomes a <see cref="SceneFormatException"/> with its line and position.</summary>
    public static JsonDocument Parse(string text)
    {
        try
        {
            return JsonDocument.Parse(text, Options);
        }
        catch (JsonException ex)
        {
            long line = (ex.LineNumber ?? 0) + 1, position = (ex.BytePositionInLine ?? 0) + 1;
            string detail = ex.Message;
            int cut = detail.IndexOf(" LineNumber:", StringComparison.Ordinal);
            if (cut > 0) detail = detail[..cut].TrimEnd();
            throw new SceneFormatException(string.Empty, $"invalid JSON at line {line}, position {position}: {detail}", ex);
        }
    }

    public static string Kind(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Object => "an object",
        JsonValueKind.Array => "an array",
        JsonValueKind.String => $"the string \"{e.GetString()}\"",
        JsonValueKind.Number => $"the number {e.GetRawText()}",
        JsonValueKind.True => "true",
        JsonValueKind.False => "false",
        JsonValueKind.Null => "null",
        _ => e.ValueKind.ToString(),
    };

    public static float Float(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Number)
            throw new SceneFormatException(path, $"expected a number, got {Kind(e)}.");
        // Parsed straight to float (not through double) so that a float written in its shortest
        // round-trippable form reads back to the same bits.
        if (!e.TryGetSingle(out float f) || !float.IsFinite(f))
            throw new SceneFormatException(path, $"the number {e.GetRawText()} is out of range for a float.");
        return f;
    }

    /// <summary>A finite number read as a double (times in seconds).</summary>
    public static double Double(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Number)
            throw new SceneFormatException(path, $"expected a number, got {Kind(e)}.");
        if (!e.TryGetDouble(out double d) || !double.IsFinite(d))
            throw new SceneFormatException(path, $"the number {e.GetRawText()} is out of range.");
        return d;
    }

    public static int Int(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Number || !e.TryGetInt32(out int v))
            throw new SceneFormatException(path, $"expected an integer, got {Kind(e)}.");
        return v;
    }

    public static bool Bool(JsonElement e, string path) => e.ValueKind switch
    {
        JsonValueKind.True => true,
        JsonValueKind.False => false,
        _ => throw new SceneFormatException(path, $"expected true or false, got {Kind(e)}."),
    };

    public static string String(JsonElement e, string path) =>
        e.ValueKind == JsonValueKind.String ? e.GetString()! : throw new SceneFormatException(path, $"expected a string, got {Kind(e)}.");

    public static IReadOnlyList<(JsonElement Value, string Path)> Array(JsonElement e, string path)
    {
        if (e.ValueKind != JsonValueKind.Array)
            throw new SceneFormatException(path, $"expected an array, got {Kind(e)}.");
        var list = new List<(JsonElement, string)>(e.GetArrayLength());
        int i = 0;
        foreach (var item in e.EnumerateArray())
            list.Add((item, $"{path}[{i++}]"));
        return list;
    }

    /// <summary>An array of exactly <paramref name="count"/> finite floats; <paramref name="what"/> names it in the error.</summary>
    public static float[] Numbers(JsonElement e, string path, int count, string what)
    {
        var items = Array(e, path);
        if (items.Count != count)
            throw new SceneFormatException(path, $"{what} needs {count} numbers, got {items.Count}.");
        var values = new float[count];
        for (int i = 0; i < count; i++)
            values[i] = Float(items[i].Value, items[i].Path);
        return values;
    }

    /// <summary>A vector written as [x, y, z].</summary>
    public static Vector3 Vec3(JsonElement e, string path)
    {
        var v = Numbers(e, path, 3, "a vector [x, y, z]");
        return new Vector3(v[0], v[1], v[2]);
    }

    /// <summary>A rotation written as [w, x, y, z] (retail order); must be non-zero; returned normalized.</summary>
    public static Quaternion Rotation(JsonElement e, string path)
    {
        var v = Numbers(e, path, 4, "a quaternion [w, x, y, z]");
        try
        {
            return Guard.Rotation(new Quaternion(v[1], v[2], v[3], v[0]), path);
        }
        catch (ArgumentException ex)
        {
            throw SceneFormatException.Wrap(path, ex);
        }
    }

    /// <summary>A quaternion written as [w, x, y, z], read exactly as written (no normalization); must be non-zero.</summary>
    public static Quaternion RawQuaternion(JsonElement e, string path)
    {
        var v = Numbers(e, path, 4, "a quaternion [w, x, y, z]");
        var q = new Quaternion(v[1], v[2], v[3], v[0]);
        if (q.LengthSquared() < 1e-12f)
            throw new SceneFormatException(path, "quaternion has zero length.");
        return q;
    }

    /// <summary>An id written as a hex string ("0x7000_0001" or "0x70000001") or a non-negative integer.</summary>
    public static uint Id(JsonElement e, string path)
    {
        if (e.ValueKind == JsonValueKind.Number)
        {
            if (e.TryGetUInt32(out uint n)) return n;
            throw new SceneFormatException(path, $"expected a 32-bit unsigned id, got {e.GetRawText()}.");
        }
        if (e.ValueKind == JsonValueKind.String && TryHex(e.GetString()!, out uint h))
            return h;
        throw new SceneFormatException(path, $"expected an id (a hex string such as \"0x7000_0001\" or an integer), got {Kind(e)}.");
    }

    /// <summary>An id written as hex text ("0x003D0003"), as in an object's keys.</summary>
    public static uint Id(string text, string path) =>
        TryHex(text, out uint h) ? h : throw new SceneFormatException(path, $"expected a hex id such as \"0x003D0003\", got \"{text}\".");

    private static bool TryHex(string s, out uint value)
    {
        value = 0;
        if (!s.StartsWith("0x", StringComparison.OrdinalIgnoreCase)) return false;
        string digits = s[2..].Replace("_", string.Empty, StringComparison.Ordinal);
        return digits.Length is > 0 and <= 8 && uint.TryParse(digits, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out value);
    }

    /// <summary>Flags written as a hex string, an integer, or an array of flag names.</summary>
    public static TEnum Flags<TEnum>(JsonElement e, string path) where TEnum : struct, Enum
    {
        ulong bits;
        if (e.ValueKind == JsonValueKind.Array)
        {
            bits = 0;
            foreach (var (item, itemPath) in Array(e, path))
            {
                bits |= FlagBits<TEnum>(String(item, itemPath), itemPath);
            }
        }
        else
        {
            bits = Id(e, path);
        }
        ulong max = Enum.GetUnderlyingType(typeof(TEnum)) == typeof(byte) ? 0xFFul : 0xFFFF_FFFFul;
        if (bits > max)
            throw new SceneFormatException(path, $"0x{bits:X} does not fit {typeof(TEnum).Name}.");
        return (TEnum)Enum.ToObject(typeof(TEnum), bits);
    }

    /// <summary>The bits of one flag written by its name (a defined name, not a number); the error lists the known names.</summary>
    public static ulong FlagBits<TEnum>(string name, string path) where TEnum : struct, Enum
    {
        if (!Enum.TryParse<TEnum>(name, ignoreCase: false, out var flag) || !Enum.IsDefined(flag) || int.TryParse(name, out _))
            throw new SceneFormatException(path, $"unknown {typeof(TEnum).Name} flag \"{name}\" (known: {string.Join(", ", Enum.GetNames<TEnum>())}).");
        return Convert.ToUInt64(flag, CultureInfo.InvariantCulture);
    }

    /// <summary>Formats a float so that it reads back to the same value.</summary>
    public static string F(float value) => value.ToString("R", CultureInfo.InvariantCulture);
}
