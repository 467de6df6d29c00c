namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// One command of a motion mover, given before the step of <see cref="Frame"/> (commands of one frame in file
/// order), as a player's key press or a server's movement event reaches the motion layer between steps.
/// </summary>
/// <param name="Frame">The frame before whose step it is given.</param>
/// <param name="Kind">The call.</param>
/// <param name="Motion">The motion command (Do, Stop).</param>
/// <param name="Speed">Its speed (Do, Stop).</param>
/// <param name="HoldKey">The hold key given with it (Do, Stop), or the key set (SetHoldKey).</param>
/// <param name="Extent">The jump's extent, 0..1 (Jump).</param>
/// <param name="Stamina">The owner has the stamina (Jump).</param>
/// <param name="Path">Its JSON path, for error messages.</param>
/// <param name="Target">The point a MoveTo goes to (landblock-local to the mover's landblock).</param>
/// <param name="MoveTo">The MoveTo's parameters (retail's defaults unless the command names them).</param>
/// <param name="Position">The reported position (InterpolateTo).</param>
/// <param name="KeepHeading">Keep the mover's heading (InterpolateTo).</param>
/// <param name="TargetMover">The index in the scene of the mover stuck to (StickTo).</param>
/// <param name="Radius">The target's radius, m (StickTo).</param>
/// <param name="Height">The target's height, m (StickTo).</param>
/// <param name="ProgressRule">The MoveTo's progress rule: retail's client CountOnly unless the command opts in to GiveUp.</param>
internal readonly record struct SceneCommand(int Frame, SceneCommandKind Kind, uint Motion, float Speed, HoldKey HoldKey, float Extent,
    bool Stamina, string Path, System.Numerics.Vector3 Target = default, MoveToParameters MoveTo = default, Position Position = default,
    bool KeepHeading = false, int TargetMover = -1, float Radius = 0f, float Height = 0f,
    MoveToProgressRule ProgressRule = MoveToProgressRule.CountOnly);
