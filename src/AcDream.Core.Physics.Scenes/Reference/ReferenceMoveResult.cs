using System.Numerics;

namespace AcDream.Core.Physics.Reference;

/// <summary>The outcome of one <see cref="ReferenceSweep.Move"/>.</summary>
public readonly struct ReferenceMoveResult
{
    /// <summary>Creates a result.</summary>
    public ReferenceMoveResult(Vector3 position, int contacts, Vector3 firstNormal, Vector3 lastNormal, float firstContactDistance)
    {
        Position = position;
        Contacts = contacts;
        FirstNormal = firstNormal;
        LastNormal = lastNormal;
        FirstContactDistance = firstContactDistance;
    }

    /// <summary>Where the mover ends.</summary>
    public Vector3 Position { get; }
    /// <summary>How many contacts stopped or deflected the motion (0: moved freely).</summary>
    public int Contacts { get; }
    /// <summary>The first contact's normal (as slid along: horizontal for a grounded mover), or zero.</summary>
    public Vector3 FirstNormal { get; }
    /// <summary>The last contact's normal, or zero.</summary>
    public Vector3 LastNormal { get; }
    /// <summary>How far the mover travelled before its first contact (metres), or the whole distance.</summary>
    public float FirstContactDistance { get; }
    /// <summary>Whether anything was touched.</summary>
    public bool Collided => Contacts > 0;
}
