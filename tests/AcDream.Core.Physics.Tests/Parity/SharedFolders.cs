using System.IO;

namespace AcDream.Core.Physics.Tests.Parity;

/// <summary>Finds the shared reference folders (a folder "shared" beside the repository or one of its parents).</summary>
internal static class SharedFolders
{
    /// <summary>The shared folder <paramref name="name"/>, found by walking up from the test binaries; null when absent.</summary>
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
