using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>What <see cref="MotionInterpreter"/> reads and writes of the physics object (CPhysicsObj).</summary>
internal struct InterpreterBody
{
    public bool Gravity;
    public bool Contact;
    public bool OnWalkable;
    public Quaternion Orientation;
    public Vector3 Velocity;
}
