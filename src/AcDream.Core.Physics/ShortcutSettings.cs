namespace AcDream.Core.Physics;

/// <summary>
/// The shortcuts a new engine, transition, path, contact record or cell graph takes (<see cref="Shortcuts"/>):
/// all of them unless a test run asks for none (the test assembly sets this before anything is built, so the
/// whole suite can run retail's path step for step and compare it with the committed data).
/// </summary>
internal static class ShortcutSettings
{
    /// <summary>The shortcuts taken by what is built from now on.</summary>
    public static Shortcuts Default { get; set; } = Shortcuts.All;
}
