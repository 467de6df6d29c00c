using AcDream.Core.Physics.Transitions;

namespace AcDream.Core.Physics.Tests.Shapes;

/// <summary>Builds a transition by hand: one mover sphere centred on the position's origin.</summary>
internal static class ShapeTestRig
{
    public const uint CellId = 0xA9B40001;
    public const float Eps = PhysicsConstants.Epsilon;

    public static Transition Mover(Vector3 current, Vector3 check, float radius = 0.5f, ObjectInfoState state = ObjectInfoState.None)
    {
        var transition = new Transition(new PhysicsWorld());
        transition.SpherePath.InitSphere(new[] { new Sphere(Vector3.Zero, radius) }, 1f);
        transition.SpherePath.InitPath(null, new Position(CellId, current), new Position(CellId, check));
        transition.SpherePath.SetCheckPos(new Position(CellId, check), null);
        transition.SpherePath.WalkInterp = 1f;
        transition.SpherePath.WalkableAllowance = PhysicsConstants.FloorZ;
        transition.ObjectInfo.State = state;
        return transition;
    }

    /// <summary>A placement of a two-sphere mover: sphere 0 radius 0.5 at z 0.5, sphere 1 radius 0.3 at z 1.5.</summary>
    public static Transition TwoSpherePlacement(Vector3 origin)
    {
        var transition = new Transition(new PhysicsWorld());
        transition.SpherePath.InitSphere(new[] { new Sphere(new Vector3(0, 0, 0.5f), 0.5f), new Sphere(new Vector3(0, 0, 1.5f), 0.3f) }, 1f);
        transition.SpherePath.InitPath(null, null, new Position(CellId, origin));
        transition.SpherePath.SetCheckPos(new Position(CellId, origin), null);
        return transition;
    }

    /// <summary>A grounded mover on a flat floor (contact plane +Z).</summary>
    public static Transition OnFloor(Vector3 current, Vector3 check, float stepUpHeight = 0.1f)
    {
        var transition = Mover(current, check, state: ObjectInfoState.Contact | ObjectInfoState.OnWalkable);
        transition.CollisionInfo.SetContactPlane(new Plane(Vector3.UnitZ, 0f), isWater: false);
        transition.ObjectInfo.StepUpHeight = stepUpHeight;
        return transition;
    }

    public static Vector3 CheckOrigin(Transition t) => t.SpherePath.CheckPos.Frame.Origin;

    public static void Near(Vector3 expected, Vector3 actual, float tolerance = 1e-4f)
    {
        Assert.True(Vector3.Distance(expected, actual) <= tolerance, $"expected {expected}, got {actual}");
    }
}
