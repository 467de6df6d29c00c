using static AcDream.Core.Physics.Tests.Shapes.ShapeTestRig;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Shapes;

public class CylSphereCollisionTests
{
    // A cylinder on the origin, radius 1, height 2; the mover's sphere has radius 0.5.
    // radsum = 1 - EPSILON + 0.5 = 1.4998; the Z slab test is 0.5 - EPSILON + 1 >= |1 - dz|.
    private static readonly CylSphere Post = new(Vector3.Zero, 1f, 2f);
    private static readonly Sphere Ball = new(Vector3.Zero, 0.5f);
    private const float Radsum = 1f - Eps + 0.5f;

    [Theory]
    [InlineData(1.4f, 0f, 1f, true)]     // wall, overlapping
    [InlineData(1.5f, 0f, 1f, false)]    // wall, exactly touching: within EPSILON is not a hit
    [InlineData(0f, 0f, 2.4f, true)]     // top cap, overlapping
    [InlineData(0f, 0f, 2.5f, false)]    // top cap, exactly touching
    [InlineData(0f, 0f, -0.4f, true)]    // bottom cap, overlapping
    [InlineData(0f, 0f, -0.5f, false)]   // bottom cap, exactly touching
    public void CollidesWithSphere_WallAndCaps(float x, float y, float z, bool expected)
        => Assert.Equal(expected, CylSphereCollision.CollidesWithSphere(Post, Ball, new Vector3(x, y, z), Radsum));

    [Fact]
    public void CollidesWithSphere_IsASlabTest_TheRimCornerIsSquare()
    {
        // (1.4, 0, 2.4) is 0.566 from the rim edge (1, 2), outside a 0.5 sphere: a capsule or rounded test
        // would miss. Retail's slab test hits (CCylSphere::collides_with_sphere).
        Vector3 disp = new(1.4f, 0, 2.4f);
        Assert.True(Vector2.Distance(new Vector2(1.4f, 2.4f), new Vector2(1f, 2f)) > 0.5f);
        Assert.True(CylSphereCollision.CollidesWithSphere(Post, Ball, disp, Radsum));
    }

    [Theory]
    [InlineData(1.4999f, TransitionState.OK)]       // grazing: inside r_cyl + r_sphere but within EPSILON of it
    [InlineData(1.4996f, TransitionState.Collided)]
    public void Placement_GrazingTheWall(float x, TransitionState expected)
    {
        var t = Mover(new Vector3(x, 0, 1), new Vector3(x, 0, 1));
        t.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(expected, CylSphereResponses.IntersectsSphere(Post, t));
    }

    [Fact]
    public void CollisionNormal_StartOutsideTheCircle_IsRadial()
    {
        var t = Mover(new Vector3(-2, 1, 1), new Vector3(-1.2f, 0.2f, 1));
        bool definite = CylSphereCollision.CollisionNormal(Post, t.SpherePath.GlobalCurrCenter[0].Center, Ball, new Vector3(-1.2f, 0.2f, 1), Radsum, out var normal);
        Assert.Equal(new Vector3(-2, 1, 0), normal);
        Assert.True(definite); // the current position already overlaps the Z span
    }

    [Fact]
    public void CollisionNormal_StartInsideTheCircle_IsPlusZFallingAndMinusZRising()
    {
        var falling = Mover(new Vector3(0.2f, 0, 3), new Vector3(0.2f, 0, 2.4f));
        Assert.True(CylSphereCollision.CollisionNormal(Post, falling.SpherePath.GlobalCurrCenter[0].Center, Ball, new Vector3(0.2f, 0, 2.4f), Radsum, out var down));
        Assert.Equal(Vector3.UnitZ, down);

        var rising = Mover(new Vector3(0.2f, 0, -1), new Vector3(0.2f, 0, -0.4f));
        Assert.True(CylSphereCollision.CollisionNormal(Post, rising.SpherePath.GlobalCurrCenter[0].Center, Ball, new Vector3(0.2f, 0, -0.4f), Radsum, out var up));
        Assert.Equal(-Vector3.UnitZ, up);
    }

    [Fact]
    public void Grounded_AgainstTheWall_SlidesWithTheRadialNormal()
    {
        // From (-2,0,0.5) to (-1.3,0.2,0.5): the radial normal is -X, the floor +Z, so the slide keeps only the
        // move's Y (cross(-X, +Z) = +Y) and never enters the wall.
        var t = OnFloor(new Vector3(-2, 0, 0.5f), new Vector3(-1.3f, 0.2f, 0.5f), stepUpHeight: 0.1f);
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Slid, state);
        Near(-Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Near(new Vector3(-2, 0.2f, 0.5f), CheckOrigin(t));
    }

    [Fact]
    public void Airborne_LandingOnTheTopCap_RecordsPlusZStepUpCandidate()
    {
        var t = Mover(new Vector3(0.2f, 0, 3), new Vector3(0.2f, 0, 2.4f));
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Assert.True(t.SpherePath.Collide);
        Assert.Equal(Vector3.UnitZ, t.SpherePath.StepUpNormal);
        Assert.Equal(PhysicsConstants.LandingZ, t.SpherePath.WalkableAllowance);
    }

    [Fact]
    public void PendingCollide_BacksUpOntoTheTopCap()
    {
        // Falling 0.6 and sunk to 2.4: backed up by 0.1 (1/6 of the move) so the bottom sits on z = 2.
        var t = Mover(new Vector3(0.2f, 0, 3), new Vector3(0.2f, 0, 2.4f));
        t.SpherePath.Collide = true;
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0.2f, 0, 2.5f), CheckOrigin(t));
        Assert.Equal(Vector3.UnitZ, t.CollisionInfo.ContactPlane.Normal);
        Assert.Equal(-2f, t.CollisionInfo.ContactPlane.D, 4);
        Assert.Equal(1f - 1f / 6f, t.SpherePath.WalkInterp, 4);
    }

    [Fact]
    public void StepDown_RestsOnTheTopCap()
    {
        var t = Mover(new Vector3(0, 0, 2.8f), new Vector3(0, 0, 2.3f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        // Lift 2 + 0.5 - 2.3 = 0.2, i.e. 0.4 of the 0.5 step: walk_interp 0.6.
        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0, 0, 2.5f), CheckOrigin(t));
        Assert.Equal(0.6f, t.SpherePath.WalkInterp, 4);
        Assert.Equal(-2f, t.CollisionInfo.ContactPlane.D, 4);
        Assert.Equal(CellId, t.CollisionInfo.ContactPlaneCellId);
    }

    /// <summary>
    /// CCylSphere::step_sphere_down (acclient.c:361573) refuses a lift whose walk fraction falls below −0.1: a
    /// check sphere a little below the lift the step allows still rests on the cap, one further below collides.
    /// Post height 2, radius 0.5, step 0.5: lift = 2.5 − z, walk_interp = 1 − lift / 0.5.
    /// </summary>
    [Theory]
    [InlineData(1.98f, TransitionState.Adjusted)] // lift 0.52: walk_interp −0.04, within the floor
    [InlineData(1.9f, TransitionState.Collided)]  // lift 0.6: walk_interp −0.2, below it
    [InlineData(1.8f, TransitionState.Collided)]  // lift 0.7: walk_interp −0.4
    public void StepDown_WalkInterpFloorIsMinusOneTenth(float z, TransitionState expected)
    {
        var t = Mover(new Vector3(0, 0, z + 0.5f), new Vector3(0, 0, z));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        Assert.Equal(expected, CylSphereResponses.IntersectsSphere(Post, t));
        if (expected == TransitionState.Adjusted)
        {
            Assert.Equal(2.5f, CheckOrigin(t).Z, 4);
            Assert.Equal(1f - (2.5f - z) / 0.5f, t.SpherePath.WalkInterp, 4);
        }
        else
            Assert.Equal(1f, t.SpherePath.WalkInterp);
    }

    /// <summary>
    /// Retail CCylSphere::step_sphere_down (acclient.c:361573) keeps the lift and the walk fraction on the
    /// x87 stack at double precision and rounds only its float stores. By hand, for a post 1.7 m high, a
    /// check sphere of radius 0.48 at z = 2.1556098461151123 stepping down 0.5: lift = f(1.7f + 0.48f − z)
    /// = 0.024390190839767456 and walk_interp = f(1 − lift/0.5) = 0.95121961832046509, both from the
    /// unrounded double lift; in float the lift rounds twice (0.024390220642089844) and walk_interp lands one
    /// float step lower (0.95121955871582031).
    /// </summary>
    [Fact]
    public void StepDown_ComputesTheLiftInDoublePrecision_AsRetailsX87()
    {
        var t = Mover(new Vector3(0, 0, 2.6556098461151123f), new Vector3(0, 0, 2.1556098461151123f), radius: 0.48f);
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        var state = CylSphereResponses.IntersectsSphere(new CylSphere(Vector3.Zero, 1f, 1.7f), t);

        Assert.Equal(TransitionState.Adjusted, state);
        Assert.Equal(0.95121961832046509f, t.SpherePath.WalkInterp);
        Assert.Equal(2.1556098461151123f + 0.024390190839767456f, CheckOrigin(t).Z);
        Assert.Equal(-1.7000000476837158f, t.CollisionInfo.ContactPlane.D);
    }

    [Fact]
    public void PerfectClip_Wall_SolvesTheSweptCircleTimeOfImpact()
    {
        // From x=-3 to x=-1.2 at mid height: contact at XY distance radsum + EPSILON = 1.5, reached after
        // moving 1.5 of 1.8, t = 5/6; the sphere is put at x = -1.5 with the radial normal -X.
        var t = Mover(new Vector3(-3, 0, 1), new Vector3(-1.2f, 0, 1), state: ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(-1.5f, 0, 1), CheckOrigin(t));
        Near(-Vector3.UnitX, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void WallTime_NegativeNearRootTakesTheFarRoot()
    {
        // Starting inside the reach circle (x = -1 of 1.5) and moving +X by 4: x(t) = -1 + 4t meets |x| = 1.5
        // at t = -0.125 (near) and 0.625 (far); retail takes the far root.
        var movement = new Vector3(4, 0, 0);
        Assert.True(CylSphereCollision.WallTime(movement, new Vector3(-1, 0, 0), 1.5f, 16f, out float time));
        Assert.Equal(0.625f, time, 5);
        Assert.False(CylSphereCollision.WallTime(movement, new Vector3(-3, 2, 0), 1.5f, 16f, out _));
    }

    [Fact]
    public void PerfectClip_TopCap_SolvesTheCapTimeOfImpact()
    {
        // Falling from z=3.5 to 2.3 over the cap: the bottom reaches z=2 after 1.0 of 1.2, t = 5/6, normal +Z.
        var t = Mover(new Vector3(0.2f, 0, 3.5f), new Vector3(0.2f, 0, 2.3f), state: ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0.2f, 0, 2.5f), CheckOrigin(t));
        Near(Vector3.UnitZ, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void PerfectClip_OverTheRim_LandsOnTheCapWhenTheCapPointIsInside()
    {
        // Diagonal from (-2,0,4) to (-1.2,0,2.3): starting outside both the circle and the Z span, the normal is
        // not definite; the cap time (0.5 + 2 - 4)/-1.7 = 15/17 puts the centre at x = -2 + 0.8*15/17, within
        // the 1.5 reach, so the cap wins: normal +Z and the sphere rests on the cap.
        var t = Mover(new Vector3(-2, 0, 4), new Vector3(-1.2f, 0, 2.3f), state: ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        var state = CylSphereResponses.IntersectsSphere(Post, t);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(-2f + 0.8f * 15f / 17f, 0, 2.5f), CheckOrigin(t));
        Near(Vector3.UnitZ, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void PathClipped_WithoutPerfectClip_RecordsTheNormalAndCollides()
    {
        var t = Mover(new Vector3(-3, 0, 1), new Vector3(-1.2f, 0, 1), state: ObjectInfoState.PathClipped);
        Assert.Equal(TransitionState.Collided, CylSphereResponses.IntersectsSphere(Post, t));
        Near(-Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Near(new Vector3(-1.2f, 0, 1), CheckOrigin(t));
    }

    [Fact]
    public void OwnerFrame_RotatedOwner_CylinderStaysWorldZAligned()
    {
        // Owner rotated 90° about X: a rotated axis would lie along -Y. Retail transforms only the low point.
        var owner = new Position(CellId, new Frame(new Vector3(10, 10, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI / 2)));
        var local = new CylSphere(new Vector3(1, 0, 0), 0.5f, 2f);

        CylSphere placed = CylSphereCollision.ToCheckSpace(local, owner, 1f, new Position(CellId, Vector3.Zero));
        Near(new Vector3(11, 10, 0), placed.LowPoint);

        // A sphere 1.5 up the world Z axis is inside; one 1.5 along the rotated axis (-Y) is outside.
        var above = Mover(new Vector3(11, 10, 1.5f), new Vector3(11, 10, 1.5f));
        above.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.Collided, CylSphereResponses.IntersectsSphere(local, owner, 1f, above));

        var alongRotatedAxis = Mover(new Vector3(11, 8.5f, 0), new Vector3(11, 8.5f, 0));
        alongRotatedAxis.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.OK, CylSphereResponses.IntersectsSphere(local, owner, 1f, alongRotatedAxis));
    }

    [Fact]
    public void OwnerFrame_ScalesRadiusHeightAndLowPoint()
    {
        var owner = new Position(CellId, new Frame(new Vector3(10, 10, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2)));
        CylSphere placed = CylSphereCollision.ToCheckSpace(new CylSphere(new Vector3(1, 0, 0), 0.5f, 1f), owner, 2f, new Position(CellId, Vector3.Zero));
        Near(new Vector3(10, 12, 0), placed.LowPoint);
        Assert.Equal(1f, placed.Radius);
        Assert.Equal(2f, placed.Height);
    }

    [Fact]
    public void SecondSphere_IsTestedWithSphereZerosRadiusSum()
    {
        // A cylinder r 0.5, h 1 from z 1.2, 0.9 away in XY. Sphere 0 (r 0.5 at z 0.5) is below its slab;
        // sphere 1 (r 0.3 at z 1.5) overlaps the slab and is 0.9 from the axis: apart by its own sum 0.8,
        // but retail uses sphere 0's radsum 0.5 - EPSILON + 0.5 (CCylSphere::intersects_sphere).
        var t = TwoSpherePlacement(Vector3.Zero);
        Assert.Equal(TransitionState.Collided, CylSphereResponses.IntersectsSphere(new CylSphere(new Vector3(0.9f, 0, 1.2f), 0.5f, 1f), t));
        Assert.Equal(TransitionState.OK, CylSphereResponses.IntersectsSphere(new CylSphere(new Vector3(1.01f, 0, 1.2f), 0.5f, 1f), t));
    }
}
