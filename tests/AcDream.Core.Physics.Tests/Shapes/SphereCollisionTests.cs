using static AcDream.Core.Physics.Tests.Shapes.ShapeTestRig;
using AcDream.Core.Physics.Shapes;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Shapes;

public class SphereCollisionTests
{
    // Two spheres of radius 0.5: they touch at a centre distance of 1; retail's radsum is 1 - EPSILON.

    [Fact]
    public void CollidesWithSphere_TouchingCounts_ApartDoesNot()
    {
        Assert.True(SphereCollision.CollidesWithSphere(new Vector3(0.6f, 0.8f, 0f), 1.0f)); // |disp| = 1 exactly
        Assert.True(SphereCollision.CollidesWithSphere(new Vector3(0.5f, 0f, 0f), 1.0f));
        Assert.False(SphereCollision.CollidesWithSphere(new Vector3(1.001f, 0f, 0f), 1.0f));
    }

    [Theory]
    [InlineData(0.5f, TransitionState.Collided)]              // deep overlap
    [InlineData(1f - 2 * Eps, TransitionState.Collided)]      // overlapping by 2 EPSILON
    [InlineData(1f - 0.5f * Eps, TransitionState.OK)]         // overlapping by less than EPSILON: retail lets it rest
    [InlineData(1.0f, TransitionState.OK)]                    // exactly touching
    [InlineData(1.5f, TransitionState.OK)]                    // apart
    public void Placement_OverlapUsesRadsumLessEpsilon(float distance, TransitionState expected)
    {
        var t = Mover(new Vector3(distance, 0, 0), new Vector3(distance, 0, 0));
        t.SpherePath.InsertType = InsertType.Placement;
        var target = new Sphere(Vector3.Zero, 0.5f);
        Assert.Equal(expected, SphereResponses.IntersectsSphere(target, t, isCreature: false));
    }

    [Fact]
    public void FindTimeOfCollision_KnownClosingSpeed()
    {
        // Starts 3 from the centre, closes along the line by 4 per step; reach 1 after moving 2: t = 0.5.
        double t = SphereCollision.FindTimeOfCollision(new Vector3(4, 0, 0), new Vector3(-3, 0, 0), 1f);
        Assert.Equal(0.5, t, 6);
    }

    [Fact]
    public void FindTimeOfCollision_ReceedingTakesTheFarRoot_StartingInsideOrMissingIsMinusOne()
    {
        // Moving away: near root (-12-4)/16 is negative, so retail returns the far root (-12+4)/16 = -0.5.
        Assert.Equal(-0.5, SphereCollision.FindTimeOfCollision(new Vector3(-4, 0, 0), new Vector3(-3, 0, 0), 1f), 6);
        Assert.Equal(-1.0, SphereCollision.FindTimeOfCollision(new Vector3(4, 0, 0), new Vector3(-0.5f, 0, 0), 1f));
        Assert.Equal(-1.0, SphereCollision.FindTimeOfCollision(new Vector3(4, 0, 0), new Vector3(-3, 2, 0), 1f));
        Assert.Equal(-1.0, SphereCollision.FindTimeOfCollision(Vector3.Zero, new Vector3(-3, 0, 0), 1f));
    }

    [Fact]
    public void PerfectClip_IsPulledBackToTheTimeOfImpact()
    {
        // From x=-3 to x=-0.5 towards a sphere at the origin; contact distance radsum + EPSILON = 1:
        // impact at x = -1, i.e. t = 2/2.5 = 0.8 of the move.
        var t = Mover(new Vector3(-3, 0, 0), new Vector3(-0.5f, 0, 0),
            state: ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip);
        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(-1, 0, 0), CheckOrigin(t));
        Near(new Vector3(-1, 0, 0), t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void PathClipped_WithoutPerfectClip_RecordsNormalFromTargetToCurrentAndCollides()
    {
        var t = Mover(new Vector3(-3, 4, 0), new Vector3(-0.5f, 0, 0), state: ObjectInfoState.PathClipped);
        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Collided, state);
        Near(new Vector3(-0.6f, 0.8f, 0), t.CollisionInfo.CollisionNormal);
        Near(new Vector3(-0.5f, 0, 0), CheckOrigin(t));
    }

    [Fact]
    public void Airborne_LandsOn_RecordsStepUpCandidate()
    {
        var t = Mover(new Vector3(0, 0, 2), new Vector3(0, 0, 0.9f));
        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Adjusted, state);
        Assert.True(t.SpherePath.Collide);
        Near(Vector3.UnitZ, t.SpherePath.StepUpNormal);
        Assert.Equal(PhysicsConstants.LandingZ, t.SpherePath.WalkableAllowance);
    }

    [Fact]
    public void Grounded_TooHighToStepUp_SlidesAlongTheTangent()
    {
        // Target at (1,0,0.5); mover from (-0.2,0,0.5) to (0.1,0.3,0.5). Normal from target to current is -X,
        // the floor is +Z, so the slide direction is cross(-X, +Z) = +Y: the move (0.3,0.3,0) keeps only its Y.
        var t = OnFloor(new Vector3(-0.2f, 0, 0.5f), new Vector3(0.1f, 0.3f, 0.5f), stepUpHeight: 0.1f);
        var state = SphereResponses.IntersectsSphere(new Sphere(new Vector3(1, 0, 0.5f), 0.5f), t, false);

        Assert.Equal(TransitionState.Slid, state);
        Near(new Vector3(-0.2f, 0.3f, 0.5f), CheckOrigin(t));
        Near(-Vector3.UnitX, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void SlideSphere_AgainstWallOnFloor_MovesAlongCrossOfNormalAndContactNormal_NeverIntoTheWall()
    {
        var t = OnFloor(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0.4f, 0.5f));
        var wallNormal = -Vector3.UnitX; // the wall is on +X, facing the mover
        var current = new Vector3(0, 0, 0.5f);

        var state = SphereResponses.SlideSphere(t, CheckOrigin(t), 0.5f, ref wallNormal, current);

        Assert.Equal(TransitionState.Slid, state);
        Vector3 slid = CheckOrigin(t) - current;
        Vector3 tangent = Vector3.Cross(-Vector3.UnitX, Vector3.UnitZ);
        Near(new Vector3(0, 1, 0), tangent);
        Near(tangent * 0.4f, slid);
        Assert.True(Vector3.Dot(slid, Vector3.UnitX) <= 0f, "the slide must not enter the wall");
        Near(-Vector3.UnitX, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void SlideSphere_StraightIntoTheWall_ZeroLengthTangentMove_Collides()
    {
        var t = OnFloor(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0, 0.5f));
        var wallNormal = -Vector3.UnitX;

        var state = SphereResponses.SlideSphere(t, CheckOrigin(t), 0.5f, ref wallNormal, new Vector3(0, 0, 0.5f));

        Assert.Equal(TransitionState.Collided, state);
        Near(new Vector3(0.3f, 0, 0.5f), CheckOrigin(t));
    }

    [Fact]
    public void SlideSphere_ZeroNormal_MovesHalfWayBack()
    {
        var t = OnFloor(new Vector3(0, 0, 0.5f), new Vector3(0.4f, 0.2f, 0.5f));
        var normal = Vector3.Zero;
        var state = SphereResponses.SlideSphere(t, CheckOrigin(t), 0.5f, ref normal, new Vector3(0, 0, 0.5f));

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0.2f, 0.1f, 0.5f), CheckOrigin(t));
    }

    [Fact]
    public void SlideSphere_NormalAlongContactNormal_ProjectsTheMoveOffTheNormal()
    {
        var t = OnFloor(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0.4f, 0.3f));
        var normal = Vector3.UnitZ;
        var state = SphereResponses.SlideSphere(t, CheckOrigin(t), 0.5f, ref normal, new Vector3(0, 0, 0.5f));

        Assert.Equal(TransitionState.Slid, state);
        Near(new Vector3(0.3f, 0.4f, 0.5f), CheckOrigin(t));
    }

    [Fact]
    public void SlideSphere_NormalAgainstContactNormal_CollidesWithReversedMoveAsNormal_RetailNotAce()
    {
        // Retail returns Collided here (ACE's port returns OK) and records the reversed move as the normal.
        var t = OnFloor(new Vector3(0, 0, 0.5f), new Vector3(0.3f, 0.4f, 0.5f));
        var normal = -Vector3.UnitZ;
        var state = SphereResponses.SlideSphere(t, CheckOrigin(t), 0.5f, ref normal, new Vector3(0, 0, 0.5f));

        Assert.Equal(TransitionState.Collided, state);
        Near(new Vector3(-0.6f, -0.8f, 0), normal);
        Near(new Vector3(-0.6f, -0.8f, 0), t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void StepDown_RestsOnTopOfTheTarget_WithContactPlaneAndWalkInterp()
    {
        // Stepping down 0.5, the sphere sank to z=0.8 over a target at the origin: it is lifted 0.2 to rest at
        // z = 1 (radsum + EPSILON = 1), 0.4 of the step, so walk_interp becomes 0.6.
        var t = Mover(new Vector3(0, 0, 1.3f), new Vector3(0, 0, 0.8f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;

        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0, 0, 1.0f), CheckOrigin(t));
        Assert.Equal(0.6f, t.SpherePath.WalkInterp, 4);
        Near(Vector3.UnitZ, t.CollisionInfo.ContactPlane.Normal);
        Assert.Equal(-0.5f, t.CollisionInfo.ContactPlane.D, 4);
        Assert.True(t.CollisionInfo.ContactPlaneIsWater); // retail quirk: set_contact_plane(…, 1)
        Assert.Equal(CellId, t.CollisionInfo.ContactPlaneCellId);
    }

    /// <summary>
    /// Retail computes CSphere::step_sphere_down (acclient.c:358615) on the x87 stack at double precision
    /// (53-bit, ClientMain::ConfigureFPU, acclient.c:60885), storing floats only at its float locals. Stepping
    /// down 0.5 onto a target of radius 0.5 with the check sphere (radius 0.5) at (0.3, 0.2, 0.6) from it, by
    /// hand in that sequence: radsum = f(1 − 0.0002f); reach = radsum + 0.0002f in double;
    /// fraction = (√(reach · f(reach) − (f(0.3²) + f(0.2²))) − 0.6f) / 0.5 in double; lift = f(0.5 · fraction)
    /// = 0.33273789286613464; normal = (f(0.3f / f(reach)), f(0.2f / f(reach)), f((lift + 0.6f) / f(reach)))
    /// with the divisions in double = (0.3f, 0.2f, 0.93273794651031494); walk_interp = f(1 − fraction)
    /// = 0.33452421426773071. The same steps in float give a rest normal Z one float step lower
    /// (0.93273788690567017) and a lift 3e-8 m shorter.
    /// </summary>
    [Fact]
    public void StepDown_OffCentre_ComputesTheRestInDoublePrecision_AsRetailsX87()
    {
        var t = Mover(new Vector3(0.3f, 0.2f, 1.1f), new Vector3(0.3f, 0.2f, 0.6f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;

        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Adjusted, state);
        var normal = t.CollisionInfo.ContactPlane.Normal;
        Assert.Equal(0.3f, normal.X);
        Assert.Equal(0.2f, normal.Y);
        Assert.Equal(0.93273794651031494f, normal.Z);
        Assert.Equal(0.6f + 0.33273789286613464f, CheckOrigin(t).Z);
        Assert.Equal(0.33452421426773071f, t.SpherePath.WalkInterp);
    }

    [Fact]
    public void StepDown_OntoACreature_IsIgnored()
    {
        var t = Mover(new Vector3(0, 0, 1.3f), new Vector3(0, 0, 0.8f));
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.5f;
        Assert.Equal(TransitionState.OK, SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, isCreature: true));
        Near(new Vector3(0, 0, 0.8f), CheckOrigin(t));
    }

    [Fact]
    public void PendingCollide_LandsOnTopOfTheTarget()
    {
        // After set_collide, falling straight down onto a sphere at the origin: backed up to z = 1.
        var t = Mover(new Vector3(0, 0, 1.5f), new Vector3(0, 0, 0.9f));
        t.SpherePath.Collide = true;
        var state = SphereResponses.IntersectsSphere(new Sphere(Vector3.Zero, 0.5f), t, false);

        Assert.Equal(TransitionState.Adjusted, state);
        Near(new Vector3(0, 0, 1.0f), CheckOrigin(t));
        Near(Vector3.UnitZ, t.CollisionInfo.ContactPlane.Normal);
        // Retail quirk: the plane passes through the unlifted check sphere's bottom (0.9 - 0.5), not z = 0.5.
        Assert.Equal(-0.4f, t.CollisionInfo.ContactPlane.D, 4);
        Assert.Equal(1f - 0.1f / 0.6f, t.SpherePath.WalkInterp, 4);
    }

    [Fact]
    public void OwnerOverload_ScalesRotatesAndCrossesLandblocks()
    {
        var owner = new Position(0xAAB40001, new Frame(new Vector3(1, 1, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2)));
        var check = new Position(CellId, Vector3.Zero);
        Sphere placed = SphereCollision.ToCheckSpace(new Sphere(new Vector3(1, 0, 0), 0.25f), owner, 2f, check);

        // (1,0,0)*2 rotated +90° about Z is (0,2,0); plus the owner's origin and one landblock east.
        Near(new Vector3(193, 3, 0), placed.Center);
        Assert.Equal(0.5f, placed.Radius);
    }

    [Fact]
    public void SecondSphere_IsTestedWithSphereZerosRadiusSum()
    {
        // Sphere 1 (r 0.3 at z 1.5) is 0.9 from a 0.5 target: apart by its own sum 0.8, but retail tests it
        // with sphere 0's radsum 0.5 + 0.5 - EPSILON (CSphere::intersects_sphere). Sphere 0 is 1.35 away.
        var t = TwoSpherePlacement(Vector3.Zero);
        Assert.Equal(InsertType.Placement, t.SpherePath.InsertType);
        Assert.Equal(TransitionState.Collided, SphereResponses.IntersectsSphere(new Sphere(new Vector3(0.9f, 0, 1.5f), 0.5f), t, false));
        Assert.Equal(TransitionState.OK, SphereResponses.IntersectsSphere(new Sphere(new Vector3(1.01f, 0, 1.5f), 0.5f), t, false));
    }

    [Fact]
    public void CheckWalkableAndEtherealObstruction_OnlyTestOverlap()
    {
        var probe = OnFloor(new Vector3(-0.2f, 0, 0.5f), new Vector3(0.1f, 0.3f, 0.5f));
        probe.SpherePath.CheckWalkable = true;
        Assert.Equal(TransitionState.Collided, SphereResponses.IntersectsSphere(new Sphere(new Vector3(1, 0, 0.5f), 0.5f), probe, false));
        Near(new Vector3(0.1f, 0.3f, 0.5f), CheckOrigin(probe));

        var ethereal = OnFloor(new Vector3(-0.2f, 0, 0.5f), new Vector3(0.1f, 0.3f, 0.5f));
        ethereal.SpherePath.ObstructionEthereal = true;
        Assert.Equal(TransitionState.Collided, SphereResponses.IntersectsSphere(new Sphere(new Vector3(1, 0, 0.5f), 0.5f), ethereal, false));
        Assert.Equal(TransitionState.OK, SphereResponses.IntersectsSphere(new Sphere(new Vector3(2, 0, 0.5f), 0.5f), ethereal, false));
    }
}
