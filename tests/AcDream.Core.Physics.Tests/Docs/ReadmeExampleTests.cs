using System.IO;
using System.Reflection;
using System.Text.RegularExpressions;

namespace AcDream.Core.Physics.Tests.Docs;

/// <summary>
/// The README's "Using the library" code is the example's code: each C# block of that section equals,
/// in order, a region marked <c>#region readme</c> in examples/WalkThrough/Program.cs, which the build
/// compiles and CI runs; likewise "A client's world" and the <c>#region client-world</c> regions of
/// examples/StreamingWalk/Program.cs. The files are embedded into this assembly at build time.
/// </summary>
public class ReadmeExampleTests
{
    private static string Resource(string name)
    {
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(name)
            ?? throw new InvalidOperationException($"resource {name} is not embedded");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd().Replace("\r\n", "\n");
    }

    private static List<string> ReadmeBlocks(string heading = "Using the library")
    {
        string readme = Resource("README.md");
        var section = Regex.Match(readme, @"^## " + Regex.Escape(heading) + @"\n(.*?)(?=^## |\z)", RegexOptions.Multiline | RegexOptions.Singleline);
        Assert.True(section.Success, $"README.md has no \"## {heading}\" section");
        return Regex.Matches(section.Groups[1].Value, @"^```csharp\n(.*?)^```", RegexOptions.Multiline | RegexOptions.Singleline)
            .Select(m => m.Groups[1].Value).ToList();
    }

    private static List<string> ExampleRegions(string program = "WalkThrough.Program.cs", string region = "readme") =>
        Regex.Matches(Resource(program), @"^#region " + region + @"\n(.*?)^#endregion", RegexOptions.Multiline | RegexOptions.Singleline)
            .Select(m => m.Groups[1].Value).ToList();

    [Fact]
    public void UsingTheLibrary_CodeBlocks_AreTheExamplesReadmeRegions() =>
        SameText(ReadmeBlocks(), ExampleRegions());

    [Fact]
    public void AClientsWorld_CodeBlocks_AreTheStreamingWalksRegions() =>
        SameText(ReadmeBlocks("A client's world"), ExampleRegions("StreamingWalk.Program.cs", "client-world"));

    [Fact]
    public void TheRetailDatFiles_CodeBlocks_AreTheDatWalksRegions() =>
        SameText(ReadmeBlocks("The retail DAT files"), ExampleRegions("DatWalk.Program.cs", "dat-readme"));

    private static void SameText(List<string> blocks, List<string> regions)
    {
        Assert.True(regions.Count >= 2, $"the example has {regions.Count} readme regions");
        Assert.Equal(regions.Count, blocks.Count);
        for (int i = 0; i < blocks.Count; i++)
        {
            if (blocks[i] == regions[i])
                continue;
            var b = blocks[i].Split('\n');
            var r = regions[i].Split('\n');
            int line = 0;
            while (line < Math.Min(b.Length, r.Length) && b[line] == r[line])
                line++;
            Assert.Fail($"README block {i + 1} differs from the example's readme region {i + 1} at its line {line + 1}:\n" +
                $"  README:  {(line < b.Length ? b[line] : "(end)")}\n  example: {(line < r.Length ? r[line] : "(end)")}");
        }
    }
}
