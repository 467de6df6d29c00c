namespace AcDream.Core.Physics;

/// <summary>One start or end of a contact, as <see cref="ContactTracker.Events"/> lists them.</summary>
public readonly struct ContactEvent
{
    internal ContactEvent(ContactEventKind kind, uint objectId)
    {
        Kind = kind;
        ObjectId = objectId;
    }

    /// <summary>Start or end, of an object or of the environment.</summary>
    public ContactEventKind Kind { get; }

    /// <summary>The object's id (0 for the environment).</summary>
    public uint ObjectId { get; }

    /// <inheritdoc />
    public override string ToString() => ObjectId == 0 ? Kind.ToString() : $"{Kind} 0x{ObjectId:X8}";
}
