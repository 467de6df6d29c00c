using AcDream.Core.Physics;
using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Geometry;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Bsp;

public class BspQueryTests
{
    [Fact]
    public void Placement_InsideIsCollided_OutsideIsOk()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var inside = BoxFixtures.MakeTransition(Vector3.Zero, new Vector3(0.2f, 0, 0), 0.3f);
        inside.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.Collided, BspQuery.FindCollisions(tree, inside, 1f));

        var outside = BoxFixtures.MakeTransition(Vector3.Zero, new Vector3(3f, 0, 0), 0.3f);
        outside.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(tree, outside, 1f));
    }

    [Fact]
    public void StepDown_LandsOnTheTopFace()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var t = BoxFixtures.MakeTransition(new Vector3(0.2f, 0, 1.6f), new Vector3(0.2f, 0, 1.3f), 0.5f);
        var path = t.SpherePath;
        path.StepDown = true;
        path.StepDownAmt = 0.3f;
        Assert.Equal(TransitionState.Adjusted, BspQuery.FindCollisions(tree, t, 1f));
        Assert.Equal(1.5f, path.CheckPos.Origin.Z, 5);
        Assert.Equal(1f / 3f, path.WalkInterp, 5);
        Assert.Same(faces[4], path.Walkable);
        var info = t.CollisionInfo;
        Assert.True(info.ContactPlaneValid);
        Assert.Equal(Vector3.UnitZ, info.ContactPlane.Normal);
        Assert.Equal(-1f, info.ContactPlane.D, 5);
        Assert.Equal(BoxFixtures.Cell, info.ContactPlaneCellId);
        Assert.False(info.ContactPlaneIsWater);
    }

    [Fact]
    public void StepDown_NothingBelow_IsOk()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3, 0, 1.6f), new Vector3(3, 0, 1.3f), 0.5f);
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.3f;
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.Equal(1.3f, t.SpherePath.CheckPos.Origin.Z);
    }

    [Fact]
    public void CheckWalkable_CollidedWhileGroundHolds()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var on = BoxFixtures.MakeTransition(new Vector3(0, 0, 1.45f), new Vector3(0, 0, 1.45f), 0.5f);
        on.SpherePath.CheckWalkable = true;
        Assert.Equal(TransitionState.Collided, BspQuery.FindCollisions(tree, on, 1f));

        var off = BoxFixtures.MakeTransition(new Vector3(1.4f, 0, 1.45f), new Vector3(1.4f, 0, 1.45f), 0.5f);
        off.SpherePath.CheckWalkable = true;
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(tree, off, 1f));
    }

    [Fact]
    public void NotInContact_HitRecordsStepUpCandidate()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        var path = t.SpherePath;
        Assert.True(path.Collide);
        Assert.Equal(Vector3.UnitX, path.StepUpNormal);
        Assert.Equal(PhysicsConstants.LandingZ, path.WalkableAllowance);
    }

    [Fact]
    public void NotInContact_SecondSphereHit_IsCollidedWithNormal()
    {
        // Sphere 0 at z = −1.6 passes under the box (0.67 from its bottom edge); sphere 1 at z = −0.6 hits the +X face.
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, -1.6f), new Vector3(1.3f, 0, -1.6f), 0.4f, twoSpheres: true);
        Assert.Equal(TransitionState.Collided, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.True(t.CollisionInfo.CollisionNormalValid);
        Assert.Equal(Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Assert.False(t.SpherePath.Collide);
    }

    [Fact]
    public void NotInContact_MovingAway_GrazedPolygonStillCountsAsHit()
    {
        // Retail quirk: "|| hit_poly" — a polygon hit only from behind still records a step-up candidate.
        var t = BoxFixtures.MakeTransition(new Vector3(1.2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.True(t.SpherePath.Collide);
    }

    [Fact]
    public void Clear_IsOk()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(2.5f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.False(t.SpherePath.Collide);
    }

    [Fact]
    public void InContact_TwoSpheres_GrazeFromBehindIsANegPolyHit()
    {
        // Sphere 0 (r 0.3) overlaps only the +X face while moving away from it; sphere 1 (z = 1.5) is clear.
        // (Were it to graze two faces, the last one in the leaf would be reported, as in retail.)
        var t = BoxFixtures.MakeTransition(new Vector3(1.1f, 0, 0.5f), new Vector3(1.2f, 0, 0.5f), 0.3f, twoSpheres: true);
        t.ObjectInfo.State = ObjectInfoState.Contact;
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        var path = t.SpherePath;
        Assert.True(path.NegPolyHit);
        Assert.True(path.NegStepUp);
        Assert.Equal(-Vector3.UnitX, path.NegCollisionNormal);
    }

    [Fact]
    public void InContact_OneSphere_GrazeFromBehindIsIgnored()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(1.2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        t.ObjectInfo.State = ObjectInfoState.Contact;
        Assert.Equal(TransitionState.OK, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.False(t.SpherePath.NegPolyHit);
    }

    [Fact]
    public void Collide_FindsWalkableAlongTheMove()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var t = BoxFixtures.MakeTransition(new Vector3(0, 0, 1.6f), new Vector3(0, 0, 1.3f), 0.5f);
        t.SpherePath.Collide = true;
        Assert.Equal(TransitionState.Adjusted, BspQuery.FindCollisions(tree, t, 1f));
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.Z, 5);
        Assert.Same(faces[4], t.SpherePath.Walkable);
        Assert.Equal(-1f, t.CollisionInfo.ContactPlane.D, 5);
    }

    [Fact]
    public void PathClipped_WithoutPerfectClip_IsCollidedWithNormal()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(1.2f, 0, 0), 0.5f);
        t.ObjectInfo.State = ObjectInfoState.PathClipped;
        Assert.Equal(TransitionState.Collided, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.Equal(Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Assert.Equal(1.2f, t.SpherePath.CheckPos.Origin.X);
    }

    [Fact]
    public void PathClipped_PerfectClip_BacksOffToTheFace()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(1.2f, 0, 0), 0.5f);
        t.ObjectInfo.State = ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip;
        Assert.Equal(TransitionState.Adjusted, BspQuery.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        // Touch time (0.5 − 2) / −1.8 = 5/6 puts the centre at x = 1.5, clear of the face; bisection keeps it.
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.X, 4);
        Assert.Equal(Vector3.UnitX, t.CollisionInfo.CollisionNormal);
    }

    [Fact]
    public void AdjustToPlane_StartWithinRadius_BisectsFromZero()
    {
        // The start (1.3) is already within a radius of the face: touch time 1 → straight to bisection over
        // [0, 1]; every sample hits, so the sphere is put back at the start.
        var tree = BoxFixtures.SolidBox(out var faces);
        var sphere = new Sphere(new Vector3(1.1f, 0, 0), 0.5f);
        var contact = Vector3.Zero;
        Assert.True(BspQuery.AdjustToPlane(tree, ref sphere, new Vector3(1.3f, 0, 0), faces[0], ref contact));
        Assert.Equal(1.3f, sphere.Center.X, 5);
    }

    [Fact]
    public void PlacementInsert_PushesOutOfAFace()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(new Vector3(1.3f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspQuery.PlacementInsert(tree, t));
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.X, 5);

        var clear = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.OK, BspQuery.PlacementInsert(tree, clear));
        Assert.Equal(3f, clear.SpherePath.CheckPos.Origin.X);
    }

    [Fact]
    public void PlacementInsert_CentreInSolid_PushesOutThroughTheNearFace()
    {
        // Centre inside, 0.2 behind the +X face: in solid and behind the plane, so the two flips of
        // adjust_to_placement_poly cancel and the sphere is pushed to a radius in front of the face: x = 1.5.
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(new Vector3(0.8f, 0, 0), new Vector3(0.8f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspQuery.PlacementInsert(tree, t));
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.X, 5);
    }

    [Fact]
    public void Queries_DoNotAllocate()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        var sphere = new Sphere(new Vector3(1.4f, 0.3f, 0.2f), 0.5f);
        long allocated = Allocations.PerRound(
            () =>
            {
                BspQuery.FindCollisions(tree, t, 1f);
                BspQuery.SphereIntersectsSolid(tree, sphere);
            },
            () =>
            {
                for (int i = 0; i < 100; i++)
                {
                    t.SpherePath.Collide = false;
                    BspQuery.FindCollisions(tree, t, 1f);
                    BspQuery.SphereIntersectsSolid(tree, sphere);
                    BspQuery.PointIntersectsSolid(tree, sphere.Center);
                    BspQuery.SphereIntersectsCellBsp(tree, sphere);
                }
            });
        Assert.Equal(0, allocated);
    }
}
