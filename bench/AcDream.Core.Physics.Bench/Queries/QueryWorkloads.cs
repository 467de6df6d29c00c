using AcDream.Core.Physics.Queries;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Bench.Queries;

/// <summary>
/// One call of each world query on the cottage scene (a room behind a doorway, a building shell, the
/// door in the doorway), and a player's transition for scale. Each returns something so the work is kept.
/// </summary>
public sealed class QueryWorkloads
{
    private const uint Land = 0xA9B40025, Room = 0xA9B40100;
    private readonly WorldQuery _query;
    private readonly PhysicsEngine _engine;
    private readonly MoverDescription _player = MoverDescription.Player();
    private readonly ObjectOverlap[] _found = new ObjectOverlap[16];

    /// <summary>The workloads, by name, in table order.</summary>
    public static readonly string[] Names =
        ["SphereCast (0.3 m, 6 m, hits the door)", "RayCast (pick, 8.5 m diagonal)", "Floor indoors (room floor)", "Floor outdoors (terrain)",
         "Cell at a point (indoor, through the building)", "OverlapSphere (1 m, at the door)", "OverlapBox (1 m half-size)", "CameraArm (room, 5 m, stops at the wall)",
         "Resolve (player, 0.1 m step, for scale)"];

    /// <summary>Loads the cottage and warms every query.</summary>
    public QueryWorkloads()
    {
        var world = SceneLibrary.Load("cottage").World;
        _query = new WorldQuery(world);
        _engine = new PhysicsEngine(world);
        for (int i = 0; i < Names.Length; i++)
            Run(i);
    }

    private static Position At(uint cell, float x, float y, float z) => new(cell, new Vector3(x, y, z));

    /// <summary>Runs workload <paramref name="index"/> once.</summary>
    public float Run(int index) => index switch
    {
        0 => _query.SphereCast(At(Land, 100, 97, 1), new Vector3(100, 103, 1), 0.3f, out var a) ? a.Fraction : -1f,
        1 => _query.RayCast(At(Land, 97, 97, 1.5f), new Vector3(103, 103, 1.5f), out var b) ? b.Fraction : -1f,
        2 => _query.TryFindFloor(At(Land, 100, 102, 2), 5, out var c) ? c.Point.Z : -1f,
        3 => _query.TryFindFloor(At(Land, 95, 95, 2), 5, out var d) ? d.Point.Z : -1f,
        4 => _query.TryFindCell(At(Land, 100, 102, 1), out var e) ? e.CellId : 0,
        5 => _query.OverlapSphere(At(Land, 100, 99.5f, 1), 1f, _found),
        6 => _query.OverlapBox(At(Land, 100, 99.5f, 1), new Vector3(1), _found),
        7 => _query.CameraArm(At(Room, 100, 101, 1.5f), new Vector3(100, 106, 1.5f)).Camera.Origin.Y,
        8 => _engine.Resolve(_player, MoverState.OnFloor(At(Land, 100, 97, 0), 0f), At(Land, 100, 97.1f, 0)).Position.Origin.Y,
        _ => throw new ArgumentOutOfRangeException(nameof(index)),
    };
}
