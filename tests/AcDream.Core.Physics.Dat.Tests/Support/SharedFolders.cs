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

    /// <summary>Each collision parity file of shared/ace-parity and shared/real-cells, as (folder, file name), in name order.</summary>
    public static TheoryData<string, string> CollisionParityFiles()
    {
        var data = new TheoryData<string, string>();
        foreach (string folder in new[] { "ace-parity", "real-cells" })
            if (Find(folder) is { } dir)
                foreach (string file in Directory.GetFiles(dir, "*.json.gz").OrderBy(f => f, StringComparer.Ordinal))
                    data.Add(folder, Path.GetFileName(file));
        return data;
    }
}
