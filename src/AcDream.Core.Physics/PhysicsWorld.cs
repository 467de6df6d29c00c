using AcDream.Core.Physics.World;
namespace AcDream.Core.Physics;

/// <summary>Everything a transition collides with: the cells and the objects registered in them.</summary>
public sealed class PhysicsWorld
{
    /// <summary>Creates an empty world.</summary>
    public PhysicsWorld()
    {
        Cells = new CellGraph();
        Objects = new ShadowObjectRegistry(Cells);
    }

    /// <summary>The cells.</summary>
    public CellGraph Cells { get; }
    /// <summary>The objects.</summary>
    public ShadowObjectRegistry Objects { get; }
}
