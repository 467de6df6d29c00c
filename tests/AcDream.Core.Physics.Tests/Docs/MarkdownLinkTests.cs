using System.IO;
using System.Text.RegularExpressions;
using AcDream.Core.Physics.Tests.Robustness;

namespace AcDream.Core.Physics.Tests.Docs;

/// <summary>
/// Every relative link and image in README.md and docs/*.md leads somewhere: the file (or folder) exists in the
/// repository, and an anchor (<c>page.md#heading</c>, <c>#heading</c>) names a heading of that page the way GitHub
/// makes heading anchors. Links with a scheme (https:, mailto:) are not followed. Code blocks and code spans are
/// skipped: a link written there is text.
/// </summary>
public class MarkdownLinkTests
{
    // [text](target) and ![alt](target); the target up to a space or the closing parenthesis.
    private static readonly Regex Link = new(@"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\((?<target>[^)\s]+)(?:\s+""[^""]*"")?\)", RegexOptions.Compiled);
    private static readonly Regex Scheme = new(@"^[A-Za-z][A-Za-z0-9+.-]*:", RegexOptions.Compiled);

    [Fact]
    public void EveryRelativeLink_InTheReadmeAndTheDocs_Resolves()
    {
        string root = BadInputTests.RepoRoot();
        var pages = new List<string> { Path.Combine(root, "README.md") };
        pages.AddRange(Directory.GetFiles(Path.Combine(root, "docs"), "*.md").Order(StringComparer.Ordinal));
        var broken = new List<string>();
        int followed = 0;
        foreach (string page in pages)
            foreach (var (line, target) in RelativeLinks(File.ReadAllText(page)))
            {
                followed++;
                string? why = Check(page, target);
                if (why is not null)
                    broken.Add($"{Path.GetRelativePath(root, page)}:{line}: ({target}) {why}");
            }
        Assert.True(followed > 20, $"only {followed} relative links found: the scan is broken");
        Assert.True(broken.Count == 0, $"{broken.Count} relative links lead nowhere:\n  " + string.Join("\n  ", broken));
    }

    [Theory]
    [InlineData("## A server tick (issue 25)", "a-server-tick-issue-25")]
    [InlineData("### MoveTo: retail's MoveToManager", "moveto-retails-movetomanager")]
    [InlineData("## `Step` and the body — 2 × 3", "step-and-the-body--2--3")]
    public void HeadingAnchors_AreGitHubs(string heading, string anchor) =>
        Assert.Contains(anchor, Anchors(heading + "\n"));

    /// <summary>The relative link targets of a markdown text, with their line numbers, outside code.</summary>
    private static IEnumerable<(int Line, string Target)> RelativeLinks(string markdown)
    {
        string[] lines = markdown.Replace("\r\n", "\n").Split('\n');
        bool fenced = false;
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].TrimStart().StartsWith("```"))
            {
                fenced = !fenced;
                continue;
            }
            if (fenced)
                continue;
            string text = Regex.Replace(lines[i], "`[^`]*`", "");
            foreach (Match m in Link.Matches(text))
            {
                string target = m.Groups["target"].Value;
                if (!Scheme.IsMatch(target))
                    yield return (i + 1, target);
            }
        }
    }

    /// <summary>Why <paramref name="target"/>, linked from <paramref name="page"/>, leads nowhere; null when it resolves.</summary>
    private static string? Check(string page, string target)
    {
        int hash = target.IndexOf('#');
        string path = hash < 0 ? target : target[..hash];
        string? anchor = hash < 0 ? null : target[(hash + 1)..];
        string file = path.Length == 0 ? page : Path.GetFullPath(Path.Combine(Path.GetDirectoryName(page)!, Uri.UnescapeDataString(path)));
        if (!File.Exists(file) && !Directory.Exists(file))
            return "no such file";
        if (anchor is null || !file.EndsWith(".md", StringComparison.OrdinalIgnoreCase) || !File.Exists(file))
            return null;
        return Anchors(File.ReadAllText(file)).Contains(anchor) ? null : $"no heading with the anchor #{anchor} in {Path.GetFileName(file)}";
    }

    /// <summary>
    /// GitHub's heading anchors: the heading's text (links reduced to their text, code marks dropped) in lower case,
    /// every character but letters, digits, spaces, hyphens and underscores removed, spaces made hyphens; a repeated
    /// anchor gets -1, -2, … Also any explicit <c>id="…"</c> or <c>name="…"</c> of an HTML anchor.
    /// </summary>
    private static HashSet<string> Anchors(string markdown)
    {
        var anchors = new HashSet<string>(StringComparer.Ordinal);
        var seen = new Dictionary<string, int>(StringComparer.Ordinal);
        bool fenced = false;
        foreach (string raw in markdown.Replace("\r\n", "\n").Split('\n'))
        {
            if (raw.TrimStart().StartsWith("```"))
                fenced = !fenced;
            if (fenced)
                continue;
            foreach (Match id in Regex.Matches(raw, @"<a\s+(?:id|name)=""([^""]+)"""))
                anchors.Add(id.Groups[1].Value);
            var heading = Regex.Match(raw, @"^#{1,6}\s+(.*?)\s*#*\s*$");
            if (!heading.Success)
                continue;
            string text = Regex.Replace(heading.Groups[1].Value, @"!?\[([^\]]*)\]\([^)]*\)", "$1").ToLowerInvariant();
            var slug = new System.Text.StringBuilder();
            foreach (char c in text)
            {
                if (char.IsLetterOrDigit(c) || c == '-' || c == '_')
                    slug.Append(c);
                else if (c == ' ')
                    slug.Append('-');
            }
            string s = slug.ToString();
            int n = seen.GetValueOrDefault(s);
            seen[s] = n + 1;
            anchors.Add(n == 0 ? s : $"{s}-{n}");
        }
        return anchors;
    }
}
