using System.IO;
using System.Reflection;
using System.Text.RegularExpressions;

namespace AcDream.Core.Physics.Tests.Docs;

/// <summary>
/// The facade: a client's code names at most two namespaces of ours, the runtime's <c>AcDream.Core.Physics</c> and
/// the one package it builds on (<c>.Dat</c> for DAT files, <c>.Scenes</c> for the tooling). Each example file is read
/// as text (embedded into this assembly at build time); a namespace counts when a <c>using</c> directive names it
/// (plain, static, alias or global) or when the code qualifies a name with it, so spelling a type out in full does
/// not hide a third namespace.
/// </summary>
public class ExampleNamespacesTests
{
    private const int MostNamespaces = 2;

    private static string Resource(string name)
    {
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(name)
            ?? throw new InvalidOperationException($"resource {name} is not embedded");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd().Replace("\r\n", "\n");
    }

    /// <summary>Our namespaces the file names: by using directives, and by qualified names in its code.</summary>
    internal static SortedSet<string> OurNamespaces(string source)
    {
        var names = new SortedSet<string>(StringComparer.Ordinal);
        foreach (Match m in Regex.Matches(source, @"^\s*(?:global\s+)?using\s+(?:static\s+)?(?:\w+\s*=\s*)?(AcDream(?:\.\w+)*)\s*;", RegexOptions.Multiline))
            names.Add(Namespace(m.Groups[1].Value));
        // Qualified names in the code (comments and strings left out): AcDream.Core.Physics.Motion.MotionTable names .Motion.
        string code = Regex.Replace(source, @"//[^\n]*|/\*.*?\*/|""(?:\\.|[^""\\])*""", "", RegexOptions.Singleline);
        foreach (Match m in Regex.Matches(code, @"(?<![\w.])(AcDream(?:\.[A-Za-z_]\w*)+)\.\w+"))
            if (!Regex.IsMatch(code.Substring(Math.Max(0, m.Index - 40), Math.Min(40, m.Index)), @"using\s+(?:static\s+)?(?:\w+\s*=\s*)?$"))
                names.Add(Namespace(m.Groups[1].Value));
        return names;
    }

    // A static using, an alias or a qualified name may end in a type: keep AcDream.Core.Physics and, when the next
    // segment is one of our sub-namespaces, that one (ours are never nested deeper).
    private static string Namespace(string name)
    {
        var parts = name.Split('.');
        int keep = Math.Min(parts.Length, 4);                                 // AcDream.Core.Physics[.Sub]
        if (keep == 4 && !SubNamespaces.Contains(parts[3]))
            keep = 3;
        return string.Join('.', parts, 0, keep);
    }

    private static readonly HashSet<string> SubNamespaces =
        ["Body", "Bsp", "Dat", "Diagnostics", "Geometry", "Managers", "Motion", "Parity", "Queries", "Reference", "Scenes",
         "Shapes", "Snapshots", "Transitions", "Validation", "Viewer", "World"];

    [Theory]
    [InlineData("StreamingWalk.Program.cs")]
    [InlineData("WalkThrough.Program.cs")]
    [InlineData("DatWalk.Program.cs")]
    [InlineData("DatWalk.DatWorldWriter.cs")]
    public void AnExamplesClientCode_NamesAtMostTwoOfOurNamespaces(string file)
    {
        var names = OurNamespaces(Resource(file));
        Assert.True(names.Count <= MostNamespaces,
            $"{file} names {names.Count} namespaces of ours ({string.Join(", ", names)}); a client's code needs at most " +
            $"{MostNamespaces}: AcDream.Core.Physics and the package it builds on. Move what it names into the facade.");
    }

    [Fact]
    public void TheCount_SeesUsingsAliasesStaticsAndQualifiedNames()
    {
        const string source = """
            using System;
            using AcDream.Core.Physics;
            using Tree = AcDream.Core.Physics.Bsp.BspTree;
            using static AcDream.Core.Physics.Motion.MotionCommand;
            // AcDream.Core.Physics.Queries.WorldQuery in a comment does not count
            var x = new AcDream.Core.Physics.World.CellGraph();
            var s = "AcDream.Core.Physics.Diagnostics.X";
            """;
        Assert.Equal(["AcDream.Core.Physics", "AcDream.Core.Physics.Bsp", "AcDream.Core.Physics.Motion", "AcDream.Core.Physics.World"],
            OurNamespaces(source));
    }
}
