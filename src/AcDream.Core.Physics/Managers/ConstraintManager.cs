namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Retail ConstraintManager (CConstraintManager.c): a leash. From <see cref="ConstrainTo"/> on, the object's
/// offsets are scaled down linearly once it is past the start distance and zeroed past the max distance, while it
/// touches the ground. Retail quirk kept: the distance measured is the one from the constraint position at
/// ConstrainTo plus the length of every offset since (constraint_pos_offset), a path length, not the current
/// distance from the constraint position; moving back towards it also counts.
/// </summary>
internal sealed class ConstraintManager
{
    public bool IsConstrained { get; private set; }
    public Position ConstraintPosition { get; private set; }
    public float StartDistance { get; private set; }
    public float MaxDistance { get; private set; }
    /// <summary>constraint_pos_offset: the distance counted so far (m).</summary>
    public float Offset { get; private set; }

    /// <summary>ConstraintManager::ConstrainTo (CConstraintManager.c:389513).</summary>
    public void ConstrainTo(in Position position, float startDistance, float maxDistance, in Position current)
    {
        IsConstrained = true;
        ConstraintPosition = position;
        StartDistance = startDistance;
        MaxDistance = maxDistance;
        Offset = (float)Distances.Between(position, current);
    }

    /// <summary>ConstraintManager::UnConstrain.</summary>
    public void UnConstrain() => IsConstrained = false;

    /// <summary>ConstraintManager::IsFullyConstrained: more than 90 % of the max distance used.</summary>
    public bool IsFullyConstrained => MaxDistance * 0.9 < Offset;

    /// <summary>ConstraintManager::adjust_offset (CConstraintManager.c:389477).</summary>
    public void AdjustOffset(ref Frame offset, bool contact)
    {
        if (!IsConstrained)
            return;
        if (contact)
        {
            if (Offset < MaxDistance)
            {
                if (Offset > StartDistance)
                    offset.Origin *= (MaxDistance - Offset) / (MaxDistance - StartDistance);
            }
            else
            {
                offset.Origin = default;
            }
        }
        var o = offset.Origin;
        Offset = (float)(System.Math.Sqrt((double)o.X * o.X + (double)o.Y * o.Y + (double)o.Z * o.Z) + Offset);
    }
}
