using static AcDream.Core.Physics.Tests.Shapes.ShapeTestRig;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Shapes;

/// <summary>Limits and rarely taken arms of the cylinder and sphere routines, with hand-computed results.</summary>
public class ShapeLimitTests
{
    private static readonly CylSphere Post = new(Vector3.Zero, 1f, 2f);

    // CCylSphere::step_sphere_down: a 0.5 m probe; the sphere (r 0.5) must rise lift = 2 + 0.5 − z onto
    // the cap; walk fraction 1 − lift / 0.5, accepted down to −0.1 (lift up to 0.55).

    [Fact]
    public void CylinderStepDown_ALiftJustWithinOnePointOneProbes_IsAccepted()
    {
        // z = 1.96: lift 0.54, fraction −0.08: the sphere rests on the cap (centre z 2.5).
        var t = Mover(new Vector3(0, 0, 2.46f), new Vector3(0, 0, 1.96f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        Assert.Equal(TransitionState.Adjusted, CylSphereResponses.IntersectsSphere(Post, t));
        Near(new Vector3(0, 0, 2.5f), CheckOrigin(t));
        Assert.Equal(-0.08f, t.SpherePath.WalkInterp, 4);
    }

    [Fact]
    public void CylinderStepDown_ALiftOfTwoProbes_IsRefused()
    {
        // z = 1.5: lift 1.0, fraction −1: Collided, the check position unchanged.
        var t = Mover(new Vector3(0, 0, 2f), new Vector3(0, 0, 1.5f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        Assert.Equal(TransitionState.Collided, CylSphereResponses.IntersectsSphere(Post, t));
        Near(new Vector3(0, 0, 1.5f), CheckOrigin(t));
    }

    [Fact]
    public void PerfectClip_RisingIntoTheBottomCap_StopsUnderIt()
    {
        // From z = −1.5 up to −0.3 (r 0.5) under the post: inside the circle and rising, normal −Z; the top
        // of the sphere meets the bottom cap (z = 0) when the centre is at −0.5, after 1.0 of 1.2: t = 5/6.
        var t = Mover(new Vector3(0.2f, 0, -1.5f), new Vector3(0.2f, 0, -0.3f), state: ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        Assert.Equal(TransitionState.Adjusted, CylSphereResponses.IntersectsSphere(Post, t));
        Near(new Vector3(0.2f, 0, -0.5f), CheckOrigin(t));
        Near(-Vector3.UnitZ, t.CollisionInfo.CollisionNormal);
    }

    // CSphere::slide_sphere when the collision normal (target centre → current centre) is parallel to the
    // contact plane's (+Z): no crease. Retail then tests the contact normal against disp (check centre −
    // target centre): pressing into the plane is Collided; otherwise the move loses its part along the normal.

    [Fact]
    public void SphereSlide_WithoutACrease_AboveTheTarget_DropsTheMoveAlongTheNormal()
    {
        // Current (0, 0, 1) right above a target at the origin, check (0.3, 0, 0.9): disp·(+Z) = 0.9 ≥ 0;
        // the move (0.3, 0, −0.1) loses −0.1 along +Z: the check position becomes (0.3, 0, 1).
        var t = OnFloor(new Vector3(0, 0, 1), new Vector3(0.3f, 0, 0.9f));
        var state = SphereResponses.SlideSphereFromTarget(new Sphere(Vector3.Zero, 0.5f), t, new Vector3(0.3f, 0, 0.9f), 0);
        Assert.Equal(TransitionState.Slid, state);
        Near(new Vector3(0.3f, 0, 1f), CheckOrigin(t));
    }

    [Fact]
    public void SphereSlide_WithoutACrease_BelowTheTarget_Collides()
    {
        // Current (0, 0, −1) right under the target: normal −Z, still parallel to +Z; disp = (0.3, 0, −0.9)
        // points against the contact normal: Collided, the check position unchanged.
        var t = OnFloor(new Vector3(0, 0, -1), new Vector3(0.3f, 0, -0.9f));
        var state = SphereResponses.SlideSphereFromTarget(new Sphere(Vector3.Zero, 0.5f), t, new Vector3(0.3f, 0, -0.9f), 0);
        Assert.Equal(TransitionState.Collided, state);
        Near(new Vector3(0.3f, 0, -0.9f), CheckOrigin(t));
    }

    [Fact]
    public void CylinderSlide_OfTheUpperSphere_IsMeasuredFromItsOwnCurrentCentre()
    {
        // A grounded two-sphere mover (r 0.5 at z 0.5 and 1.5) under a floating post (low point z 1,
        // radius 0.5, height 1): sphere 0's top (z 1.0) misses it by EPSILON, sphere 1 hits. From (−1.2, 0)
        // towards (−0.9, 0.3): the normal is radial, (−1, 0, 0); the crease with the floor (+Z) is (0, 1, 0);
        // sphere 1's move (0.3, 0.3, 0) keeps only (0, 0.3, 0): the check origin becomes (−1.2, 0.3, 0).
        var t = new Transition(new PhysicsWorld());
        t.SpherePath.InitSphere(new[] { new Sphere(new Vector3(0, 0, 0.5f), 0.5f), new Sphere(new Vector3(0, 0, 1.5f), 0.5f) }, 1f);
        t.SpherePath.InitPath(null, new Position(CellId, new Vector3(-1.2f, 0, 0)), new Position(CellId, new Vector3(-0.9f, 0.3f, 0)));
        t.SpherePath.SetCheckPos(new Position(CellId, new Vector3(-0.9f, 0.3f, 0)), null);
        t.SpherePath.WalkInterp = 1f;
        t.ObjectInfo.State = ObjectInfoState.Contact | ObjectInfoState.OnWalkable;
        t.ObjectInfo.StepUpHeight = 0.1f;
        t.CollisionInfo.SetContactPlane(new Plane(Vector3.UnitZ, 0f), isWater: false);
        var floating = new CylSphere(new Vector3(0, 0, 1f), 0.5f, 1f);

        Assert.Equal(TransitionState.Slid, CylSphereResponses.IntersectsSphere(floating, t));
        Near(new Vector3(-1.2f, 0.3f, 0), CheckOrigin(t));
    }
}
