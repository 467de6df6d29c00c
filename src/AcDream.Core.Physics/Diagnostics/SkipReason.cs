using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Diagnostics;

/// <summary>Why an object's shape was not tested.</summary>
public enum SkipReason : byte
{
    /// <summary>The object has HasPhysicsBsp and no exemption applies: its cylinders and spheres are not tested (retail binary dispatch).</summary>
    BspOnlyDispatch = 0,
    /// <summary>The object collides through its cylinders or spheres, so its BSP parts are not tested.</summary>
    NotBspDispatch = 1,
    /// <summary>The object has cylinders, so its spheres are not tested.</summary>
    HasCylinders = 2,
    /// <summary>The object is ethereal and ignores collisions.</summary>
    EtherealIgnoreCollisions = 3,
    /// <summary>Missile-ignore or the PvP exemption removes the object from collision.</summary>
    Exempt = 4,
    /// <summary>The mover is the camera and the object a creature.</summary>
    ViewerVsCreature = 5,
    /// <summary>The object lies beyond reach of the mover's check spheres, so none of its shapes was tested (not a retail rule: retail would test it and find nothing).</summary>
    OutOfReach = 7,
    /// <summary>The object is ethereal and the path is stepping down.</summary>
    EtherealStepDown = 6,
}
