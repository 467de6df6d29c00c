namespace AcDream.Core.Physics.Scenes;

/// <summary>What a scene command does (the <see cref="ObjectMotion"/> call it makes).</summary>
internal enum SceneCommandKind
{
    /// <summary><see cref="ObjectMotion.DoMotion"/>.</summary>
    Do,
    /// <summary><see cref="ObjectMotion.StopMotion"/>.</summary>
    Stop,
    /// <summary><see cref="ObjectMotion.StopCompletely"/>.</summary>
    StopCompletely,
    /// <summary><see cref="ObjectMotion.SetHoldKey"/>.</summary>
    SetHoldKey,
    /// <summary><see cref="ObjectMotion.ChargeJump"/> then <see cref="ObjectMotion.Jump"/>.</summary>
    Jump,
    /// <summary><see cref="ObjectMotion.MoveToPosition"/> (retail's MoveToManager; a server's creature chasing a point).</summary>
    MoveTo,
    /// <summary><see cref="Managers.PositionManager.InterpolateTo"/>: a position a server reports for the mover.</summary>
    InterpolateTo,
    /// <summary><see cref="Managers.PositionManager.StickTo"/> an earlier mover of the scene, then its position each frame (UpdateTarget).</summary>
    StickTo,
    /// <summary><see cref="Managers.PositionManager.UnStick"/>.</summary>
    UnStick,
}
