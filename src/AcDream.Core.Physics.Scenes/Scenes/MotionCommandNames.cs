using System.Collections.Generic;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// The motion command names a scene may use (the constants of <see cref="MotionCommand"/>: Ready, WalkForward,
/// RunForward, TurnRight…), both ways.
/// </summary>
public static class MotionCommandNames
{
    private static readonly (string Name, uint Id)[] Known =
    [
        ("Ready", MotionCommand.Ready), ("WalkForward", MotionCommand.WalkForward), ("WalkBackwards", MotionCommand.WalkBackwards),
        ("RunForward", MotionCommand.RunForward), ("TurnRight", MotionCommand.TurnRight), ("TurnLeft", MotionCommand.TurnLeft),
        ("SideStepRight", MotionCommand.SideStepRight), ("SideStepLeft", MotionCommand.SideStepLeft), ("Falling", MotionCommand.Falling),
        ("Dead", MotionCommand.Dead), ("Fallen", MotionCommand.Fallen), ("Crouch", MotionCommand.Crouch), ("Sitting", MotionCommand.Sitting),
        ("Sleeping", MotionCommand.Sleeping), ("NonCombat", MotionCommand.NonCombat),
    ];

    /// <summary>The names, comma-separated (for error messages).</summary>
    internal static string List
    {
        get
        {
            var names = new List<string>(Known.Length);
            foreach (var (name, _) in Known) names.Add(name);
            return string.Join(", ", names);
        }
    }

    /// <summary>The id of a command name (case-sensitive, as <see cref="MotionCommand"/> spells it).</summary>
    public static bool TryId(string name, out uint id)
    {
        foreach (var k in Known)
            if (k.Name == name)
            {
                id = k.Id;
                return true;
            }
        id = 0;
        return false;
    }

    /// <summary>The command's name, or its hex id when it has none; "-" for 0 (no command).</summary>
    public static string Name(uint id)
    {
        if (id == 0) return "-";
        foreach (var k in Known)
            if (k.Id == id) return k.Name;
        return $"0x{id:X8}";
    }
}
