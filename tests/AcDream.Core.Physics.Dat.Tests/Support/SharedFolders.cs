namespace AcDream.Core.Physics.Dat.Tests.Support;

/// <summary>Finds the shared reference folders (a folder "shared" beside the repository or one of its parents).</summary>
internal static class SharedFolders
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
