using System;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// A scene or trajectory file is malformed: bad JSON, a wrong type, an unknown field, a bad value or a
/// broken reference. The message starts with the JSON path of the offending value
/// (e.g. <c>objects[2].rotation: quaternion has zero length.</c>).
/// </summary>
public sealed class SceneFormatException : Exception
{
    /// <summary>Creates the exception.</summary>
    /// <param name="jsonPath">The JSON path of the bad value (dotted names and [index]es; empty for the whole file).</param>
    /// <param name="detail">What is wrong with it.</param>
    /// <param name="inner">The library's own exception, when the value was refused by its validation.</param>
    public SceneFormatException(string jsonPath, string detail, Exception? inner = null)
        : base(string.IsNullOrEmpty(jsonPath) ? detail : $"{jsonPath}: {detail}", inner)
    {
        JsonPath = jsonPath ?? string.Empty;
        Detail = detail;
    }

    /// <summary>The JSON path of the bad value; empty when the file as a whole is bad (e.g. not JSON).</summary>
    public string JsonPath { get; }

    /// <summary>The message without the path.</summary>
    public string Detail { get; }

    /// <summary>
    /// Wraps an <see cref="ArgumentException"/> of the library's own validation so that the message starts
    /// with <paramref name="jsonPath"/> (unless it already does) and carries no "(Parameter …)" suffix.
    /// </summary>
    internal static SceneFormatException Wrap(string jsonPath, ArgumentException ex)
    {
        string message = ex.Message;
        if (ex.ParamName is not null)
        {
            string suffix = $" (Parameter '{ex.ParamName}')";
            if (message.EndsWith(suffix, StringComparison.Ordinal))
                message = message[..^suffix.Length];
        }
        if (message.StartsWith(jsonPath + ".", StringComparison.Ordinal) || message.StartsWith(jsonPath + ":", StringComparison.Ordinal)
            || message.StartsWith(jsonPath + "[", StringComparison.Ordinal))
        {
            int colon = message.IndexOf(": ", StringComparison.Ordinal);
            return colon > 0
                ? new SceneFormatException(message[..colon], message[(colon + 2)..], ex)
                : new SceneFormatException(jsonPath, message, ex);
        }
        return new SceneFormatException(jsonPath, message, ex);
    }
}
