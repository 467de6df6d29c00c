using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>
/// The run's shortcut mode: with <c>ACDREAM_PHYSICS_SHORTCUTS=none</c> in the environment, everything the tests
/// build takes no shortcut (retail's path step for step), so the same tests, replays and parity comparisons
/// against committed data show the shortcuts change no result bit. Set before any test builds anything.
/// Tests that compare the two paths directly build both with explicit <see cref="Shortcuts"/> values.
/// </summary>
internal static class ShortcutsMode
{
    /// <summary>The environment variable CI sets for the second run.</summary>
    public const string Variable = "ACDREAM_PHYSICS_SHORTCUTS";

    [ModuleInitializer]
    internal static void Apply()
    {
        string? mode = Environment.GetEnvironmentVariable(Variable);
        if (string.Equals(mode, "none", StringComparison.OrdinalIgnoreCase))
            ShortcutSettings.Default = Shortcuts.None;
        else if (!string.IsNullOrEmpty(mode) && !string.Equals(mode, "all", StringComparison.OrdinalIgnoreCase))
            throw new InvalidOperationException($"{Variable}: 'none' or 'all', got '{mode}'.");
    }
}
