using System.IO;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.Tests.Robustness;

namespace AcDream.Core.Physics.Tests.Docs;

/// <summary>
/// docs/creatures.md's recipe is the example's code: its C# blocks equal, in order, the regions marked
/// <c>#region recipe</c> in examples/ChaseAndMelee/Program.cs, which the build compiles and CI runs against the
/// runtime package (it exits 1 when the creature does not hold the player in melee or the arrow misses it).
/// </summary>
public class CreatureRecipeTests
{
    [Fact]
    public void TheCreaturesPage_CodeBlocks_AreTheChaseAndMeleeRegions()
    {
        string root = BadInputTests.RepoRoot();
        string page = File.ReadAllText(Path.Combine(root, "docs", "creatures.md")).Replace("\r\n", "\n");
        string program = File.ReadAllText(Path.Combine(root, "examples", "ChaseAndMelee", "Program.cs")).Replace("\r\n", "\n");
        var blocks = Regex.Matches(page, @"^```csharp\n(.*?)^```", RegexOptions.Multiline | RegexOptions.Singleline)
            .Select(m => m.Groups[1].Value).ToList();
        var regions = Regex.Matches(program, @"^#region recipe\n(.*?)^#endregion", RegexOptions.Multiline | RegexOptions.Singleline)
            .Select(m => m.Groups[1].Value).ToList();
        Assert.True(regions.Count >= 3, $"the example has {regions.Count} recipe regions");
        Assert.Equal(regions.Count, blocks.Count);
        for (int i = 0; i < blocks.Count; i++)
        {
            var b = blocks[i].Split('\n');
            var r = regions[i].Split('\n');
            int line = 0;
            while (line < Math.Min(b.Length, r.Length) && b[line] == r[line])
                line++;
            Assert.True(blocks[i] == regions[i], $"docs/creatures.md block {i + 1} differs from the example's recipe region {i + 1} at its line {line + 1}:\n" +
                $"  page:    {(line < b.Length ? b[line] : "(end)")}\n  example: {(line < r.Length ? r[line] : "(end)")}");
        }
    }
}
