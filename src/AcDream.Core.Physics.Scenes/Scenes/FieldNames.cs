using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Which expected field name an unknown one was probably meant to be: the same name in another case, or
/// one within a few edits (an inserted, deleted or replaced letter, or two neighbours swapped). Load-time only.
/// </summary>
internal static class FieldNames
{
    /// <summary>
    /// The closest of <paramref name="expected"/> to <paramref name="name"/> within <paramref name="maxEdits"/>
    /// edits (at most one for names of up to four letters), or null when none is that close.
    /// </summary>
    public static string? Closest(string name, IReadOnlyList<string> expected, int maxEdits)
    {
        string? best = null;
        int bestDistance = int.MaxValue;
        foreach (string candidate in expected)
        {
            if (string.Equals(name, candidate, StringComparison.OrdinalIgnoreCase))
                return candidate;
            int limit = candidate.Length <= 4 ? Math.Min(maxEdits, 1) : maxEdits;
            if (Math.Abs(name.Length - candidate.Length) > limit)
                continue;
            int distance = Distance(name.ToLowerInvariant(), candidate.ToLowerInvariant());
            if (distance <= limit && distance < bestDistance)
                (best, bestDistance) = (candidate, distance);
        }
        return best;
    }

    /// <summary>Edits (insert, delete, replace, swap of neighbours) that turn <paramref name="a"/> into <paramref name="b"/>.</summary>
    private static int Distance(string a, string b)
    {
        var d = new int[a.Length + 1, b.Length + 1];
        for (int i = 0; i <= a.Length; i++) d[i, 0] = i;
        for (int j = 0; j <= b.Length; j++) d[0, j] = j;
        for (int i = 1; i <= a.Length; i++)
            for (int j = 1; j <= b.Length; j++)
            {
                int cost = a[i - 1] == b[j - 1] ? 0 : 1;
                d[i, j] = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                    d[i, j] = Math.Min(d[i, j], d[i - 2, j - 2] + 1);
            }
        return d[a.Length, b.Length];
    }
}
