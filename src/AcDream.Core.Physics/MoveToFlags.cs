using System;

namespace AcDream.Core.Physics;

/// <summary>Retail's MovementParameters bits (the bitfield MovementParameters::get_command and the MoveToManager read).</summary>
[Flags]
public enum MoveToFlags : uint
{
    /// <summary>None.</summary>
    None = 0,
    /// <summary>May walk (without it a mover that can run always runs).</summary>
    CanWalk = 0x1,
    /// <summary>May run: runs when farther than the walk/run threshold beyond the distance to the object.</summary>
    CanRun = 0x2,
    /// <summary>May sidestep (carried; retail's MoveToManager does not read it).</summary>
    CanSidestep = 0x4,
    /// <summary>May walk backwards (carried; not read by the MoveToManager).</summary>
    CanWalkBackwards = 0x8,
    /// <summary>Always run (get_command's first test).</summary>
    CanCharge = 0x10,
    /// <summary>Carried; not read by the MoveToManager.</summary>
    FailWalk = 0x20,
    /// <summary>Turn to <see cref="MoveToParameters.DesiredHeading"/> after arriving (relative to the target's heading for an object).</summary>
    UseFinalHeading = 0x40,
    /// <summary>
    /// Stick to the object on arrival: a MoveToObject or TurnToObject that arrives calls the object's
    /// <see cref="Managers.PositionManager.StickTo"/> on the target (retail's BeginNextNode; see
    /// <see cref="ObjectMotion.StickOnArrival"/>). MoveToPosition and TurnToHeading clear it, as retail does.
    /// </summary>
    Sticky = 0x80,
    /// <summary>Move away until <see cref="MoveToParameters.MinDistance"/>.</summary>
    MoveAway = 0x100,
    /// <summary>Move towards until <see cref="MoveToParameters.DistanceToObject"/>.</summary>
    MoveTowards = 0x200,
    /// <summary>Measure the distance between the two cylinders (radius, height) instead of the origins.</summary>
    UseSpheres = 0x400,
    /// <summary>Carried to the motion commands.</summary>
    SetHoldKey = 0x800,
    /// <summary>Carried.</summary>
    Autonomous = 0x1000,
    /// <summary>Carried to the motion commands.</summary>
    ModifyRawState = 0x2000,
    /// <summary>Carried to the motion commands.</summary>
    ModifyInterpretedState = 0x4000,
    /// <summary>Carried.</summary>
    CancelMoveTo = 0x8000,
    /// <summary>TurnToHeading and TurnToObject stop the mover first.</summary>
    StopCompletely = 0x10000,
    /// <summary>Carried to the motion commands.</summary>
    DisableJumpDuringLink = 0x20000,
    /// <summary>
    /// Retail's default bitfield (MovementParameters::MovementParameters, acclient.c:339436: 0x1EE0F): can walk, run,
    /// sidestep and walk backwards; towards; spheres; set hold key; modify raw and interpreted state; cancel moveto;
    /// stop completely. Not CanCharge (ACE's constructor sets it).
    /// </summary>
    RetailDefault = 0x1EE0F,
}
