using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Physics.Validation;

namespace AcDream.Core.Physics.Scenes;

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
