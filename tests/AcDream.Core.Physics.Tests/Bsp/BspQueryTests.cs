using AcDream.Core.Physics.Bsp;
using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.Tests.Support;
using AcDream.Core.Physics.Transitions.Responses;

namespace AcDream.Core.Physics.Tests.Bsp;

public class BspQueryTests
{
    [Fact]
    public void Placement_InsideIsCollided_OutsideIsOk()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var inside = BoxFixtures.MakeTransition(Vector3.Zero, new Vector3(0.2f, 0, 0), 0.3f);
        inside.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(tree, inside, 1f));

        var outside = BoxFixtures.MakeTransition(Vector3.Zero, new Vector3(3f, 0, 0), 0.3f);
        outside.SpherePath.InsertType = InsertType.Placement;
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(tree, outside, 1f));
    }

    [Fact]
    public void StepDown_LandsOnTheTopFace()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var t = BoxFixtures.MakeTransition(new Vector3(0.2f, 0, 1.6f), new Vector3(0.2f, 0, 1.3f), 0.5f);
        var path = t.SpherePath;
        path.StepDown = true;
        path.StepDownAmt = 0.3f;
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(tree, t, 1f));
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

    /// <summary>
    /// BSPTREE::step_sphere_down on an object scaled 2: the probe is the step divided by the scale in the tree's
    /// space, and the landing offset is multiplied back. The box's top face (local z 1) is at z 2; a sphere of
    /// radius 0.5 checked at z 2.3 (local 1.15, radius 0.25: 0.1 into the face) after a probe of 0.3 m (local 0.15)
    /// is lifted onto it, to z 2.5 (local 1.25), giving back 0.1 of the local 0.15: walk_interp 1 − 0.1 / 0.15 = 1/3.
    /// </summary>
    [Fact]
    public void StepDown_OnAScaledObject_ProbesAndLandsInTheScaledSpace()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var t = BoxFixtures.MakeTransition(new Vector3(0.4f, 0, 2.6f), new Vector3(0.4f, 0, 2.3f), 0.5f);
        var path = t.SpherePath;
        path.CacheLocalSpaceSphere(new Position(BoxFixtures.Cell, Vector3.Zero), 2f);
        path.StepDown = true;
        path.StepDownAmt = 0.3f;
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(tree, t, 2f));
        Assert.Equal(2.5f, path.CheckPos.Origin.Z, 5);
        Assert.Equal(1f / 3f, path.WalkInterp, 5);
        Assert.Same(faces[4], path.Walkable);
    }

    [Fact]
    public void StepDown_NothingBelow_IsOk()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3, 0, 1.6f), new Vector3(3, 0, 1.3f), 0.5f);
        t.SpherePath.StepDown = true;
        t.SpherePath.StepDownAmt = 0.3f;
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.Equal(1.3f, t.SpherePath.CheckPos.Origin.Z);
    }

    [Fact]
    public void CheckWalkable_CollidedWhileGroundHolds()
    {
        var tree = BoxFixtures.SolidBox(out _);
        var on = BoxFixtures.MakeTransition(new Vector3(0, 0, 1.45f), new Vector3(0, 0, 1.45f), 0.5f);
        on.SpherePath.CheckWalkable = true;
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(tree, on, 1f));

        var off = BoxFixtures.MakeTransition(new Vector3(1.4f, 0, 1.45f), new Vector3(1.4f, 0, 1.45f), 0.5f);
        off.SpherePath.CheckWalkable = true;
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(tree, off, 1f));
    }

    [Fact]
    public void NotInContact_HitRecordsStepUpCandidate()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
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
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.True(t.CollisionInfo.CollisionNormalValid);
        Assert.Equal(Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Assert.False(t.SpherePath.Collide);
    }

    [Fact]
    public void NotInContact_MovingAway_GrazedPolygonStillCountsAsHit()
    {
        // Retail quirk: "|| hit_poly" — a polygon hit only from behind still records a step-up candidate.
        var t = BoxFixtures.MakeTransition(new Vector3(1.2f, 0, 0), new Vector3(1.3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.True(t.SpherePath.Collide);
    }

    [Fact]
    public void Clear_IsOk()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(2.5f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.False(t.SpherePath.Collide);
    }

    [Fact]
    public void InContact_TwoSpheres_GrazeFromBehindIsANegPolyHit()
    {
        // Sphere 0 (r 0.3) overlaps only the +X face while moving away from it; sphere 1 (z = 1.5) is clear.
        // (Were it to graze two faces, the last one in the leaf would be reported, as in retail.)
        var t = BoxFixtures.MakeTransition(new Vector3(1.1f, 0, 0.5f), new Vector3(1.2f, 0, 0.5f), 0.3f, twoSpheres: true);
        t.ObjectInfo.State = ObjectInfoState.Contact;
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
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
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.False(t.SpherePath.NegPolyHit);
    }

    [Fact]
    public void Collide_FindsWalkableAlongTheMove()
    {
        var tree = BoxFixtures.SolidBox(out var faces);
        var t = BoxFixtures.MakeTransition(new Vector3(0, 0, 1.6f), new Vector3(0, 0, 1.3f), 0.5f);
        t.SpherePath.Collide = true;
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(tree, t, 1f));
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.Z, 5);
        Assert.Same(faces[4], t.SpherePath.Walkable);
        Assert.Equal(-1f, t.CollisionInfo.ContactPlane.D, 5);
    }

    [Fact]
    public void PathClipped_WithoutPerfectClip_IsCollidedWithNormal()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(1.2f, 0, 0), 0.5f);
        t.ObjectInfo.State = ObjectInfoState.PathClipped;
        Assert.Equal(TransitionState.Collided, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        Assert.Equal(Vector3.UnitX, t.CollisionInfo.CollisionNormal);
        Assert.Equal(1.2f, t.SpherePath.CheckPos.Origin.X);
    }

    [Fact]
    public void PathClipped_PerfectClip_BacksOffToTheFace()
    {
        var t = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(1.2f, 0, 0), 0.5f);
        t.ObjectInfo.State = ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip;
        Assert.Equal(TransitionState.Adjusted, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
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
        Assert.Equal(TransitionState.Adjusted, BspResponses.PlacementInsert(tree, t));
        Assert.Equal(1.5f, t.SpherePath.CheckPos.Origin.X, 5);

        var clear = BoxFixtures.MakeTransition(new Vector3(3f, 0, 0), new Vector3(3f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.OK, BspResponses.PlacementInsert(tree, clear));
        Assert.Equal(3f, clear.SpherePath.CheckPos.Origin.X);
    }

    [Fact]
    public void PlacementInsert_CentreInSolid_PushesOutThroughTheNearFace()
    {
        // Centre inside, 0.2 behind the +X face: in solid and behind the plane, so the two flips of
        // adjust_to_placement_poly cancel and the sphere is pushed to a radius in front of the face: x = 1.5.
        var tree = BoxFixtures.SolidBox(out _);
        var t = BoxFixtures.MakeTransition(new Vector3(0.8f, 0, 0), new Vector3(0.8f, 0, 0), 0.5f);
        Assert.Equal(TransitionState.Adjusted, BspResponses.PlacementInsert(tree, t));
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
                BspResponses.FindCollisions(tree, t, 1f);
                BspQuery.SphereIntersectsSolid(tree, sphere);
            },
            () =>
            {
                for (int i = 0; i < 100; i++)
                {
                    t.SpherePath.Collide = false;
                    BspResponses.FindCollisions(tree, t, 1f);
                    BspQuery.SphereIntersectsSolid(tree, sphere);
                    BspQuery.PointIntersectsSolid(tree, sphere.Center);
                    BspQuery.SphereIntersectsCellBsp(tree, sphere);
                }
            });
        Assert.Equal(0, allocated);
    }
    [Fact]
    public void InContact_TwoSpheres_SecondSphereGrazeFromBehindSlides()
    {
        // Sphere 0 (r 0.3) at (1.2, 0, −1.6) is clear: 0.6 below the −Z face, and √(0.2² + 0.6²) = 0.632
        // from the +X face's bottom edge. Sphere 1 (z = −0.6) is 0.2 in front of the +X face (≤ 0.3 − 0.0002,
        // inside the face's y, z range) but moves away from it (movement +X · N +X > 0): a graze from
        // behind. Retail records sphere 1's graze as a negative-polygon hit that slides (step-up flag
        // false), with the reversed normal −X.
        var t = BoxFixtures.MakeTransition(new Vector3(1.1f, 0, -1.6f), new Vector3(1.2f, 0, -1.6f), 0.3f, twoSpheres: true);
        t.ObjectInfo.State = ObjectInfoState.Contact;
        Assert.Equal(TransitionState.OK, BspResponses.FindCollisions(BoxFixtures.SolidBox(out _), t, 1f));
        var path = t.SpherePath;
        Assert.True(path.NegPolyHit);
        Assert.False(path.NegStepUp);
        Assert.Equal(-Vector3.UnitX, path.NegCollisionNormal);
    }

    [Fact]
    public void AdjustToPlane_BisectsToWithinTwoHundredthsOfTheMove()
    {
        // Sphere r 0.5 from (1.4, 2, 0) to (1.2, 0, 0), movement (−0.2, −2, 0), past the box's +X/+Y edge
        // (x = 1, y = 1). The start is 0.4 from the +X plane (< 0.5): touch time 1 → bisection over [0, 1].
        // At time t the centre is (1.4 − 0.2t, 2 − 2t); it hits the edge when its distance to it,
        // √((0.4 − 0.2t)² + (1 − 2t)²), is ≤ 0.4998.
        //   t 0.5      → (0.3, 0)             distance 0.3     hit   → [0, 0.5]
        //   t 0.25     → (0.35, 0.5)          distance 0.610   clear → [0.25, 0.5]
        //   t 0.375    → (0.325, 0.25)        distance 0.410   hit   → [0.25, 0.375]
        //   t 0.3125   → (0.3375, 0.375)      distance 0.5045  clear → [0.3125, 0.375]
        //   t 0.34375  → (0.33125, 0.3125)    distance 0.455   hit   → [0.3125, 0.34375]
        //   t 0.328125 → (0.334375, 0.34375)  distance 0.4796  hit   → [0.3125, 0.328125], width 1/64 < 0.02: stop.
        // Result t = 0.3125: centre (1.4 − 0.0625, 2 − 0.625) = (1.3375, 1.375, 0).
        var tree = BoxFixtures.SolidBox(out var faces);
        var sphere = new Sphere(new Vector3(1.2f, 0, 0), 0.5f);
        var contact = Vector3.Zero;
        Assert.True(BspQuery.AdjustToPlane(tree, ref sphere, new Vector3(1.4f, 2f, 0), faces[0], ref contact));
        Assert.Equal(1.3375f, sphere.Center.X, 5);
        Assert.Equal(1.375f, sphere.Center.Y, 5);
    }

    [Fact]
    public void AdjustToPlane_ReAimsAtTheNearerWall()
    {
        // One leaf holding two walls facing +X: A at x = 0.7 (first), B at x = 1. Sphere r 0.5 from x = 3
        // to x = 0.6 (movement −2.4); at the end it hits A first (0.1 away), so A is the polygon given.
        //   touch on A: (0.5 − 2.3) / −2.4 = 0.75 → x = 1.2: A 0.5 away (> 0.4998, clear) but B 0.2 away:
        //   a hit — re-aim at B, bracket upper 0.75 (one try used);
        //   touch on B: (0.5 − 2) / −2.4 = 0.625 → x = 1.5: A 0.8, B 0.5 away, clear → lower 0.625;
        //   bisection over [0.625, 0.75]: 0.6875 (x 1.35), 0.65625 (x 1.425), 0.640625 (x 1.4625) all hit B,
        //   width 1/64 < 0.02: stop at lower 0.625 → x = 3 − 1.5 = 1.5.
        var wallA = BspTestKit.Rect(new Vector3(0.7f, -1, -1), new Vector3(0.7f, 1, 1), Vector3.UnitX);
        var wallB = BspTestKit.Rect(new Vector3(1f, -1, -1), new Vector3(1f, 1, 1), Vector3.UnitX);
        var tree = BspTree.Create(new[] { wallA, wallB }, new[]
        {
            new BspNodeData { IsLeaf = true, Solid = false, Polygons = new[] { 0, 1 } },
        });
        var sphere = new Sphere(new Vector3(0.6f, 0, 0), 0.5f);
        var currPos = new Vector3(3f, 0, 0);
        var contact = Vector3.Zero;
        Polygon? hit = null;
        Assert.True(BspNodeQuery.SphereIntersectsPoly(tree, 0, sphere, sphere.Center - currPos, ref hit, ref contact));
        Assert.Same(wallA, hit);
        Assert.True(BspQuery.AdjustToPlane(tree, ref sphere, currPos, wallA, ref contact));
        Assert.Equal(1.5f, sphere.Center.X, 5);
    }
}
