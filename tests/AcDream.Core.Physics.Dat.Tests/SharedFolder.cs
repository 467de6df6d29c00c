using System.IO;

namespace AcDream.Core.Physics.Dat.Tests;

/// <summary>The shared reference folders (a folder "shared" beside the repository or beside one of its parents).</summary>
internal static class SharedFolder
{
    public static string? Find(string name)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.FullName, "shared", name);
            if (File.Exists(Path.Combine(candidate, "README.md")))
                return candidate;
        }
        return null;
    }
}
