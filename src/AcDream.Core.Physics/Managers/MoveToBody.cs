namespace AcDream.Core.Physics.Managers;

/// <summary>What <see cref="MoveToManager"/> reads and writes of the object for one call (CPhysicsObj's position and flags).</summary>
internal struct MoveToBody
{
    public Position Position;
    public bool Contact;
    /// <summary>CPhysicsObj::IsInterpolating: the position manager has positions queued (a failed check is then not counted).</summary>
    public bool Interpolating;
    public uint Id;
    public float Radius, Height;
}
